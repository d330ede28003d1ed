/* SPDX-License-Identifier: MIT */
#pragma once
// Helpers shared by the tests of the reference methods.
#include <cmath>
#include <span>
#include <vector>

#include "model/triangulation.h"

namespace tristream::testing {

using Polygon = std::vector<Point>;

// Keeps the part of `poly` no farther from a than from b (a half-plane; Sutherland-Hodgman).
inline Polygon clip_closer_to(const Polygon& poly, const Point& a, const Point& b) {
  // Inside when s(x) = 2 x.(b - a) - (|b|^2 - |a|^2) <= 0.
  auto s = [&](const Point& x) {
    return 2 * (x.x * (b.x - a.x) + x.y * (b.y - a.y)) - ((b.x * b.x + b.y * b.y) - (a.x * a.x + a.y * a.y));
  };
  Polygon out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point& p = poly[i];
    const Point& q = poly[(i + 1) % poly.size()];
    const double sp = s(p), sq = s(q);
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

// Unsigned area of a simple polygon.
inline double area(std::span<const Point> poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point& p = poly[i];
    const Point& q = poly[(i + 1) % poly.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return std::abs(a) / 2;
}

// Triangle 0 = (A, B, C) with a neighbour across each edge; apexes N_ab, N_bc, N_ca.
inline Mesh four_triangles(const Point& a, const Point& b, const Point& c, const Point& n_ab, const Point& n_bc,
                           const Point& n_ca) {
  Mesh mesh;
  mesh.points = {a, b, c, n_ab, n_bc, n_ca};
  mesh.values = {10, 20, 30, 40, 50, 60};
  mesh.triangles = {Triangle{{0, 1, 2}}, Triangle{{1, 0, 3}}, Triangle{{2, 1, 4}}, Triangle{{0, 2, 5}}};
  mesh.normalize_winding();
  return mesh;
}

}  // namespace tristream::testing
