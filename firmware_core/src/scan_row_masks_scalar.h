#pragma once
// RowMasks without SIMD: the covered columns of a scan-path box row, column by column. The SSE2
// alternative is scan_row_masks_sse2.h; both give the same masks.
#include <stdint.h>

namespace tristream::core::detail {
namespace {

template <int Groups>
class RowMasks {
 public:
  RowMasks(const int32_t* row, const int32_t* a, const int32_t* b) {
    for (int k = 0; k < 3; ++k) row_[k] = row[k], a_[k] = a[k], b_[k] = b[k];
  }
  uint32_t covered() const {
    int32_t e0 = row_[0], e1 = row_[1], e2 = row_[2];
    uint32_t mask = 0, bit = 1;
    for (int i = 0; i < 16 && (e0 | e1 | e2) < 0; ++i, bit <<= 1) e0 += a_[0], e1 += a_[1], e2 += a_[2];
    for (; bit < 0x10000u && (e0 | e1 | e2) >= 0; bit <<= 1) {
      mask |= bit;
      e0 += a_[0], e1 += a_[1], e2 += a_[2];
    }
    return mask;
  }
  void next_row() {
    for (int k = 0; k < 3; ++k) row_[k] += b_[k];
  }

 private:
  int32_t row_[3], a_[3], b_[3];
};

}  // namespace
}  // namespace tristream::core::detail
