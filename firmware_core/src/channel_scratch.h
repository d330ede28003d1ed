/* SPDX-License-Identifier: MIT */
#pragma once
// Layered blobs (one mesh per channel): each layer's channel goes into an int16 q4 scratch of the
// tile (3 values per pixel), which is converted to the pixel format once all layers are drawn.
#include <stdint.h>

#include "arith.h"
#include "pixel_conversion.h"
#include "tristream/render_params.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

constexpr int16_t scratch_empty = INT16_MIN;

// One channel of a layered blob into the int16 q4 channel scratch (3 values per pixel).
struct ScratchWriter {
  int16_t* base;
  int32_t width;  // pixels per scratch row
  Rect rect;
  int channel;

  static constexpr bool takes_rounded = false;
  static void put_rounded(int16_t*, int32_t, int32_t, const int32_t*) {}

  int16_t* at(int32_t x, int32_t y) const { return base + 3 * ((y - rect.y0) * width + (x - rect.x0)) + channel; }
  static void put(int16_t* p, int32_t, int32_t, const int32_t* v) {
    int32_t q4 = v[0] >> 4;
    *p = int16_t(q4 < -32767 ? -32767 : (q4 > 32767 ? 32767 : q4));
  }
};

template <PixelFormat F>
void convert_scratch(const int16_t* scratch, uint8_t* base, int32_t stride, const Rect& rect, const RenderParams& p,
                     bool ycbcr) {
  const int32_t w = rect.width();
  for (int32_t y = rect.y0; y < rect.y1; ++y) {
    for (int32_t x = rect.x0; x < rect.x1; ++x) {
      const int16_t* s = scratch + 3 * ((y - rect.y0) * w + (x - rect.x0));
      uint8_t* px = base + (y - rect.y0) * stride + (x - rect.x0) * bytes_per_pixel(F);
      if (s[0] == scratch_empty || s[1] == scratch_empty || s[2] == scratch_empty) {
        store_rgb<F>(px, p.background[0], p.background[1], p.background[2], x, y, p.dither);
        continue;
      }
      int32_t v[3] = {int32_t(s[0]) * 16, int32_t(s[1]) * 16, int32_t(s[2]) * 16};
      if (ycbcr) {
        int32_t rgb[3];
        ycbcr_to_rgb_q8(v[0], v[1], v[2], rgb);
        v[0] = rgb[0], v[1] = rgb[1], v[2] = rgb[2];
      }
      store_rgb<F>(px, to_u8(v[0]), to_u8(v[1]), to_u8(v[2]), x, y, p.dither);
    }
  }
}

}  // namespace
}  // namespace tristream::core::detail
