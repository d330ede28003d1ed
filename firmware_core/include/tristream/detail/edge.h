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
#if TS_USE_SSE2
#include <emmintrin.h>
#endif
#include "tristream/detail/arith.h"

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
constexpr bool inclusive_edge(int64_t dx, int64_t dy, bool boundary) {
  return boundary | (dy > 0) | ((dy == 0) & (dx < 0));
}

#if TS_USE_SSE2
// inclusive_edge in int32 lanes: all ones where inclusive, 0 elsewhere (boundary: all ones or 0).
inline __m128i inclusive_edge_lanes(__m128i dx, __m128i dy, __m128i boundary) {
  const __m128i zero = _mm_setzero_si128();
  return _mm_or_si128(
      _mm_or_si128(_mm_cmpgt_epi32(dy, zero), _mm_and_si128(_mm_cmpeq_epi32(dy, zero), _mm_cmpgt_epi32(zero, dx))),
      boundary);
}
#endif

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
struct FloorStepper {
  int32_t q = 0;      // floor(num / den)
  int32_t r = 0;      // num - q * den, in [0, den)
  int32_t den = 1;
  int32_t q_step = 0;  // floor(step / den)
  int32_t r_step = 0;  // step - q_step * den

  void init(int64_t num, int64_t step, int64_t d) {
    const int64_t q64 = floor_div(num, d);
    q = int32_t(q64);
    r = int32_t(num - q64 * d);
    den = int32_t(d);
    const int64_t qs = floor_div(step, d);
    q_step = int32_t(qs);
    r_step = int32_t(step - qs * d);
  }
  // Without a branch: whether the remainder wraps follows the slope's fraction, which a branch
  // predictor guesses badly.
  __attribute__((always_inline)) void next_row() {
    r += r_step;
    const int32_t wrap = r >= den;
    q += q_step + wrap;
    r -= den & -wrap;
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
      bound[2] = FloorStepper{};
      bound[2].q = INT32_MAX;  // left bound -INT32_MAX: below every real left bound
    } else {
      third_left = e.a > 0;
      const int64_t den = e.a > 0 ? e.a : -e.a;
      bound[2].init(e.b * y0 + e.c, e.b, den);
    }
#if TS_USE_SSE2
    q_ = _mm_setr_epi32(bound[0].q, bound[1].q, bound[2].q, 0);
    r_ = _mm_setr_epi32(bound[0].r, bound[1].r, bound[2].r, 0);
    den_ = _mm_setr_epi32(bound[0].den, bound[1].den, bound[2].den, 1);
    q_step_ = _mm_setr_epi32(bound[0].q_step, bound[1].q_step, bound[2].q_step, 0);
    r_step_ = _mm_setr_epi32(bound[0].r_step, bound[1].r_step, bound[2].r_step, 0);
#endif
  }
  // Columns [*x0, *x1] (inclusive; empty when *x0 > *x1) of the current row.
  __attribute__((always_inline)) void span(int32_t* x0, int32_t* x1) const {
#if TS_USE_SSE2
    const int32_t q0 = _mm_cvtsi128_si32(q_), q1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(q_, 1));
    const int32_t v = _mm_cvtsi128_si32(_mm_shuffle_epi32(q_, 2));
#else
    const int32_t q0 = bound[0].q, q1 = bound[1].q;
    const int32_t v = bound[2].q;
#endif
    // The third bound applies to one side; the other side takes a bound that never wins. Bit
    // operations on a mask, not a branch (compilers keep the ternary form as a jump here).
    const int32_t left_mask = -int32_t(third_left);
    const int32_t third_lo = (-v & left_mask) | (INT32_MIN & ~left_mask);
    const int32_t third_hi = (INT32_MAX & left_mask) | (v & ~left_mask);
    *x0 = max2(-q0, third_lo);
    *x1 = min2(q1, third_hi);
  }
  __attribute__((always_inline)) void next_row() {
#if TS_USE_SSE2
    // FloorStepper::next_row in lanes 0..2 (lane 3 idle): r < 2 den < 2^31, so the signed compare
    // r > den - 1 is r >= den; a wrap is -1 in its lane.
    r_ = _mm_add_epi32(r_, r_step_);
    const __m128i wrap = _mm_cmpgt_epi32(r_, _mm_sub_epi32(den_, _mm_set1_epi32(1)));
    q_ = _mm_sub_epi32(_mm_add_epi32(q_, q_step_), wrap);
    r_ = _mm_sub_epi32(r_, _mm_and_si128(den_, wrap));
#else
    bound[0].next_row();
    bound[1].next_row();
    bound[2].next_row();
#endif
  }

#if TS_USE_SSE2
 private:
  // The three bounds' q, r, den, q_step and r_step in lanes 0..2 (bound[] only sets them up).
  __m128i q_, r_, den_, q_step_, r_step_;
#endif
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
