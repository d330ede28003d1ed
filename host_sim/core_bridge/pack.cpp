// SPDX-License-Identifier: MIT
#include "core_bridge/pack.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numeric>
#include <string>

#include "bytes.h"
#include "common/errors.h"
#include "model/topology.h"
#include "reference/gradients.h"
#include "wire_layout.h"

namespace tristream {

namespace {

using core::detail::store_i32;
using core::detail::store_u16;
using core::detail::store_u32;

constexpr int S = core::config::subpixel_bits;

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

// Triangle t collapses on the core's grid: named by the lines of its vertices when the mesh was
// read from a file (the only way to find a triangle the reader computed), else by its index.
std::string collapse_message(const Mesh& mesh, std::size_t t, const std::string& where) {
  const std::string rounded =
      " collapses when its vertices are rounded to 1/" + std::to_string(1 << S) + " pixel (the core's grid)";
  if (mesh.vertex_lines.size() != mesh.vertex_count()) return where + ": triangle " + std::to_string(t) + rounded;
  std::array<std::uint32_t, 3> lines{};
  for (int k = 0; k < 3; ++k) lines[k] = mesh.vertex_lines[mesh.triangles[t].v[k]];
  std::sort(lines.begin(), lines.end());
  const std::string vertices = "vertices on lines " + std::to_string(lines[0]) + ", " + std::to_string(lines[1]) +
                               " and " + std::to_string(lines[2]);
  if (mesh.triangulated_by_reader)
    return where + ": a triangle of the Delaunay triangulation the reader computed (the file lists no triangles), " +
           vertices + "," + rounded + ": move those vertices apart";
  return where + ": triangle " + std::to_string(t) + " of the triangles section (counting from 0), " + vertices + "," +
         rounded + ": move those vertices apart";
}

// The shortest form that reads back to `v`, as the .tri writer prints it.
std::string number(double v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}

// A vertex for messages: its line in the file (when the mesh was read from one) or its index, and
// its position as given.
std::string vertex_name(const Mesh& mesh, std::uint32_t v) {
  const bool lines = mesh.vertex_lines.size() == mesh.vertex_count();
  return (lines ? std::to_string(mesh.vertex_lines[v]) : std::to_string(v)) + " (" + number(mesh.points[v].x) + ", " +
         number(mesh.points[v].y) + ")";
}

// Two vertices that triangles use must not round to one point of the core's grid: the core would
// draw the pixel there from both (a vertex no triangle uses is never drawn, as in the .tri rules).
// Sorting the rounded positions finds a pair in O(n log n).
void check_distinct_on_grid(const std::vector<QPoint>& pos, const Mesh& mesh, const std::string& where) {
  std::vector<std::uint32_t> order = mesh.used_vertices();
  auto key = [&](std::uint32_t v) { return std::array<std::int64_t, 3>{pos[v].x, pos[v].y, v}; };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::uint32_t a = order[k - 1], b = order[k];
    if (pos[a].x != pos[b].x || pos[a].y != pos[b].y) continue;
    const double unit = 1.0 / double(1 << S);
    const bool lines = mesh.vertex_lines.size() == mesh.vertex_count();
    throw DataError(where + ": vertices " + (lines ? "on lines " : "") + vertex_name(mesh, a) + " and " +
                    vertex_name(mesh, b) + " both round to (" + number(double(pos[a].x) * unit) + ", " +
                    number(double(pos[a].y) * unit) + ") on the core's 1/" + std::to_string(1 << S) +
                    "-pixel grid, where the core would draw one point with two vertices' values: move them apart (1/" +
                    std::to_string(1 << S) + " pixel in x or y suffices)");
  }
}

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
  // finish_layer refuses a triangle that collapses first: two of its own vertices on one point say so.
  LayerData out = finish_layer(std::move(d), oriented, method, gradients, where);
  check_distinct_on_grid(out.pos, mesh, where);
  return out;
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
      throw DataError(collapse_message(mesh, t, where));
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

  namespace w = core::wire;
  namespace h = core::wire::header;
  namespace L = core::wire::v1_layer;
  // Sections in layer order, each 4-aligned: positions, values, gradients (zienkiewicz), triangles.
  std::uint32_t at = h::bytes;
  const std::uint32_t table = at;
  at += L::bytes * std::uint32_t(layers.size());
  struct Offsets {
    std::uint32_t pos, val, grad, tri;
  };
  std::vector<Offsets> off;
  for (const LayerData& d : layers) {
    Offsets o{};
    o.pos = at;
    at = w::align_section(at + w::position::bytes * std::uint32_t(d.pos.size()));
    o.val = at;
    at = w::align_section(at + w::value::bytes * std::uint32_t(d.values.size()));
    if (method == core::Method::zienkiewicz) {
      o.grad = at;
      at = w::align_section(at + w::gradient::bytes * std::uint32_t(d.gradients.size() / 2));
    }
    o.tri = at;
    at = w::align_section(at + w::triangle::bytes * std::uint32_t(d.triangles.size()));
    off.push_back(o);
  }
  std::vector<std::uint8_t> bytes(at, 0);
  std::uint8_t* b = bytes.data();
  w::put_magic(b + h::magic, w::v1_magic);
  store_u16(b + h::version, core::blob_version);
  store_u16(b + h::header_size, h::bytes);
  store_u32(b + h::total_size, at);
  store_u16(b + h::width, std::uint32_t(tri.width));
  store_u16(b + h::height, std::uint32_t(tri.height));
  b[h::color_space] = std::uint8_t(tri.space == ColorSpace::grey ? 0 : tri.space == ColorSpace::rgb ? 1 : 2);
  b[h::method] = std::uint8_t(method);
  b[h::layer_count] = std::uint8_t(layers.size());
  b[h::values_per_vertex] = std::uint8_t(per_vertex);
  b[h::subpixel_bits] = std::uint8_t(core::config::subpixel_bits);
  b[h::gradient_frac_bits] = std::uint8_t(core::config::gradient_frac_bits);
  store_u32(b + h::config_hash, core::blob_config_hash());
  store_u32(b + h::layer_table, table);
  std::int64_t tallest = 0;
  for (std::size_t l = 0; l < layers.size(); ++l) {
    const LayerData& d = layers[l];
    const Offsets& o = off[l];
    std::uint8_t* e = b + table + l * L::bytes;
    store_u32(e + L::vertex_count, std::uint32_t(d.pos.size()));
    store_u32(e + L::triangle_count, std::uint32_t(d.triangles.size()));
    store_u32(e + L::positions, o.pos);
    store_u32(e + L::values, o.val);
    store_u32(e + L::gradients, o.grad);
    store_u32(e + L::triangles, o.tri);
    for (std::size_t v = 0; v < d.pos.size(); ++v) {
      std::uint8_t* p = b + o.pos + w::position::bytes * v;
      store_u16(p + w::position::x, std::uint32_t(d.pos[v].x));
      store_u16(p + w::position::y, std::uint32_t(d.pos[v].y));
    }
    for (std::size_t k = 0; k < d.values.size(); ++k) store_u16(b + o.val + w::value::bytes * k, d.values[k]);
    for (std::size_t k = 0; 2 * k < d.gradients.size(); ++k) {
      std::uint8_t* g = b + o.grad + w::gradient::bytes * k;
      store_i32(g + w::gradient::gx, d.gradients[2 * k]);
      store_i32(g + w::gradient::gy, d.gradients[2 * k + 1]);
    }
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
      std::uint8_t* p = b + o.tri + w::triangle::bytes * t;
      for (std::uint32_t k = 0; k < 3; ++k) store_u16(p + w::triangle::corner(k), d.triangles[t][k]);
      store_u16(p + w::triangle::flags, d.triangles[t][3]);
    }
    for (const auto& t : d.triangles) {
      const std::int64_t lo = std::min({d.pos[t[0]].y, d.pos[t[1]].y, d.pos[t[2]].y});
      const std::int64_t hi = std::max({d.pos[t[0]].y, d.pos[t[1]].y, d.pos[t[2]].y});
      tallest = std::max(tallest, (hi >> S) - ((lo + (1 << S) - 1) >> S) + 1);
    }
  }
  store_u32(b + h::max_triangle_height, std::uint32_t(tallest));
  store_u32(b + h::checksum, core::blob_checksum(b, std::uint32_t(bytes.size())));
  return bytes;
}

}  // namespace tristream
