/* SPDX-License-Identifier: MIT */
#pragma once
// RowMasks without SIMD: the covered columns of a scan-path box row, column by column. The SSE2
// alternative is scan_row_masks_sse2.h; both give the same masks.
#include <stdint.h>
#include "unroll.h"

namespace tristream::core::detail {
namespace {

template <int Groups>
class RowMasks {
 public:
  // box: the box's columns as a mask (bits 0 .. width - 1); no column beyond it is tested.
  RowMasks(const int32_t* row, const int32_t* a, const int32_t* b, uint32_t box) : end_(box + 1) {
    TS_UNROLL
    for (int k = 0; k < 3; ++k) row_[k] = row[k], a_[k] = a[k], b_[k] = b[k];
  }
  // The uncovered columns before the covered ones are skipped, then the covered ones counted: the
  // mask is the bits from the first covered column to the one before the next uncovered one.
  __attribute__((always_inline)) uint32_t covered() const {
    int32_t e0 = row_[0], e1 = row_[1], e2 = row_[2];
    const int32_t a0 = a_[0], a1 = a_[1], a2 = a_[2];
    uint32_t bit = 1;
    for (; bit != end_ && (e0 | e1 | e2) < 0; bit <<= 1) e0 += a0, e1 += a1, e2 += a2;
    const uint32_t first = bit;
    for (; bit != end_ && (e0 | e1 | e2) >= 0; bit <<= 1) e0 += a0, e1 += a1, e2 += a2;
    return bit - first;
  }
  __attribute__((always_inline)) void next_row() {
    TS_UNROLL
    for (int k = 0; k < 3; ++k) row_[k] += b_[k];
  }

 private:
  int32_t row_[3], a_[3], b_[3];
  uint32_t end_;
};

}  // namespace
}  // namespace tristream::core::detail
