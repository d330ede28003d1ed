/* SPDX-License-Identifier: MIT */
#pragma once
// The tile cull's test (ColumnWindow::meeting, tile_cull.h) with SSE2: eight triangles at a time in
// 16-bit lanes. The same bits as portable/tile_cull.h (test_core_backends compares them).
#include <stddef.h>
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../arith.h"
#include "../bytes.h"
#include "../triangle_records.h"
#include "tristream/blob.h"

namespace tristream::core::detail::sse2 {
namespace {

// Whether the eight store records at p hold a flag record. StoreRecords: a u16 of 0xFFFF among
// their 48 bytes, which only a flag record's marker is (a slot is at most 0xFFFE, flags at most
// 0x1FF). PackedStoreRecords: a negative int32 among their 32 bytes (a flag record's two top bits
// are set, a triangle's clear).
template <typename Records>
TS_INLINE inline bool has_flag_record8(const uint8_t* p) {
  auto at = [p](int i) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * i)); };
  if constexpr (Records::stride == PackedStoreRecords::stride) {
    static_assert(int32_t(packed_flag_marker) < 0 && (packed_flag_marker << 1) >> 31 == 1, "the marker's top bits");
    return _mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(at(0), at(1)))) != 0;  // the sign bits
  } else {
    static_assert(StoreRecords::stride * 8 == 48, "three vectors");
    const __m128i ones = _mm_set1_epi16(-1);
    const __m128i a = _mm_cmpeq_epi16(at(0), ones), b = _mm_cmpeq_epi16(at(1), ones),
                  c = _mm_cmpeq_epi16(at(2), ones);
    return _mm_movemask_epi8(_mm_or_si128(_mm_or_si128(a, b), c)) != 0;
  }
}

// Bit j: triangle j of the eight records at p meets the columns. Coordinates (16 bits) and bounds
// are compared as signed 16-bit lanes after flipping the top bit (the order of the unsigned
// values); the bounds are clamped to 16 bits only in the direction that keeps more triangles (a
// triangle kept in error is clipped away exactly by rasterize, one missed would be wrong):
// min(low, 65535) for max < low, max(high, 0) for min > high.
template <typename Records>
TS_INLINE inline uint32_t meeting8(const uint8_t* p, const uint8_t* positions, int32_t low, int32_t high) {
  // As the 16-bit lane it goes to (the same bits).
  auto x = [&](int j, int k) {
    return int16_t(load_u16(positions + 4 * size_t(Records::vertex(p + j * Records::stride, k))));
  };
  const __m128i top_bit = _mm_set1_epi16(int16_t(0x8000));
  __m128i v[3];
  for (int k = 0; k < 3; ++k) {
    __m128i w = _mm_cvtsi32_si128(x(0, k));
    w = _mm_insert_epi16(w, x(1, k), 1);
    w = _mm_insert_epi16(w, x(2, k), 2);
    w = _mm_insert_epi16(w, x(3, k), 3);
    w = _mm_insert_epi16(w, x(4, k), 4);
    w = _mm_insert_epi16(w, x(5, k), 5);
    w = _mm_insert_epi16(w, x(6, k), 6);
    w = _mm_insert_epi16(w, x(7, k), 7);
    v[k] = _mm_xor_si128(w, top_bit);
  }
  const __m128i mn = _mm_min_epi16(_mm_min_epi16(v[0], v[1]), v[2]);
  const __m128i mx = _mm_max_epi16(_mm_max_epi16(v[0], v[1]), v[2]);
  const int32_t lo = low < 65535 ? low : 65535, hi = high > 0 ? high : 0;
  const __m128i outside = _mm_or_si128(_mm_cmpgt_epi16(_mm_set1_epi16(int16_t(lo ^ 0x8000)), mx),
                                       _mm_cmpgt_epi16(mn, _mm_set1_epi16(int16_t(hi ^ 0x8000))));
  return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(outside, outside))) & 0xFFu;
}

// portable::meeting's bits. A full window (span 32): each byte of the word with two live
// triangles or more by meeting8 (they are in the window, so their records are valid), the other
// bytes one triangle at a time, as are eight records with a flag record among them (its fields
// are no vertices).
template <typename Records, typename Window>
inline uint32_t meeting(const Window window, const BlobLayer& layer, uint32_t t, uint32_t live, uint32_t span) {
  const uint8_t* const triangles = layer.triangles + size_t(t) * Records::stride;
  const uint8_t* const positions = layer.positions;
  const int32_t low = window.lo, high = window.hi - 1;
  uint32_t hits = 0;
  if (span == 32) {
    uint32_t rest = 0;
    for (int g = 0; g < 4; ++g) {
      const uint32_t byte = (live >> (8 * g)) & 0xFFu;
      const uint8_t* const eight = triangles + size_t(8 * g) * Records::stride;
      if ((byte & (byte - 1)) && !(Records::has_flag_records && has_flag_record8<Records>(eight))) {
        hits |= (meeting8<Records>(eight, positions, low, high) & byte) << (8 * g);
      } else {
        rest |= byte << (8 * g);
      }
    }
    live = rest;
  }
  for (; live; live &= live - 1) {
    const uint32_t i = uint32_t(__builtin_ctz(live));
    const uint8_t* p = triangles + size_t(i) * Records::stride;
    const int32_t x0 = load_u16(positions + 4 * size_t(Records::vertex(p, 0)));
    const int32_t x1 = load_u16(positions + 4 * size_t(Records::vertex(p, 1)));
    const int32_t x2 = load_u16(positions + 4 * size_t(Records::vertex(p, 2)));
    const int32_t outside = (max3(x0, x1, x2) - low) | (high - min3(x0, x1, x2));  // < 0: misses
    hits |= uint32_t(outside >= 0) << i;
  }
  return hits;
}

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
