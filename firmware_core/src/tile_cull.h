/* SPDX-License-Identifier: MIT */
#pragma once
// The tile cull: which live triangles meet a tile's columns, from the raw vertex x alone.
#include <stddef.h>
#include <stdint.h>

#include "output_mapping.h"
#include "triangle_records.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#if TS_USE_SSE2
#include <emmintrin.h>
#endif
#include "arith.h"
#include "bytes.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

// The columns [rect.x0, rect.x1) of a tile as thresholds on raw (domain, unmapped) vertex x:
// a triangle's columns [ceil(min x'), floor(max x')] (x' mapped) miss the tile exactly when
// max x < lo or min x >= hi, because the mapping is monotone: floor(m / 2^S) < x0 iff m < x0 2^S,
// and ceil(m / 2^S) >= x1 iff m >= (x1 - 1) 2^S + 1. One cheap test per live triangle and tile.
struct ColumnWindow {
  int32_t lo, hi;

  // Smallest raw v in [0, 65536] with map.x(v) >= target (65536 when there is none).
  static int32_t first_at_least(const Mapping& map, int32_t target) {
    if (map.identity) return target < 0 ? 0 : (target > 65536 ? 65536 : target);
    int32_t lo = 0, hi = 65536;
    while (lo < hi) {
      const int32_t mid = lo + (hi - lo) / 2;
      if (map.x(mid) >= target) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    return lo;
  }
  ColumnWindow(const Mapping& map, const Rect& rect)
      : lo(first_at_least(map, rect.x0 * (1 << config::subpixel_bits))),
        hi(first_at_least(map, (rect.x1 - 1) * (1 << config::subpixel_bits) + 1)) {}

  // The triangles t + i (bit i of live) whose columns meet the tile, as bits. A loop without
  // branches on the data and without calls (so its pointers and bounds stay in registers): the
  // test is one sign, not (max < lo) | (min >= hi), which compilers turn into two branches, the
  // first taken for a share of the triangles that grows along the band (unpredictable in the
  // middle tiles).
  // Records: the layout of the layer's triangle records (triangle_records.h).
  template <typename Records>
  uint32_t meeting(const BlobLayer& layer, uint32_t t, uint32_t live, uint32_t span) const {
    const uint8_t* const triangles = layer.triangles + size_t(t) * Records::stride;
    const uint8_t* const positions = layer.positions;
    const int32_t low = lo, high = hi - 1;
#if TS_USE_SSE2
    uint32_t hits = 0;
    if (span == 32) {
      // Bytes of the word with two live triangles or more: all eight triangles in 16-bit lanes
      // (they are in the window, so their records are valid), the other bytes one by one below,
      // as are eight records with a flag record among them (its fields are no vertices).
      uint32_t rest = 0;
      for (int g = 0; g < 4; ++g) {
        const uint32_t byte = (live >> (8 * g)) & 0xFFu;
        const uint8_t* const eight = triangles + size_t(8 * g) * Records::stride;
        if ((byte & (byte - 1)) && !(Records::has_flag_records && has_flag_record8<Records>(eight))) {
          hits |= (meeting8<Records>(eight, positions) & byte) << (8 * g);
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
#else
    (void)span;
    // From the highest live bit down: its leading zeros j give the bit (0x80000000 >> j) and the
    // record (31 - j records on), a miss clears its bit from the kept bits with one masked clear,
    // and the bit leaves the live ones with a flag-setting clear: 24 Thumb-2 instructions a test
    // against 28 for the lowest bit's index, a shifted hit bit and live &= live - 1 (kodim23
    // 768 x 512 in 32 x 32 tiles -1.3 % modelled Cortex-M4 cycles; one more for the band store's
    // 6-byte records, whose offset takes two). The last record's address as an integer: the bit's
    // record is that minus stride x j without forming a pointer before the layer's records (bit
    // 31 - j is live, so its record is in the window).
    const uintptr_t last = uintptr_t(triangles) + 31 * Records::stride;
    uint32_t kept = live;
    while (live) {
      const uint32_t j = uint32_t(__builtin_clz(live));
      const uint32_t bit = 0x80000000u >> j;
      const uint8_t* p = reinterpret_cast<const uint8_t*>(last - j * Records::stride);
      const int32_t x0 = load_u16(positions + 4 * size_t(Records::vertex(p, 0)));
      const int32_t x1 = load_u16(positions + 4 * size_t(Records::vertex(p, 1)));
      const int32_t x2 = load_u16(positions + 4 * size_t(Records::vertex(p, 2)));
      // The sign of ANDed differences (misses when every x is below low or every x above high):
      // the same test as max and min, which take IT blocks on Cortex-M4.
      const int32_t outside = ((x0 - low) & (x1 - low) & (x2 - low)) | ((high - x0) & (high - x1) & (high - x2));
      kept &= ~(bit & uint32_t(outside >> 31));
      live &= ~bit;
    }
    return kept;
#endif
  }
#if TS_USE_SSE2
  // Whether the eight store records at p hold a flag record. StoreRecords: a u16 of 0xFFFF among
  // their 48 bytes, which only a flag record's marker is (a slot is at most 0xFFFE, flags at most
  // 0x1FF). PackedStoreRecords: a negative int32 among their 32 bytes (a flag record's two top bits
  // are set, a triangle's clear).
  template <typename Records>
  static bool has_flag_record8(const uint8_t* p) {
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
  // Bit j: triangle j of the eight records at p meets the columns. Coordinates (16 bits) and
  // bounds are compared as signed 16-bit lanes after flipping the top bit (the order of the
  // unsigned values); the bounds are clamped to 16 bits only in the direction that keeps more
  // triangles (a triangle kept in error is clipped away exactly by rasterize, one missed would be
  // wrong): min(lo, 65535) for max < lo, max(hi - 1, 0) for min > hi - 1.
  template <typename Records>
  uint32_t meeting8(const uint8_t* p, const uint8_t* positions) const {
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
    const int32_t low = lo < 65535 ? lo : 65535, high = hi - 1 > 0 ? hi - 1 : 0;
    const __m128i outside = _mm_or_si128(_mm_cmpgt_epi16(_mm_set1_epi16(int16_t(low ^ 0x8000)), mx),
                                         _mm_cmpgt_epi16(mn, _mm_set1_epi16(int16_t(high ^ 0x8000))));
    return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(outside, outside))) & 0xFFu;
  }
#endif
};

}  // namespace
}  // namespace tristream::core::detail
