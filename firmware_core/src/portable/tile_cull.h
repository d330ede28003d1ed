/* SPDX-License-Identifier: MIT */
#pragma once
// The tile cull's test (ColumnWindow::meeting, tile_cull.h) in plain C++: the form of every target
// without SSE2.
#include <stddef.h>
#include <stdint.h>

#include "../tuning.h"
#include "../bytes.h"
#include "tristream/blob.h"

namespace tristream::core::detail::portable {
namespace {

// All ones when the triangle of record p misses the columns [low, high] (every raw x below low or
// every one above high), else 0: the sign of ANDed differences, the same test as max and min, which
// take IT blocks on Cortex-M4.
template <typename Records>
TS_INLINE inline uint32_t misses(const uint8_t* positions, const uint8_t* p, int32_t low, int32_t high) {
  const int32_t x0 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 0)));
  const int32_t x1 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 1)));
  const int32_t x2 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 2)));
  const int32_t outside = ((x0 - low) & (x1 - low) & (x2 - low)) | ((high - x0) & (high - x1) & (high - x2));
  return uint32_t(outside >> 31);
}

// ColumnWindow::meeting (tile_cull.h): the triangles t + i of the layer (bit i of live; span
// unused here) whose raw vertex x are not all below window.lo nor all above window.hi - 1, as bits.
// A loop without branches on the data and without calls, so that its pointers and bounds stay in
// registers.
// Where a bit scan is an instruction (tuning::scans_bits), from the highest live bit down: its
// leading zeros j give the bit (0x80000000 >> j) and the record (31 - j records on), a miss clears
// its bit from the kept bits with one masked clear, and the bit leaves the live ones with a
// flag-setting clear: 24 Thumb-2 instructions a test against 28 for the lowest bit's index, a
// shifted hit bit and live &= live - 1 (one more for the band store's 6-byte records, whose offset
// takes two). The last record's address as an integer: the bit's record is that minus stride x j
// without forming a pointer before the layer's records (bit 31 - j is live, so its record is in
// the window). Elsewhere from the lowest bit up, one shift a bit.
template <typename Records, typename Window>
inline uint32_t meeting(const Window& window, const BlobLayer& layer, uint32_t t, uint32_t live, uint32_t span) {
  const uint8_t* const triangles = layer.triangles + size_t(t) * Records::stride;
  const uint8_t* const positions = layer.positions;
  const int32_t low = window.lo, high = window.hi - 1;
  (void)span;
  uint32_t kept = live;
  if constexpr (!tuning::scans_bits) {
    // A bit scan is a library call here (ARMv6-M: __clzsi2; RISC-V without Zbb).
    const uint8_t* p = triangles;
    for (uint32_t bit = 1; live; live >>= 1, bit <<= 1, p += Records::stride)
      if (live & 1) kept &= ~(bit & misses<Records>(positions, p, low, high));
    return kept;
  }
  const uintptr_t last = uintptr_t(triangles) + 31 * Records::stride;
  while (live) {
    const uint32_t j = uint32_t(__builtin_clz(live));
    const uint32_t bit = 0x80000000u >> j;
    const uint8_t* p = reinterpret_cast<const uint8_t*>(last - j * Records::stride);
    // misses' test written out: the Cortex-M4's code through the call differs (+1.2 % cycles in
    // 32 x 32 tiles).
    const int32_t x0 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 0)));
    const int32_t x1 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 1)));
    const int32_t x2 = load_u16_even(positions + 4 * size_t(Records::vertex(p, 2)));
    const int32_t outside = ((x0 - low) & (x1 - low) & (x2 - low)) | ((high - x0) & (high - x1) & (high - x2));
    kept &= ~(bit & uint32_t(outside >> 31));
    live &= ~bit;
  }
  return kept;
}

}  // namespace
}  // namespace tristream::core::detail::portable
