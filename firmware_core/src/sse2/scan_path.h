/* SPDX-License-Identifier: MIT */
#pragma once
// The scan path's platform part (scan_path.h) with SSE2: the edges of a small triangle in lanes,
// the covered columns of a box row four columns at a time and without branches (whose
// mispredictions cost more than the rest of a small triangle's rows). The same masks and set-up
// as the portable raster's set-up (test_core_backends compares them).
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../edge.h"
#include "../shader.h"
#include "../triangle_view.h"
#include "tristream/blob.h"
#include "tristream/fixed_point.h"
#include "edges.h"

namespace tristream::core::detail::sse2 {
namespace {

// scan_rows in a copy per box width in groups of four columns (1 to 4).
constexpr bool scan_rows_by_width = true;

// Whether the x coefficient A = -dy 2^S of a scan-path edge fits int16 (|dy| < 18 * 2^S, see
// SmallEdges).
constexpr bool small_a_fits_int16 = (int32_t(18) << (2 * config::subpixel_bits)) <= 32768;

// Groups: vectors of four columns per edge, as many as the box needs (at most 4 for boxes below 16
// columns), so the whole state stays in registers.
template <int Groups>
class RowMasks {
 public:
  // From the edges in lanes 0..2 of row, a and b (all the groups' columns are tested: the caller
  // masks the result with the box).
  TS_INLINE RowMasks(__m128i row, __m128i a, __m128i b, uint32_t) {
    init<0>(row, a, b);
    init<1>(row, a, b);
    init<2>(row, a, b);
  }
  // The current row's covered columns [*first, *last] within box (offsets from its first column),
  // or false for none.
  TS_INLINE bool columns(uint32_t box, int32_t* first, int32_t* last) const {
    const uint32_t mask = covered() & box;
    if (!mask) return false;
    *first = __builtin_ctz(mask);
    *last = 31 - __builtin_clz(mask);
    return true;
  }
  TS_INLINE uint32_t covered() const {
    __m128i any_negative[4];
    for (int j = 0; j < Groups; ++j) any_negative[j] = _mm_or_si128(_mm_or_si128(e_[0][j], e_[1][j]), e_[2][j]);
    // Columns past the groups: negative (not covered).
    for (int j = Groups; j < 4; ++j) any_negative[j] = _mm_set1_epi32(-1);
    // Saturating packs keep each lane's sign: 16 signs in 16 bytes, one bit each by movemask.
    const __m128i lo = _mm_packs_epi32(any_negative[0], any_negative[1]);
    const __m128i hi = _mm_packs_epi32(any_negative[2], any_negative[3]);
    return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(lo, hi))) & 0xFFFFu;
  }
  TS_INLINE void next_row() {
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < Groups; ++j) e_[k][j] = _mm_add_epi32(e_[k][j], b_[k]);
  }

 private:
  template <int K>
  TS_INLINE void init(__m128i row, __m128i a, __m128i b) {
    const __m128i ak = _mm_shuffle_epi32(a, K * 0x55);
    const __m128i four_a = _mm_slli_epi32(ak, 2);
    // Lanes 0..3: row + (0, 1, 2, 3) a (SSE2 has no 32-bit lane product).
    __m128i ramp;
    if constexpr (small_a_fits_int16) {
      // One int16 multiply-add: a's low half (a itself) times 0..3, its high half times 0.
      ramp = _mm_madd_epi16(ak, _mm_setr_epi32(0, 1, 2, 3));
    } else {
      ramp = _mm_and_si128(ak, _mm_set_epi32(-1, -1, -1, 0));
      ramp = _mm_add_epi32(ramp, _mm_and_si128(ak, _mm_set_epi32(-1, -1, 0, 0)));
      ramp = _mm_add_epi32(ramp, _mm_and_si128(ak, _mm_set_epi32(-1, 0, 0, 0)));
    }
    __m128i e = _mm_add_epi32(_mm_shuffle_epi32(row, K * 0x55), ramp);
    for (int j = 0; j < Groups; ++j) {
      e_[K][j] = e;
      e = _mm_add_epi32(e, four_a);
    }
    b_[K] = _mm_shuffle_epi32(b, K * 0x55);
  }

  __m128i e_[3][Groups];
  __m128i b_[3];
};


struct SmallEdges {
  // Lane k: the int16 pair (-dy_k, dx_k) (low half, high half); A_k; B_k; E_k - bias_k at the box's
  // first pixel.
  __m128i pairs, a, b, row;
  int32_t area2;
};

// Lanes 0..2 (int32, each below 2^15 in magnitude) of lo and hi as int16 pairs (lo low, hi high).
inline __m128i int16_pairs(__m128i lo, __m128i hi) {
  return _mm_or_si128(_mm_and_si128(lo, _mm_set1_epi32(0xFFFF)), _mm_slli_epi32(hi, 16));
}

// The edges of a scan-path triangle, for its rows from (left, y0).
inline void small_edges(const TriangleView& tv, int32_t area2, int32_t left, int32_t y0, SmallEdges* e) {
  constexpr int S = config::subpixel_bits;
  e->area2 = area2;
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i dx = _mm_sub_epi32(_mm_shuffle_epi32(x, _MM_SHUFFLE(3, 0, 2, 1)), x);
  const __m128i dy = _mm_sub_epi32(_mm_shuffle_epi32(y, _MM_SHUFFLE(3, 0, 2, 1)), y);
  const __m128i zero = _mm_setzero_si128();
  const __m128i neg_dy = _mm_sub_epi32(zero, dy);
  e->pairs = int16_pairs(neg_dy, dx);
  e->a = _mm_slli_epi32(neg_dy, S);
  e->b = _mm_slli_epi32(dx, S);
  // The tie rule of detail/edge.h.
  const __m128i bits = _mm_setr_epi32(boundary_edge0, boundary_edge0 << 1, boundary_edge0 << 2, 0);
  const __m128i boundary = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(tv.flags), bits), bits);
  const __m128i inclusive = inclusive_edge_lanes(dx, dy, boundary);
  const __m128i offsets = int16_pairs(_mm_sub_epi32(_mm_set1_epi32(left * (1 << S)), x),
                                      _mm_sub_epi32(_mm_set1_epi32(y0 * (1 << S)), y));
  // E - bias = E - 1 - (inclusive ? -1 : 0) = E + ~inclusive.
  e->row = _mm_add_epi32(_mm_madd_epi16(e->pairs, offsets), _mm_xor_si128(inclusive, _mm_set1_epi32(-1)));
}

// The setup of a scan-path triangle for the shader (on its first covered row in the clip).
// Without SSE2 e_ref32 and e_ref are set only where the shader reads them (ERefsRead).
template <unsigned Reads = scan_e_ref32 | scan_e_ref64>
inline void small_setup(const TriangleView& tv, const SmallEdges& e, TriangleSetup* s) {
  const int32_t xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  const int32_t yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  s->xr = xr;
  s->yr = yr;
  s->area2 = e.area2;
  s->small_box = true;
  constexpr int S = config::subpixel_bits;
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i ref = _mm_madd_epi16(e.pairs, int16_pairs(_mm_sub_epi32(_mm_set1_epi32(xr * (1 << S)), x),
                                                          _mm_sub_epi32(_mm_set1_epi32(yr * (1 << S)), y)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->a), e.a);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->b), e.b);
  const __m128i sign = _mm_srai_epi32(ref, 31);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->e_ref), _mm_unpacklo_epi32(ref, sign));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(s->e_ref + 2), _mm_unpackhi_epi32(ref, sign));
}

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
