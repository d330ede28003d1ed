// SPDX-License-Identifier: MIT
#include "baselines/removal_mesh.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "geometry/predicates.h"

namespace tristream::baselines {

RemovalMesh::RemovalMesh(int width, int height) : width_(width), height_(height) {
  if (width < 2 || height < 2) throw std::invalid_argument("removal mesh: expected at least 2 x 2 pixels");
  const std::size_t n = std::size_t(width) * height;
  if (2 * n >= none) throw std::invalid_argument("removal mesh: too many pixels");
  alive_count_ = n;
  alive_.assign(n, 1);
  vertex_triangle_.assign(n, none);
  tri_.resize(2 * std::size_t(width - 1) * (height - 1));
  // Cell (x, y) with corners a = (x, y), b = (x + 1, y), c = (x + 1, y + 1), d = (x, y + 1) holds
  // slot 2k: (a, b, c) and slot 2k + 1: (a, c, d), k = y (W - 1) + x; both positive in the Mesh
  // winding (y down). Across a -> b lies the cell above's (a, c, d), across b -> c the right
  // cell's (a, c, d), across d -> a the left cell's (a, b, c), across c -> d the cell below's
  // (a, b, c).
  const std::uint32_t cells_x = std::uint32_t(width - 1), cells_y = std::uint32_t(height - 1);
  for (std::uint32_t y = 0; y < cells_y; ++y)
    for (std::uint32_t x = 0; x < cells_x; ++x) {
      const std::uint32_t a = y * std::uint32_t(width) + x, b = a + 1, c = b + std::uint32_t(width), d = c - 1;
      const std::uint32_t k = y * cells_x + x, upper = 2 * k, lower = upper + 1;
      tri_[upper] = {{a, b, c},
                     {y > 0 ? 2 * (k - cells_x) + 1 : none, x + 1 < cells_x ? 2 * (k + 1) + 1 : none, lower}};
      tri_[lower] = {{a, c, d}, {upper, y + 1 < cells_y ? 2 * (k + cells_x) : none, x > 0 ? 2 * (k - 1) : none}};
      for (std::uint32_t u : {a, b, c, d}) vertex_triangle_[u] = u == b ? upper : lower;
    }
}

bool RemovalMesh::is_corner(std::uint32_t v) const {
  const encoder::IntPoint p = pixel(v);
  return (p.x == 0 || p.x == width_ - 1) && (p.y == 0 || p.y == height_ - 1);
}

int RemovalMesh::index_of(const Slot& s, std::uint32_t v) { return s.v[0] == v ? 0 : s.v[1] == v ? 1 : 2; }

void RemovalMesh::star(std::uint32_t v, Star& out) const {
  out.triangles.clear();
  out.link.clear();
  out.on_side = false;
  // Back across edge v -> a0 until the start comes round again or a side stops the walk.
  std::uint32_t t = vertex_triangle_[v];
  const std::uint32_t start = t;
  int i = index_of(tri_[t], v);
  for (;;) {
    const std::uint32_t back = tri_[t].n[i];
    if (back == none) {
      out.on_side = true;
      break;
    }
    t = back;
    i = index_of(tri_[t], v);
    if (t == start) break;
  }
  // Forward across edge a_(k+1) -> v.
  const std::uint32_t first = t;
  for (;;) {
    out.triangles.push_back(t);
    out.link.push_back(tri_[t].v[(i + 1) % 3]);
    const std::uint32_t next = tri_[t].n[(i + 2) % 3];
    if (next == none) {
      out.link.push_back(tri_[t].v[(i + 2) % 3]);
      break;
    }
    if (next == first) break;
    t = next;
    i = index_of(tri_[t], v);
  }
}

void RemovalMesh::fill(const Star& s, std::vector<Corners>& out) const {
  out.clear();
  std::vector<std::uint32_t>& poly = polygon_;
  poly.assign(s.link.begin(), s.link.end());
  while (poly.size() > 3) {
    const std::size_t n = poly.size();
    bool cut = false;
    for (std::size_t i = 0; i < n && !cut; ++i) {
      const std::uint32_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      const Point pa = point(a), pb = point(b), pc = point(c);
      if (orient2d(pa, pb, pc) <= 0) continue;
      bool empty = true;
      for (std::uint32_t d : s.link)
        if (d != a && d != b && d != c && incircle(pa, pb, pc, point(d)) > 0) {
          empty = false;
          break;
        }
      if (!empty) continue;
      out.push_back({a, b, c});
      poly.erase(poly.begin() + std::ptrdiff_t(i));
      cut = true;
    }
    if (!cut) throw std::logic_error("removal mesh: no Delaunay ear in a hole");
  }
  if (poly.size() != 3 || orient2d(point(poly[0]), point(poly[1]), point(poly[2])) <= 0)
    throw std::logic_error("removal mesh: a hole's last triangle is degenerate");
  out.push_back({poly[0], poly[1], poly[2]});
}

std::uint32_t RemovalMesh::new_slot(const Corners& v) {
  std::uint32_t t;
  if (!free_.empty()) {
    t = free_.back();
    free_.pop_back();
  } else {
    t = std::uint32_t(tri_.size());
    tri_.push_back({});
  }
  tri_[t] = {v, {none, none, none}};
  return t;
}

void RemovalMesh::remove(std::uint32_t v, const Star& s, const std::vector<Corners>& fill,
                         std::vector<std::uint32_t>& created) {
  outside_.clear();
  for (std::uint32_t t : s.triangles) {
    const int i = index_of(tri_[t], v);
    const std::uint32_t a = tri_[t].v[(i + 1) % 3], b = tri_[t].v[(i + 2) % 3], o = tri_[t].n[(i + 1) % 3];
    int e = -1;
    if (o != none)
      for (int j = 0; j < 3; ++j)
        if (tri_[o].v[j] == b && tri_[o].v[(j + 1) % 3] == a) e = j;
    outside_.push_back({a, b, o, e});
  }
  for (std::uint32_t t : s.triangles) {
    tri_[t].v = {none, none, none};
    free_.push_back(t);
  }
  const std::size_t first = created.size();
  for (const Corners& c : fill) created.push_back(new_slot(c));
  for (std::size_t k = first; k < created.size(); ++k) {
    const std::uint32_t t = created[k];
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = tri_[t].v[e], w = tri_[t].v[(e + 1) % 3];
      vertex_triangle_[u] = t;
      std::uint32_t across = none;
      for (std::size_t j = first; j < created.size() && across == none; ++j) {
        const Corners& q = tri_[created[j]].v;
        for (int f = 0; f < 3; ++f)
          if (q[f] == w && q[(f + 1) % 3] == u) across = created[j];
      }
      if (across == none)
        for (const Outside& o : outside_)
          if (o.a == u && o.b == w) {
            across = o.slot;
            if (o.slot != none) tri_[o.slot].n[o.edge] = t;
          }
      tri_[t].n[e] = across;
    }
  }
  alive_[v] = 0;
  vertex_triangle_[v] = none;
  --alive_count_;
}

}  // namespace tristream::baselines
