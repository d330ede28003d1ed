// SPDX-License-Identifier: MIT
#include "core_bridge/pack.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/errors.h"
#include "model/topology.h"
#include "reference/gradients.h"

namespace tristream {

namespace {

constexpr int S = core::config::subpixel_bits;

void put16(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  b[at] = std::uint8_t(v & 0xFF);
  b[at + 1] = std::uint8_t((v >> 8) & 0xFF);
}
void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  put16(b, at, v & 0xFFFF);
  put16(b, at + 2, v >> 16);
}

struct QPoint {
  std::int64_t x, y;
};

// Sign of (a, b) . (sx * eps, sy * eps^2) for infinitesimal eps.
int symbolic_sign(std::int64_t a, std::int64_t b, int sx, int sy) {
  if (a != 0) return (a * sx > 0) ? 1 : -1;
  return (b * sy > 0) ? 1 : -1;
}

// Whether triangle (p0, p1, p2), positively oriented, contains corner k + direction d, with
// d = (sx eps, sy eps^2): both edges at the corner must have d on their inner side.
bool corner_contains(const QPoint* p, int k, int sx, int sy) {
  for (int e : {k, (k + 2) % 3}) {
    const QPoint& a = p[e];
    const QPoint& b = p[(e + 1) % 3];
    // Edge function gradient (A, B) = (-(by - ay), bx - ax).
    if (symbolic_sign(-(b.y - a.y), b.x - a.x, sx, sy) < 0) return false;
  }
  return true;
}

struct LayerData {
  std::vector<QPoint> pos;
  std::vector<std::uint16_t> values;   // per vertex and value
  std::vector<std::int32_t> gradients; // per vertex and value: gx, gy
  std::vector<std::array<std::uint16_t, 4>> triangles;  // v0, v1, v2, flags (sorted)
};

LayerData finish_layer(LayerData d, const Mesh& mesh, core::Method method, const std::vector<std::int32_t>* gradients,
                       const std::string& where);

LayerData build_layer(const Mesh& input, int width, int height, core::Method method,
                      const std::vector<std::int32_t>* gradients, const std::string& where) {
  const Mesh& mesh = input;
  if (mesh.vertex_count() > core::blob_max_vertices)
    throw DataError(where + ": " + std::to_string(mesh.vertex_count()) + " vertices, the core takes at most " +
                    std::to_string(core::blob_max_vertices));
  if (mesh.triangles.empty() || mesh.triangles.size() > core::blob_max_triangles)
    throw DataError(where + ": " + std::to_string(mesh.triangles.size()) + " triangles, the core takes 1 to " +
                    std::to_string(core::blob_max_triangles));
  LayerData d;
  const double scale = double(1 << S);
  const std::int64_t max_x = std::int64_t(width - 1) << S, max_y = std::int64_t(height - 1) << S;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const QPoint q{std::llround(mesh.points[v].x * scale), std::llround(mesh.points[v].y * scale)};
    if (q.x < 0 || q.y < 0 || q.x > max_x || q.y > max_y)
      throw DataError(where + ": vertex " + std::to_string(v) + " lies outside the domain [0, " +
                      std::to_string(width - 1) + "] x [0, " + std::to_string(height - 1) + "]");
    d.pos.push_back(q);
    for (int c = 0; c < mesh.value_count; ++c)
      d.values.push_back(std::uint16_t(std::clamp<long>(std::lround(mesh.value(v, c) * 256.0), 0, 255 * 256)));
  }
  // Either winding is accepted; the core wants positive orientation (clockwise on screen).
  Mesh oriented = input;
  for (std::size_t t = 0; t < oriented.triangles.size(); ++t) {
    auto& v = oriented.triangles[t].v;
    const QPoint &a = d.pos[v[0]], &b = d.pos[v[1]], &c = d.pos[v[2]];
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0) std::swap(v[1], v[2]);
  }
  return finish_layer(std::move(d), oriented, method, gradients, where);
}

LayerData finish_layer(LayerData d, const Mesh& mesh, core::Method method, const std::vector<std::int32_t>* gradients,
                       const std::string& where) {
  const Topology topo = build_topology(mesh);
  if (method == core::Method::zienkiewicz && gradients) {
    if (gradients->size() != 2 * mesh.vertex_count() * std::size_t(mesh.value_count))
      throw DataError(where + ": " + std::to_string(gradients->size()) + " gradient components given, expected " +
                      std::to_string(2 * mesh.vertex_count() * std::size_t(mesh.value_count)));
    const std::int32_t limit = core::config::max_gradient << core::config::gradient_frac_bits;
    for (std::size_t k = 0; k < gradients->size(); ++k)
      if ((*gradients)[k] > limit || (*gradients)[k] < -limit)
        throw DataError(where + ": vertex " + std::to_string(k / (2 * mesh.value_count)) +
                        ": gradient beyond the core's limit of " + std::to_string(core::config::max_gradient) +
                        " per pixel");
    d.gradients = *gradients;
  } else if (method == core::Method::zienkiewicz) {
    std::vector<std::vector<Gradient>> g;
    for (int c = 0; c < mesh.value_count; ++c) g.push_back(vertex_gradients(mesh, topo, c));
    const double gscale = double(1 << core::config::gradient_frac_bits);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
      for (int c = 0; c < mesh.value_count; ++c) {
        const double gx = g[c][v].gx, gy = g[c][v].gy;
        const double limit = core::config::max_gradient;
        if (!(std::abs(gx) <= limit) || !(std::abs(gy) <= limit))
          throw DataError(where + ": vertex " + std::to_string(v) + ": gradient (" + std::to_string(gx) + ", " +
                          std::to_string(gy) + ") beyond the core's limit of " + std::to_string(int(limit)) +
                          " per pixel");
        d.gradients.push_back(std::int32_t(std::lround(gx * gscale)));
        d.gradients.push_back(std::int32_t(std::lround(gy * gscale)));
      }
  }
  const std::size_t nt = mesh.triangles.size();
  std::vector<std::uint16_t> flags(nt, 0);
  std::vector<char> boundary_vertex(mesh.vertex_count(), 0);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& v = mesh.triangles[t].v;
    const QPoint p[3] = {d.pos[v[0]], d.pos[v[1]], d.pos[v[2]]};
    if ((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x) <= 0)
      throw DataError(where + ": triangle " + std::to_string(t) + " collapses when its vertices are rounded to 1/" +
                      std::to_string(1 << S) + " pixel");
    for (int e = 0; e < 3; ++e)
      if (topo.is_boundary_edge(std::uint32_t(t), e)) {
        flags[t] |= std::uint16_t(core::boundary_edge0 << e);
        boundary_vertex[v[e]] = boundary_vertex[v[(e + 1) % 3]] = 1;
      }
  }
  std::vector<std::uint32_t> order(nt);
  std::iota(order.begin(), order.end(), 0u);
  auto top = [&](std::uint32_t t) {
    const auto& v = mesh.triangles[t].v;
    return std::min({d.pos[v[0]].y, d.pos[v[1]].y, d.pos[v[2]].y});
  };
  auto key = [&](std::uint32_t t) {
    const auto& v = mesh.triangles[t].v;
    return std::array<std::int64_t, 4>{top(t), std::min({d.pos[v[0]].x, d.pos[v[1]].x, d.pos[v[2]].x}),
                                       std::max({d.pos[v[0]].y, d.pos[v[1]].y, d.pos[v[2]].y}),
                                       std::max({d.pos[v[0]].x, d.pos[v[1]].x, d.pos[v[2]].x})};
  };
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::uint32_t> rank(nt);
  for (std::uint32_t k = 0; k < nt; ++k) rank[order[k]] = k;
  // Each boundary vertex's pixel goes to one triangle of its fan: the one containing the vertex
  // moved by the reference renderer's direction w = (sx eps, sy eps^2) (sx = +1 in column 0, else
  // -1; sy = +1 in row 0, else -1: into the image rectangle), else by the first of the four
  // directions (+-eps, +-eps^2) that enters the domain, else the fan's triangle that comes first in
  // the blob (so that a blob read back and packed again keeps its owners).
  const std::int64_t one = std::int64_t(1) << S;
  for (std::size_t vtx = 0; vtx < mesh.vertex_count(); ++vtx) {
    if (!boundary_vertex[vtx]) continue;
    const int wx = d.pos[vtx].x < one ? 1 : -1;  // sample points of column 0 have x < 1
    const int wy = d.pos[vtx].y < one ? 1 : -1;
    const int dirs[5][2] = {{wx, wy}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    std::int64_t owner = -1;
    for (const auto& dir : dirs) {
      for (std::uint32_t k = topo.vertex_start[vtx]; k < topo.vertex_start[vtx + 1] && owner < 0; ++k) {
        const std::uint32_t t = topo.vertex_triangles[k];
        const auto& v = mesh.triangles[t].v;
        const QPoint p[3] = {d.pos[v[0]], d.pos[v[1]], d.pos[v[2]]};
        const int corner = v[0] == vtx ? 0 : (v[1] == vtx ? 1 : 2);
        if (corner_contains(p, corner, dir[0], dir[1])) owner = t;
      }
      if (owner >= 0) break;
    }
    if (owner < 0)
      for (std::uint32_t k = topo.vertex_start[vtx]; k < topo.vertex_start[vtx + 1]; ++k)
        if (owner < 0 || rank[topo.vertex_triangles[k]] < rank[std::uint32_t(owner)]) owner = topo.vertex_triangles[k];
    for (std::uint32_t k = topo.vertex_start[vtx]; k < topo.vertex_start[vtx + 1]; ++k) {
      const std::uint32_t t = topo.vertex_triangles[k];
      const auto& v = mesh.triangles[t].v;
      const int corner = v[0] == vtx ? 0 : (v[1] == vtx ? 1 : 2);
      flags[t] |= std::uint16_t(core::corner_explicit0 << corner);
      if (std::int64_t(t) == owner) flags[t] |= std::uint16_t(core::corner_owned0 << corner);
    }
  }
  // Canonical rotation: the topmost (then leftmost) vertex first, so that the blob, and the
  // rounding of the interpolants, do not depend on the order the input lists vertices in.
  auto rotate_flags = [](std::uint16_t f, int r) {
    std::uint16_t out = 0;
    for (int group = 0; group < 3; ++group)
      for (int k = 0; k < 3; ++k)
        if (f & (1u << (3 * group + (k + r) % 3))) out |= std::uint16_t(1u << (3 * group + k));
    return out;
  };
  for (std::uint32_t t : order) {
    const auto& v = mesh.triangles[t].v;
    int r = 0;
    for (int k = 1; k < 3; ++k) {
      const QPoint &a = d.pos[v[k]], &b = d.pos[v[r]];
      if (a.y < b.y || (a.y == b.y && a.x < b.x)) r = k;
    }
    d.triangles.push_back({std::uint16_t(v[r]), std::uint16_t(v[(r + 1) % 3]), std::uint16_t(v[(r + 2) % 3]),
                           rotate_flags(flags[t], r)});
  }
  return d;
}

std::size_t align4(std::size_t n) { return (n + 3) & ~std::size_t(3); }

}  // namespace

core::Method parse_core_method(std::string_view name) {
  if (name == "bilinear") return core::Method::bilinear;
  if (name == "zienkiewicz") return core::Method::zienkiewicz;
  throw UsageError("the core renders methods bilinear and zienkiewicz, not \"" + std::string(name) + "\"");
}

std::string_view to_string(core::Method method) {
  return method == core::Method::zienkiewicz ? "zienkiewicz" : "bilinear";
}

std::vector<std::uint8_t> pack_blob(const Triangulation& tri, core::Method method, std::string_view name,
                                    const BlobGradients* gradients) {
  const std::string where(name);
  if (tri.width < 2 || tri.height < 2 || tri.width > core::config::max_dimension ||
      tri.height > core::config::max_dimension)
    throw DataError(where + ": image size " + std::to_string(tri.width) + " x " + std::to_string(tri.height) +
                    ", the core takes 2 to " + std::to_string(core::config::max_dimension) + " per side");
  if (tri.layers.empty()) throw DataError(where + ": no mesh");
  if (gradients && gradients->size() != tri.layers.size())
    throw DataError(where + ": gradients for " + std::to_string(gradients->size()) + " layers given, expected " +
                    std::to_string(tri.layers.size()));
  std::vector<LayerData> layers;
  for (std::size_t l = 0; l < tri.layers.size(); ++l)
    layers.push_back(build_layer(tri.layers[l], tri.width, tri.height, method, gradients ? &(*gradients)[l] : nullptr,
                                 tri.layered() ? where + ": layer " + std::to_string(l) : where));
  const int per_vertex = tri.layers[0].value_count;

  std::size_t at = core::blob_header_size;
  const std::size_t table = at;
  at += core::blob_layer_entry_size * layers.size();
  struct Offsets {
    std::size_t pos, val, grad, tri;
  };
  std::vector<Offsets> off;
  for (const LayerData& d : layers) {
    Offsets o{};
    o.pos = at;
    at = align4(at + 4 * d.pos.size());
    o.val = at;
    at = align4(at + 2 * d.values.size());
    if (method == core::Method::zienkiewicz) {
      o.grad = at;
      at = align4(at + 4 * d.gradients.size());
    }
    o.tri = at;
    at = align4(at + core::blob_triangle_size * d.triangles.size());
    off.push_back(o);
  }
  std::vector<std::uint8_t> b(at, 0);
  b[0] = 'T', b[1] = 'S', b[2] = 'T', b[3] = 'B';
  put16(b, 4, core::blob_version);
  put16(b, 6, core::blob_header_size);
  put32(b, 8, std::uint32_t(at));
  put16(b, 12, std::uint32_t(tri.width));
  put16(b, 14, std::uint32_t(tri.height));
  b[16] = std::uint8_t(tri.space == ColorSpace::grey ? 0 : tri.space == ColorSpace::rgb ? 1 : 2);
  b[17] = std::uint8_t(method);
  b[18] = std::uint8_t(layers.size());
  b[19] = std::uint8_t(per_vertex);
  b[20] = std::uint8_t(core::config::subpixel_bits);
  b[21] = std::uint8_t(core::config::gradient_frac_bits);
  put32(b, 24, core::blob_config_hash());
  put32(b, 28, std::uint32_t(table));
  std::int64_t tallest = 0;
  for (std::size_t l = 0; l < layers.size(); ++l) {
    const LayerData& d = layers[l];
    const Offsets& o = off[l];
    const std::size_t e = table + l * core::blob_layer_entry_size;
    put32(b, e, std::uint32_t(d.pos.size()));
    put32(b, e + 4, std::uint32_t(d.triangles.size()));
    put32(b, e + 8, std::uint32_t(o.pos));
    put32(b, e + 12, std::uint32_t(o.val));
    put32(b, e + 16, std::uint32_t(o.grad));
    put32(b, e + 20, std::uint32_t(o.tri));
    for (std::size_t v = 0; v < d.pos.size(); ++v) {
      put16(b, o.pos + 4 * v, std::uint32_t(d.pos[v].x));
      put16(b, o.pos + 4 * v + 2, std::uint32_t(d.pos[v].y));
    }
    for (std::size_t k = 0; k < d.values.size(); ++k) put16(b, o.val + 2 * k, d.values[k]);
    for (std::size_t k = 0; k < d.gradients.size(); ++k) put32(b, o.grad + 4 * k, std::uint32_t(d.gradients[k]));
    for (std::size_t t = 0; t < d.triangles.size(); ++t)
      for (int k = 0; k < 4; ++k) put16(b, o.tri + core::blob_triangle_size * t + 2 * k, d.triangles[t][k]);
    for (const auto& t : d.triangles) {
      const std::int64_t lo = std::min({d.pos[t[0]].y, d.pos[t[1]].y, d.pos[t[2]].y});
      const std::int64_t hi = std::max({d.pos[t[0]].y, d.pos[t[1]].y, d.pos[t[2]].y});
      tallest = std::max(tallest, (hi >> S) - ((lo + (1 << S) - 1) >> S) + 1);
    }
  }
  put32(b, 32, std::uint32_t(tallest));
  put32(b, core::blob_checksum_offset, core::blob_checksum(b.data(), std::uint32_t(b.size())));
  return b;
}

}  // namespace tristream
