/* SPDX-License-Identifier: MIT */
#pragma once
// The O(n^2) definition find_mesh_defect (geometry/mesh_check.h) is tested against: every pair of
// triangles, and every used vertex against every edge.
#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/predicates.h"
#include "model/triangulation.h"

namespace tristream::testing {

// Interiors of two positive triangles overlap iff no edge line of either separates them.
inline bool interiors_overlap(const std::vector<Point>& p, const Triangle& a, const Triangle& b) {
  auto separated = [&](const Triangle& s, const Triangle& t) {
    for (int e = 0; e < 3; ++e) {
      const Point& u = p[s.v[e]];
      const Point& w = p[s.v[(e + 1) % 3]];
      if (orient2d(u, w, p[t.v[0]]) <= 0 && orient2d(u, w, p[t.v[1]]) <= 0 && orient2d(u, w, p[t.v[2]]) <= 0)
        return true;
    }
    return false;
  };
  return !separated(a, b) && !separated(b, a);
}

inline bool strictly_inside_segment(const Point& a, const Point& b, const Point& q) {
  if (orient2d(a, b, q) != 0) return false;
  const bool x_between = (a.x < q.x && q.x < b.x) || (b.x < q.x && q.x < a.x);
  const bool y_between = (a.y < q.y && q.y < b.y) || (b.y < q.y && q.y < a.y);
  return a.x == b.x ? (q.x == a.x && y_between) : x_between;
}

// Whether positive triangles overlap or have a used vertex inside an edge.
inline bool brute_force_defect(const std::vector<Point>& p, const std::vector<Triangle>& t) {
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 1; j < t.size(); ++j)
      if (interiors_overlap(p, t[i], t[j])) return true;
  std::vector<char> used(p.size(), 0);
  for (const Triangle& tri : t)
    for (auto v : tri.v) used[v] = 1;
  for (const Triangle& tri : t)
    for (int e = 0; e < 3; ++e)
      for (std::uint32_t v = 0; v < p.size(); ++v)
        if (used[v] && strictly_inside_segment(p[tri.v[e]], p[tri.v[(e + 1) % 3]], p[v])) return true;
  return false;
}

// Drops degenerate triangles and makes the others positive.
inline std::vector<Triangle> positive(const std::vector<Point>& p, const std::vector<Triangle>& t) {
  std::vector<Triangle> out;
  for (Triangle tri : t) {
    const double o = orient2d(p[tri.v[0]], p[tri.v[1]], p[tri.v[2]]);
    if (o == 0) continue;
    if (o < 0) std::swap(tri.v[1], tri.v[2]);
    out.push_back(tri);
  }
  return out;
}

}  // namespace tristream::testing
