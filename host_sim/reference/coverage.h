/* SPDX-License-Identifier: MIT */
#pragma once
// The pixel coverage rule shared by every triangle-based reference method (docs/CONVENTIONS.md):
// output pixel (i, j) samples the domain point (i * sx, j * sy). A sample point strictly
// inside a triangle belongs to it. A point on edges is decided by symbolic perturbation: it
// belongs to the triangle that contains p + eps * w(p), where w points into the image
// rectangle at its border and is the classic top-left direction elsewhere:
//   w = (sx, sy * delta), sx = +1 in column 0 and -1 elsewhere, sy = +1 in row 0 and -1
//   elsewhere (delta infinitesimal). For edge a->b of a triangle with orient2d > 0 (Mesh
//   winding), d = b - a, the edge owns its points iff cross(d, w) > 0, that is
//   (-sx * d.y > 0) or (d.y == 0 and sy * d.x > 0).
// The same edge seen from its neighbour (-d) fails the test, and at a vertex exactly one
// triangle of the fan contains the direction w, so every sample point of a triangulation
// of the whole image rectangle is visited exactly once, vertices on the border included.
// For a domain that is not the whole rectangle, boundary edges off the rectangle border are
// also inclusive (the outer boundary is part of the domain); a sample point exactly at such a
// boundary vertex may then be visited twice, both times with that vertex's value.
// Decisions use exact orientation predicates (geometry/predicates.h).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/predicates.h"
#include "model/topology.h"
#include "model/triangulation.h"

namespace tristream {

// Maps output pixels to domain points: corner to corner, or with one scale of scale_d / scale_n
// domain units per output pixel on both axes (the fits; a sample is then i * d / n, rounded once).
struct PixelMapping {
  int out_width = 0, out_height = 0;
  double sx = 1, sy = 1;  // domain units per output pixel
  std::int64_t scale_n = 0, scale_d = 0;

  PixelMapping(int domain_width, int domain_height, int width, int height, std::int64_t n = 0, std::int64_t d = 0)
      : out_width(width), out_height(height),
        sx(n > 0 ? double(d) / double(n) : width > 1 ? double(domain_width - 1) / (width - 1) : 1.0),
        sy(n > 0 ? double(d) / double(n) : height > 1 ? double(domain_height - 1) / (height - 1) : 1.0),
        scale_n(n), scale_d(d) {}

  double coordinate(int i, double s) const {
    if (s == 1) return double(i);
    return scale_n > 0 ? double(i * scale_d) / double(scale_n) : i * s;
  }
  Point sample(int i, int j) const { return {coordinate(i, sx), coordinate(j, sy)}; }
  // The output pixel range whose sample points can lie in [lo, hi] (domain units).
  int first_column(double lo) const { return std::max(0, int(std::floor(lo / sx)) - 1); }
  int last_column(double hi) const { return std::min(out_width - 1, int(std::ceil(hi / sx)) + 1); }
  int first_row(double lo) const { return std::max(0, int(std::floor(lo / sy)) - 1); }
  int last_row(double hi) const { return std::min(out_height - 1, int(std::ceil(hi / sy)) + 1); }
};

// Whether edge a->b owns the points on it that are sampled in a column with sign sx and a
// row with sign sy (see the rule above).
inline bool owns_edge_points(const Point& a, const Point& b, int sx, int sy) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return (-sx * dy > 0) || (dy == 0 && sy * dx > 0);
}

namespace detail {

// orient2d(a, b, p) from one floating-point evaluation when its sign is certain (Shewchuk's
// error bound for this expression), else from the exact predicate.
// With `exact` (every coordinate an integer of magnitude below 2^25) the evaluation has no
// rounding at all and is returned as it is.
inline double orient_filtered(const Point& a, const Point& b, const Point& p, bool exact) {
  const double l = (b.x - a.x) * (p.y - a.y);
  const double r = (b.y - a.y) * (p.x - a.x);
  const double det = l - r;
  if (exact) return det;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound || -det > bound) return det;
  return orient2d(a, b, p);
}

inline bool is_small_integer(double v) { return v == std::trunc(v) && std::abs(v) < 33554432.0; }

}  // namespace detail

// Calls visit(i, j, l0, l1, l2) for every output pixel (i, j) whose sample point triangle t
// owns; (l0, l1, l2) are the barycentric coordinates of the sample point with respect to
// t's vertices v[0], v[1], v[2]. Each row scans only the columns of the triangle's span
// there (widened by a pixel and a rounding margin); every pixel decision is exact.
template <class Visit>
void for_each_owned_pixel(const Mesh& mesh, const Topology& topo, std::uint32_t t, const PixelMapping& map,
                          Visit&& visit) {
  const auto& v = mesh.triangles[t].v;
  const Point& p0 = mesh.points[v[0]];
  const Point& p1 = mesh.points[v[1]];
  const Point& p2 = mesh.points[v[2]];
  const Point* corner[3] = {&p0, &p1, &p2};
  // inclusive[k][e]: k = 0 elsewhere, 1 in column 0, 2 in row 0, 3 at pixel (0, 0).
  bool inclusive[4][3];
  for (int k = 0; k < 4; ++k)
    for (int e = 0; e < 3; ++e)
      inclusive[k][e] = topo.is_boundary_edge(t, e) ||
                        owns_edge_points(*corner[e], *corner[(e + 1) % 3], k & 1 ? 1 : -1, k & 2 ? 1 : -1);
  const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
  constexpr double eps = 2.220446049250313e-16;
  // Integer vertices sampled at integer points (the usual case) need no exact fallback.
  bool exact = map.sx == 1 && map.sy == 1;
  for (const Point* c : corner) exact = exact && detail::is_small_integer(c->x) && detail::is_small_integer(c->y);

  const int i0 = map.first_column(std::min({p0.x, p1.x, p2.x}));
  const int i1 = map.last_column(std::max({p0.x, p1.x, p2.x}));
  const int j0 = map.first_row(std::min({p0.y, p1.y, p2.y}));
  const int j1 = map.last_row(std::max({p0.y, p1.y, p2.y}));
  for (int j = j0; j <= j1; ++j) {
    const double y = map.sample(0, j).y;
    // The span of x where every edge function is >= 0, conservatively widened.
    double lo = -1e300, hi = 1e300;
    for (int e = 0; e < 3; ++e) {
      const Point& a = *corner[e];
      const Point& b = *corner[(e + 1) % 3];
      const double dy = b.y - a.y;
      if (dy == 0) continue;  // a horizontal edge bounds rows, not columns: left to the exact test
      const double shift = (b.x - a.x) * (y - a.y) / dy;
      const double x = a.x + shift;
      const double margin = 8 * eps * (std::abs(a.x) + std::abs(shift)) + 1e-300;
      if (dy > 0) hi = std::min(hi, x + margin);
      else lo = std::max(lo, x - margin);
    }
    if (lo > hi) continue;
    const int first = std::max(i0, lo <= -1e299 ? i0 : map.first_column(lo));
    const int last = std::min(i1, hi >= 1e299 ? i1 : map.last_column(hi));
    for (int i = first; i <= last; ++i) {
      const Point p = map.sample(i, j);
      const bool* incl = inclusive[(i == 0 ? 1 : 0) + (j == 0 ? 2 : 0)];
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        const double o = detail::orient_filtered(*corner[e], *corner[(e + 1) % 3], p, exact);
        inside = o > 0 || (o == 0 && incl[e]);
      }
      if (!inside) continue;
      // Barycentric coordinates: the sub-triangle opposite each vertex over the whole.
      const double l0 = ((p1.x - p.x) * (p2.y - p.y) - (p1.y - p.y) * (p2.x - p.x)) / area;
      const double l1 = ((p2.x - p.x) * (p0.y - p.y) - (p2.y - p.y) * (p0.x - p.x)) / area;
      visit(i, j, l0, l1, 1.0 - l0 - l1);
    }
  }
}

}  // namespace tristream
