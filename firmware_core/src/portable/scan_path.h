/* SPDX-License-Identifier: MIT */
#pragma once
// The scan path's platform part (scan_path.h) in plain C++: the form of every target without SSE2.
// A row's covered columns are found column by column, stopping at the first uncovered column
// after the covered ones (a row's covered columns are contiguous).
#include <stdint.h>

#include "../tuning.h"
#include "../edge.h"
#include "../shader.h"
#include "../triangle_view.h"
#include "tristream/blob.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail::portable {
namespace {

// One copy of scan_rows for every box width (RowMasks ignores Groups here).
constexpr bool scan_rows_by_width = false;

template <int Groups>
class RowMasks {
 public:
  // box: the box's columns as a mask (bits 0 .. width - 1); no column beyond it is tested.
  RowMasks(const int32_t* row, const int32_t* a, const int32_t* b, uint32_t box) : end_(box + 1) {
    TS_UNROLL
    for (int k = 0; k < 3; ++k) row_[k] = row[k], a_[k] = a[k], b_[k] = b[k];
  }
  // The current row's covered columns [*first, *last] (offsets from the box's first column), or
  // false for none: the uncovered columns before the covered ones are skipped, then the covered
  // ones counted. Where a bit scan is a library call (tuning::scans_bits) the walk counts columns,
  // elsewhere the covered bits' mask is scanned.
  TS_INLINE bool columns(uint32_t /*box*/, int32_t* first, int32_t* last) const {
    constexpr int32_t count = tuning::scans_bits ? 0 : 1;
    int32_t e0 = row_[0], e1 = row_[1], e2 = row_[2];
    const int32_t a0 = a_[0], a1 = a_[1], a2 = a_[2];
    uint32_t bit = 1;
    int32_t i = 0;
    for (; bit != end_ && (e0 | e1 | e2) < 0; bit <<= 1, i += count) e0 += a0, e1 += a1, e2 += a2;
    if (bit == end_) return false;
    const uint32_t first_bit = bit;
    const int32_t i0 = i;
    for (; bit != end_ && (e0 | e1 | e2) >= 0; bit <<= 1, i += count) e0 += a0, e1 += a1, e2 += a2;
    if constexpr (tuning::scans_bits) {
      const uint32_t mask = bit - first_bit;
      *first = __builtin_ctz(mask);
      *last = 31 - __builtin_clz(mask);
    } else {
      *first = i0;
      *last = i - 1;
    }
    return true;
  }
  TS_INLINE void next_row() {
    TS_UNROLL
    for (int k = 0; k < 3; ++k) row_[k] += b_[k];
  }

 private:
  int32_t row_[3], a_[3], b_[3];
  uint32_t end_;
};


struct SmallEdges {
  int32_t a[3], b[3], row[3];
  int32_t first[3];  // E_k at the box's first pixel (row without the bias), for small_setup
  int32_t left, y0;
  int32_t area2;
};

// The edges of a scan-path triangle, for its rows from (left, y0).
inline void small_edges(const TriangleView& tv, int32_t area2, int32_t left, int32_t y0, SmallEdges* e) {
  constexpr int S = config::subpixel_bits;
  e->area2 = area2;
  e->left = left;
  e->y0 = y0;
  TS_UNROLL
  for (int k = 0; k < 3; ++k) {
    const int n = k == 2 ? 0 : k + 1;
    const int32_t dx = tv.x[n] - tv.x[k], dy = tv.y[n] - tv.y[k];
    e->a[k] = -dy * (1 << S);
    e->b[k] = dx * (1 << S);
    const bool inclusive = inclusive_edge(dx, dy, (tv.flags & (boundary_edge0 << k)) != 0);
    e->first[k] = -dy * (left * (1 << S) - tv.x[k]) + dx * (y0 * (1 << S) - tv.y[k]);
    e->row[k] = e->first[k] - (inclusive ? 0 : 1);
  }
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
  // E_k is A_k x + B_k y + C_k (per pixel: a = A 2^S, b = B 2^S): from the box's first pixel.
  const int32_t ox = xr - e.left, oy = yr - e.y0;
  TS_UNROLL
  for (int k = 0; k < 3; ++k) {
    s->a[k] = e.a[k];
    s->b[k] = e.b[k];
    if (Reads != 0) {
      const int32_t ref = e.first[k] + e.a[k] * ox + e.b[k] * oy;
      if (Reads & scan_e_ref32) s->e_ref32[k] = ref;
      if (Reads & scan_e_ref64) s->e_ref[k] = ref;
    }
  }
}

}  // namespace
}  // namespace tristream::core::detail::portable
