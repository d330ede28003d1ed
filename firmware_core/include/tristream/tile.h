/* SPDX-License-Identifier: MIT */
#pragma once
// A tile: a view of caller memory holding the pixels of a screen rectangle.
#include <stdint.h>

#include "tristream/pixel_format.h"

namespace tristream::core {

// Half-open screen rectangle: columns x0 .. x1-1, rows y0 .. y1-1, in output pixels.
struct Rect {
  int32_t x0 = 0;
  int32_t y0 = 0;
  int32_t x1 = 0;
  int32_t y1 = 0;

  constexpr int32_t width() const { return x1 - x0; }
  constexpr int32_t height() const { return y1 - y0; }
  constexpr bool empty() const { return x1 <= x0 || y1 <= y0; }
};

// Pixel (x, y) of the screen, for x in [rect.x0, rect.x1) and y in [rect.y0, rect.y1), is at
// pixels + (y - rect.y0) * stride + (x - rect.x0) * bytes_per_pixel(format).
struct Tile {
  uint8_t* pixels = nullptr;
  int32_t stride = 0;  // bytes from one row to the next
  Rect rect;
  PixelFormat format = PixelFormat::rgb888;
};

// Receives each finished tile, in band order (top to bottom), left to right within a band.
// A tile buffer is reused for the next tile once the sink returns (a target's tiles stay where
// they were drawn: RenderParams::target).
using TileSink = void (*)(void* context, const Tile* tile);

}  // namespace tristream::core
