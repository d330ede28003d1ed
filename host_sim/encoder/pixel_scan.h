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

// Calls visit_run(y, x_first, x_last) for the runs of pixels owned by the triangle v (orient2d >
// 0, coordinates in [0, 2^20)), row by row, left to right: at most two runs a row (the pixel at
// x = 0 on its own, then the rest). Products stay below 2^42: 64-bit edge functions.
template <class VisitRun>
void scan_triangle_runs(const std::array<IntPoint, 3>& v, VisitRun&& visit_run) {
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
  // Row y's covered columns past x = 0 are those with G_e + s_e (x - x0) >= 0 for every edge,
  // G_e = E_e(x0, y) + bias[k][e] and s_e = step_x[e]. An edge with s_e != 0 bounds them by
  // q_e = floor(G_e / |s_e|): from x0 - q_e (s_e > 0) or up to x0 + q_e (s_e < 0). q_e and its
  // remainder step exactly from row to row (G_e grows by step_y[e]); the row y = 0, whose biases
  // differ, is computed directly.
  auto floor_div = [](std::int64_t a, std::int64_t b) {  // b > 0
    const std::int64_t q = a / b;
    return q - ((a % b != 0) && (a < 0));
  };
  std::int64_t q[3] = {}, r[3] = {}, dq[3] = {}, dr[3] = {}, m[3] = {};
  for (int e = 0; e < 3; ++e) {
    m[e] = step_x[e] < 0 ? -step_x[e] : step_x[e];
    if (m[e] == 0) continue;
    const std::int64_t g = row_value[e] + bias[0][e];
    q[e] = floor_div(g, m[e]);
    r[e] = g - q[e] * m[e];
    dq[e] = floor_div(step_y[e], m[e]);
    dr[e] = step_y[e] - dq[e] * m[e];
  }
  const std::int64_t width = x1 - x0;
  for (int y = y0; y <= y1; ++y) {
    int from = x0;
    if (x0 == 0) {
      const int k = y == 0 ? 3 : 2;
      const std::int64_t e0 = row_value[0], e1 = row_value[1], e2 = row_value[2];
      if (((e0 + bias[k][0]) | (e1 + bias[k][1]) | (e2 + bias[k][2])) >= 0) visit_run(y, 0, 0);
      from = 1;
    }
    std::int64_t lo = from - x0, hi = width;  // offsets from x0
    for (int e = 0; e < 3; ++e) {
      if (m[e] == 0) {
        if (row_value[e] + bias[y == 0 ? 1 : 0][e] < 0) hi = -1;
        continue;
      }
      const std::int64_t qe = y == 0 ? floor_div(row_value[e] + bias[1][e], m[e]) : q[e];
      if (step_x[e] > 0)
        lo = std::max(lo, -qe);
      else
        hi = std::min(hi, qe);
      q[e] += dq[e];
      r[e] += dr[e];
      if (r[e] >= m[e]) r[e] -= m[e], ++q[e];
    }
    if (lo <= hi) visit_run(y, x0 + int(lo), x0 + int(hi));
    for (int e = 0; e < 3; ++e) row_value[e] += step_y[e];
  }
}

// Calls visit(x, y) for every pixel (x, y) owned by the triangle v, row by row (as
// scan_triangle_runs).
template <class Visit>
void scan_triangle(const std::array<IntPoint, 3>& v, Visit&& visit) {
  scan_triangle_runs(v, [&](int y, int first, int last) {
    for (int x = first; x <= last; ++x) visit(x, y);
  });
}

}  // namespace tristream::encoder
