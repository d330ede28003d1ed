/* SPDX-License-Identifier: MIT */
#pragma once
// The pixels a triangle may cover: the box of sample points between its vertices, and its rows
// inside a clip (rasterize.h).
#include <stdint.h>

namespace tristream::core::detail {

struct PixelBox {
  int32_t left, right;  // the first and last pixel column whose sample x is within the vertices'
  int32_t top, bottom;  // the same for rows
  int32_t y0, y1;       // rows top..bottom inside the clip (non-empty)
};

}  // namespace tristream::core::detail
