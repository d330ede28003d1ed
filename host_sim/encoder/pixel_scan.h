/* SPDX-License-Identifier: MIT */
#pragma once
// The pixels of a triangle with integer vertices, for triangles that tile the rectangle
// [0, W-1] x [0, H-1] (the encoder's meshes): every pixel of the rectangle is visited by
// exactly one triangle. A pixel on an edge or at a vertex belongs to the triangle that holds
// the pixel moved by an infinitesimal step d: d = (-1, -e) (left, then up; e << 1) inside the
// rectangle, with each component turned inwards on the row y = 0 and the column x = 0, so
// that the moved point always lies in the rectangle. Decisions are integer only: per edge one
// bias for each of the four step directions, computed once.
#include <algorithm>
#include <array>
#include <cstdint>

namespace tristream::encoder {

struct IntPoint {
  std::int32_t x = 0;
  std::int32_t y = 0;
};

// Calls visit(x, y) for every pixel (x, y) owned by the triangle v (orient2d > 0,
// coordinates in [0, 2^20)), row by row. Products stay below 2^42: 64-bit edge functions.
template <class Visit>
void scan_triangle(const std::array<IntPoint, 3>& v, Visit&& visit) {
  std::int64_t step_x[3], step_y[3], row_value[3];
  // bias[k][e]: 0 when edge e owns its zero set for step direction k, else -1 (covered iff
  // E + bias >= 0). k = 2 * (x == 0) + (y == 0).
  std::int64_t bias[4][3];
  const int x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
  const int y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
  for (int e = 0; e < 3; ++e) {
    const IntPoint& a = v[e];
    const IntPoint& b = v[(e + 1) % 3];
    const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
    // E(p) = (b - a) x (p - a) = dx (py - ay) - dy (px - ax); inside is E > 0. Moving p by
    // (sx, sy e) changes E by -dy sx + dx sy e: its sign decides a zero.
    step_x[e] = -dy;
    step_y[e] = dx;
    row_value[e] = dx * (y0 - a.y) - dy * (x0 - a.x);
    for (int k = 0; k < 4; ++k) {
      const std::int64_t sx = (k & 2) ? 1 : -1, sy = (k & 1) ? 1 : -1;
      const bool owns_zero = -dy * sx != 0 ? -dy * sx > 0 : dx * sy > 0;
      bias[k][e] = owns_zero ? 0 : -1;
    }
  }
  for (int y = y0; y <= y1; ++y) {
    const int k = y == 0 ? 1 : 0;
    std::int64_t e0 = row_value[0], e1 = row_value[1], e2 = row_value[2];
    int x = x0;
    if (x == 0) {
      if (((e0 + bias[k + 2][0]) | (e1 + bias[k + 2][1]) | (e2 + bias[k + 2][2])) >= 0) visit(0, y);
      e0 += step_x[0], e1 += step_x[1], e2 += step_x[2];
      ++x;
    }
    e0 += bias[k][0], e1 += bias[k][1], e2 += bias[k][2];
    // Skip to the first covered column, then visit the run (one rule: a convex set).
    while (x <= x1 && (e0 | e1 | e2) < 0) {
      e0 += step_x[0], e1 += step_x[1], e2 += step_x[2];
      ++x;
    }
    while (x <= x1 && (e0 | e1 | e2) >= 0) {
      visit(x, y);
      e0 += step_x[0], e1 += step_x[1], e2 += step_x[2];
      ++x;
    }
    for (int e = 0; e < 3; ++e) row_value[e] += step_y[e];
  }
}

}  // namespace tristream::encoder
