/* SPDX-License-Identifier: MIT */
#pragma once
// Edge functions in SSE2 lanes: the tie rule of three edges at once (for the scan path) and the
// span path's row bounds, three in lanes (portable/edges.h has the interface). The same results
// as the portable forms (test_core_span_stepper compares the bounds row by row).
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../edge.h"

namespace tristream::core::detail::sse2 {

// inclusive_edge in int32 lanes: all ones where inclusive, 0 elsewhere (boundary: all ones or 0).
inline __m128i inclusive_edge_lanes(__m128i dx, __m128i dy, __m128i boundary) {
  const __m128i zero = _mm_setzero_si128();
  return _mm_or_si128(
      _mm_or_si128(_mm_cmpgt_epi32(dy, zero), _mm_and_si128(_mm_cmpeq_epi32(dy, zero), _mm_cmpgt_epi32(zero, dx))),
      boundary);
}

// SpanStepper's three bounds with their FloorStepper::next_row in lanes 0..2 (lane 3 idle): a row
// is four vector operations, with no branch.
class RowSpans {
 public:
  TS_INLINE void init(const Edge* edges, const int32_t* /*ys*/, int32_t y0) {
    SpanStepper bounds;
    bounds.init(edges, y0);
    const FloorStepper* b = bounds.bound;
    left_mask_ = -int32_t(bounds.third_left);
    q_ = _mm_setr_epi32(b[0].q, b[1].q, b[2].q, 0);
    r_ = _mm_setr_epi32(b[0].r, b[1].r, b[2].r, 0);
    den_ = _mm_setr_epi32(b[0].den, b[1].den, b[2].den, 1);
    q_step_ = _mm_setr_epi32(b[0].q_step, b[1].q_step, b[2].q_step, 0);
    r_step_ = _mm_setr_epi32(b[0].r_step, b[1].r_step, b[2].r_step, 0);
  }
  TS_INLINE void begin_row(int32_t) {}
  TS_INLINE void span(int32_t, int32_t* x0, int32_t* x1) const {
    const int32_t q0 = _mm_cvtsi128_si32(q_), q1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(q_, 1));
    const int32_t v = _mm_cvtsi128_si32(_mm_shuffle_epi32(q_, 2));
    SpanStepper::columns(q0, q1, v, left_mask_, x0, x1);
  }
  TS_INLINE void next_row() {
    // r < 2 den < 2^31, so the signed compare r > den - 1 is r >= den; a wrap is -1 in its lane.
    r_ = _mm_add_epi32(r_, r_step_);
    const __m128i wrap = _mm_cmpgt_epi32(r_, _mm_sub_epi32(den_, _mm_set1_epi32(1)));
    q_ = _mm_sub_epi32(_mm_add_epi32(q_, q_step_), wrap);
    r_ = _mm_sub_epi32(r_, _mm_and_si128(den_, wrap));
  }

 private:
  __m128i q_, r_, den_, q_step_, r_step_;
  int32_t left_mask_;  // all ones when the third bound is a left one (SpanStepper::third_left)
};

}  // namespace tristream::core::detail::sse2
#endif
