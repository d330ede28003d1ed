/* SPDX-License-Identifier: MIT */
#pragma once
// Barycentric coordinates of a triangle with integer corners, as three planes over the pixels.
#include <array>
#include <cstdint>

#include "encoder/pixel_scan.h"

namespace tristream::encoder {

// Twice the signed area of (a, b, c): (b - a) x (c - a), positive for the meshes' orientation.
inline std::int64_t orient(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  return std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(b.y - a.y) * (c.x - a.x);
}

// The weight of corner e at (x, y): ax[e] x + ay[e] y + a0[e], from the edge opposite corner e.
struct BarycentricPlanes {
  double ax[3], ay[3], a0[3];
};

// The planes of triangle p (orient(p) != 0).
inline BarycentricPlanes barycentric_planes(const std::array<IntPoint, 3>& p) {
  const double area2 = double(orient(p[0], p[1], p[2]));
  BarycentricPlanes l;
  for (int e = 0; e < 3; ++e) {
    const IntPoint& b = p[(e + 1) % 3];
    const IntPoint& c = p[(e + 2) % 3];
    l.ax[e] = -(c.y - b.y) / area2;
    l.ay[e] = (c.x - b.x) / area2;
    l.a0[e] = (double(c.y - b.y) * b.x - double(c.x - b.x) * b.y) / area2;
  }
  return l;
}

}  // namespace tristream::encoder
