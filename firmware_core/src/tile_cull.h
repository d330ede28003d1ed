/* SPDX-License-Identifier: MIT */
#pragma once
// The tile cull: which live triangles meet a tile's columns, from the raw vertex x alone.
#include <stddef.h>
#include <stdint.h>

#include "output_mapping.h"
#include "triangle_records.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#include "backend.h"
#include "portable/tile_cull.h"
#include "sse2/tile_cull.h"
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

  // The test of a triangle against the window, in the platform's form (backend::meeting, in
  // portable/tile_cull.h and sse2/tile_cull.h):
  //   uint32_t meeting<Records>(const ColumnWindow&, const BlobLayer& layer, uint32_t t, uint32_t live,
  //                             uint32_t span)
  // returns the triangles t + i (bit i of live; span: the live window's length) whose columns meet
  // the tile, as bits (Records: the layout of the layer's triangle records, triangle_records.h).
  // The test is one sign, not (max < lo) | (min >= hi), which compilers turn into two branches,
  // the first taken for a share of the triangles that grows along the band (unpredictable in the
  // middle tiles).
};

}  // namespace
}  // namespace tristream::core::detail
