/* SPDX-License-Identifier: MIT */
#pragma once
// Edge functions of a triangle and the per-row span bounds they imply.
//
// For an edge P -> Q (positions in position_fx) and the sample point of pixel (x, y),
//   E(x, y) = A x + B y + C,  A = -(Qy - Py) 2^S,  B = (Qx - Px) 2^S,  C = (Qy - Py) Px - (Qx - Px) Py,
// which is positive inside a triangle of positive orientation. A pixel is covered when
// E >= bias on all three edges: bias 0 for inclusive edges, 1 for exclusive ones. An edge is
// inclusive when it is on the domain boundary, or by the tie rule when A < 0 or (A == 0 and B < 0):
// a sample point on a shared edge belongs to the triangle containing the point moved by
// (-eps, -eps^2), i.e. to the left (and, on a horizontal edge, above), the rule of the reference
// renderer (host_sim/reference/coverage.h). Boundary vertices have an explicit owner (blob.h).
#include <stdint.h>

#include "tristream/config.h"
#include "tuning.h"
#include "arith.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {

struct Edge {
  int64_t a = 0;
  int64_t b = 0;
  int64_t c = 0;       // reduced by the bias: covered when a x + b y + c >= 0
  int64_t c_exact = 0;  // without the bias: a x + b y + c_exact is the exact edge function

  int64_t exact_at(int32_t x, int32_t y) const { return a * x + b * y + c_exact; }
};

// The tie rule, for an edge P -> Q with dx = Qx - Px, dy = Qy - Py: inclusive when on the domain
// boundary, or A < 0, or A == 0 and B < 0 (A = -dy 2^S, B = dx 2^S), i.e. dy > 0, or dy == 0 and
// dx < 0. Every path of the rasterizer takes its biases from here (or from the lane form below).
// In the width of the caller's differences (int32 on the scan path: no 64-bit compares).
template <typename Int>
constexpr bool inclusive_edge(Int dx, Int dy, bool boundary) {
  return boundary | (dy > 0) | ((dy == 0) & (dx < 0));
}

inline Edge make_edge(int32_t px, int32_t py, int32_t qx, int32_t qy, bool boundary) {
  const int64_t dx = int64_t(qx) - px;
  const int64_t dy = int64_t(qy) - py;
  Edge e;
  e.a = -dy * (int64_t(1) << config::subpixel_bits);
  e.b = dx * (int64_t(1) << config::subpixel_bits);
  const bool inclusive = inclusive_edge(dx, dy, boundary);
  e.c_exact = dy * px - dx * py;
  e.c = e.c_exact - (inclusive ? 0 : 1);
  return e;
}

// floor(num(y) / den) for num(y) = num0 + step * (y - y0), den > 0, stepped one row at a time
// with additions only. Exact: quotient and remainder are carried, never rounded.
// No member initializers: a stepper is set by init, init32 or constant (zeroing the steppers of a
// table of rows' bounds, set up per triangle, would cost a store each).
struct FloorStepper {
  int32_t q;       // floor(num / den)
  int32_t r;       // num - q * den, in [0, den)
  int32_t den;
  int32_t q_step;  // floor(step / den)
  int32_t r_step;  // step - q_step * den

  // A bound that stays q on every row.
  static constexpr FloorStepper constant(int32_t q) { return FloorStepper{q, 0, 1, 0, 0}; }

  void init(int64_t num, int64_t step, int64_t d) {
    const int64_t q64 = floor_div(num, d);
    q = int32_t(q64);
    r = int32_t(num - q64 * d);
    den = int32_t(d);
    const int64_t qs = floor_div(step, d);
    q_step = int32_t(qs);
    r_step = int32_t(step - qs * d);
  }
  // The same for num, step and d > 0 in int32 (no 64-bit division or product).
  void init32(int32_t num, int32_t step, int32_t d) {
    floor_divmod32(num, d, &q, &r);
    den = d;
    floor_divmod32(step, d, &q_step, &r_step);
  }
  // The wrap of the remainder as a conditional (on Cortex-M one IT block: CMP, ITT, SUB, ADD), not
  // as a mask (seven instructions). The SSE2 span path steps its bounds in lanes (sse2/edges.h).
  TS_INLINE void next_row() {
    r += r_step;
    q += q_step;
    if (r >= den) {
      r -= den;
      ++q;
    }
  }
};

// The span of covered columns of one row, from the three edges: x >= -floor(num / a) for edges
// with a > 0 (left bounds), x <= floor(num / -a) for a < 0 (right bounds), num = b y + c.
// Edges with a == 0 restrict rows only (see row_range). A triangle of positive area has at least
// one left and one right bound and at most one edge with a == 0, so the bounds are kept in three
// fixed slots: slot 0 a left bound, slot 1 a right bound, slot 2 the third edge (left, right, or a
// neutral left bound for a == 0 that never wins), without a per-row loop over edge kinds.
struct SpanStepper {
  FloorStepper bound[3];
  bool third_left = true;

  void init(const Edge* edges, int32_t y0) {
    int third = 0;
    int order[3] = {-1, -1, -1};
    for (int k = 0; k < 3; ++k) {
      const Edge& e = edges[k];
      if (e.a > 0 && order[0] < 0) {
        order[0] = k;
      } else if (e.a < 0 && order[1] < 0) {
        order[1] = k;
      } else {
        third = k;
      }
    }
    for (int s = 0; s < 2; ++s) {
      const Edge& e = edges[order[s]];
      const int64_t den = e.a > 0 ? e.a : -e.a;
      bound[s].init(e.b * y0 + e.c, e.b, den);
    }
    const Edge& e = edges[third];
    if (e.a == 0) {
      third_left = true;
      bound[2] = FloorStepper::constant(INT32_MAX);  // left bound -INT32_MAX: below every real left bound
    } else {
      third_left = e.a > 0;
      const int64_t den = e.a > 0 ? e.a : -e.a;
      bound[2].init(e.b * y0 + e.c, e.b, den);
    }
  }
  // Columns [*x0, *x1] (inclusive; empty when *x0 > *x1) of the current row.
  TS_INLINE void span(int32_t* x0, int32_t* x1) const {
    columns(bound[0].q, bound[1].q, bound[2].q, -int32_t(third_left), x0, x1);
  }
  TS_INLINE void next_row() {
    bound[0].next_row();
    bound[1].next_row();
    bound[2].next_row();
  }
  // A row's columns from the bounds' quotients q0 (left), q1 (right) and v (the third, on the left
  // when left_mask is all ones, on the right when it is 0: -int32_t(third_left)).
  TS_INLINE static void columns(int32_t q0, int32_t q1, int32_t v, int32_t left_mask, int32_t* x0, int32_t* x1) {
    // The third bound applies to one side; the other side takes a bound that never wins. Bit
    // operations on a mask, not a branch (compilers keep the ternary form as a jump here).
    const int32_t third_lo = (-v & left_mask) | (INT32_MIN & ~left_mask);
    const int32_t third_hi = (INT32_MAX & left_mask) | (v & ~left_mask);
    *x0 = max2(-q0, third_lo);
    *x1 = min2(q1, third_hi);
  }
};

// Narrows [*y0, *y1] (inclusive rows) by the edges with a == 0: b y + c >= 0.
inline void restrict_rows(const Edge* edges, int32_t* y0, int32_t* y1) {
  for (int k = 0; k < 3; ++k) {
    const Edge& e = edges[k];
    if (e.a != 0) continue;
    if (e.b > 0) {
      const int64_t lo = -floor_div(e.c, e.b);  // y >= ceil(-c / b)
      if (lo > *y0) *y0 = int32_t(lo > INT32_MAX ? INT32_MAX : lo);
    } else {
      const int64_t hi = floor_div(e.c, -e.b);
      if (hi < *y1) *y1 = int32_t(hi < INT32_MIN ? INT32_MIN : hi);
    }
  }
}

}  // namespace tristream::core::detail
