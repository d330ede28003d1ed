/* SPDX-License-Identifier: MIT */
#pragma once
// RowMasks for SSE2 (x86-64 hosts): the covered columns of a scan-path box row, four columns at a
// time and without branches. The scalar alternative is scan_row_masks_scalar.h; both give the same
// masks (the golden tests run both).
#include <emmintrin.h>
#include <stdint.h>

#include "tristream/config.h"

namespace tristream::core::detail {
namespace {

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
  __attribute__((always_inline)) RowMasks(__m128i row, __m128i a, __m128i b, uint32_t) {
    init<0>(row, a, b);
    init<1>(row, a, b);
    init<2>(row, a, b);
  }
  __attribute__((always_inline)) uint32_t covered() const {
    __m128i any_negative[4];
    for (int j = 0; j < Groups; ++j) any_negative[j] = _mm_or_si128(_mm_or_si128(e_[0][j], e_[1][j]), e_[2][j]);
    // Columns past the groups: negative (not covered).
    for (int j = Groups; j < 4; ++j) any_negative[j] = _mm_set1_epi32(-1);
    // Saturating packs keep each lane's sign: 16 signs in 16 bytes, one bit each by movemask.
    const __m128i lo = _mm_packs_epi32(any_negative[0], any_negative[1]);
    const __m128i hi = _mm_packs_epi32(any_negative[2], any_negative[3]);
    return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(lo, hi))) & 0xFFFFu;
  }
  __attribute__((always_inline)) void next_row() {
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < Groups; ++j) e_[k][j] = _mm_add_epi32(e_[k][j], b_[k]);
  }

 private:
  template <int K>
  __attribute__((always_inline)) void init(__m128i row, __m128i a, __m128i b) {
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

}  // namespace
}  // namespace tristream::core::detail
