/* SPDX-License-Identifier: MIT */
#pragma once
// Pixel writers: how a shader's values become pixels of the tile.
//
// A Writer (DirectWriter here, ScratchWriter in channel_scratch.h) has:
//   P* at(int32_t x, int32_t y) const                  the address of pixel (x, y) of the tile (P: the
//                                                      writer's element type);
//   void put(P* p, int32_t x, int32_t y, const int32_t* v) const
//                                                      one pixel from q24_8 channel values, unclamped;
//   static constexpr bool takes_rounded                whether the next two exist;
//   void put_rounded(P* p, int32_t x, int32_t y, const int32_t* r) const
//                                                      one pixel from rounded integer values, unclamped;
//   void put_span_in_range(...)                        a span of linear values known to round into
//                                                      [0, 255] (DirectWriter);
// (DirectWriter's pixels from three channels in SSE2 lanes: sse2/pixel_writers.h.)
// (x, y) is the absolute output position (dithering is keyed on it).
#include <stdint.h>
#include <string.h>

#include "tristream/config.h"
#include "arith.h"
#include "pixel_conversion.h"
#include "tristream/fixed_point.h"
#include "tristream/pixel_format.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

template <PixelFormat F, int Channels, bool YCbCr>
struct DirectWriter {
  uint8_t* base;
  int32_t stride;
  Rect rect;
  bool dither;

  uint8_t* at(int32_t x, int32_t y) const { return base + (y - rect.y0) * stride + (x - rect.x0) * bytes_per_pixel(F); }
  static constexpr PixelFormat format = F;
  // Whether put_rounded is available: channels that go to the pixel without conversion.
  static constexpr bool takes_rounded = F != PixelFormat::coverage8 && !YCbCr;

  // r: channel values already rounded to integers (q24_8 value v gives (v + 128) >> 8), unclamped.
  void put_rounded(uint8_t* p, int32_t x, int32_t y, const int32_t* r) const {
    if constexpr (Channels == 1) {
      store_grey<F>(p, clamp_u8(r[0]), x, y, dither);
    } else {
      store_rgb<F>(p, clamp_u8(r[0]), clamp_u8(r[1]), clamp_u8(r[2]), x, y, dither);
    }
  }
  // Pixels x0..x1 of row y from q16_16 values (rounding offset included) v0, v1, v2 stepped by d0,
  // d1, d2 (channels 1 and 2 unused for grey), every one known to round into [0, 255]. Scalars, not
  // arrays: on Cortex-M the whole loop state then stays in registers.
  void put_span_in_range(uint8_t* p, int32_t x0, int32_t x1, int32_t y, uint32_t v0, uint32_t v1, uint32_t v2,
                         uint32_t d0, uint32_t d1, uint32_t d2) const {
    if (dither) {
      put_span<true>(p, x0, x1, y, v0, v1, v2, d0, d1, d2);
    } else {
      put_span<false>(p, x0, x1, y, v0, v1, v2, d0, d1, d2);
    }
  }
  // The same for a writer whose dither is Dither (the caller's test, once for many spans).
  template <bool Dither>
  TS_INLINE void put_span(uint8_t* p, int32_t x0, int32_t x1, int32_t y, uint32_t v0, uint32_t v1, uint32_t v2,
                          uint32_t d0, uint32_t d1, uint32_t d2) const {
    constexpr int s = q16_16::frac_bits;
    constexpr int bpp = bytes_per_pixel(F);
    if constexpr (F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be) {
      // Without dithering the loop neither reads the flag nor the position.
      // The pixel pointer is the loop counter (no column count kept beside it).
      if constexpr (!Dither) {
        uint8_t* const end = p + (x1 - x0 + 1) * bpp;
        if constexpr (Channels == 1) {
          for (; p != end; p += bpp, v0 += d0) {
            const uint32_t u = v0 >> s;
            store565_bytes(p, pack565_bytes_by_table<F>(u, u, u));
          }
        } else {
          // G biased by 256 (the table's G half): v1 < 2^24 (put_span_in_range's range), so
          // v1 + 2^24 does not wrap.
          v1 += 256u << s;
          // The table's address in a register for the whole row: an empty asm hides that it is a
          // constant, which GCC otherwise reloads from the literal pool on every pixel.
          const uint16_t* table = rgb565_table<F>.v;
          __asm__("" : "+r"(table));
          for (; p != end; p += bpp, v0 += d0, v1 += d1, v2 += d2)
            store565_bytes(p, pack565_bytes_by_table_biased<F>(v0 >> s, v1 >> s, v2 >> s, table));
        }
      } else {
        put_span_dithered(p, x0, x1, y, v0, v1, v2, d0, d1, d2);
      }
      return;
    }
    if constexpr (Channels == 1) {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, v0 += d0) store_grey<F>(p, uint8_t(v0 >> s), x, y, Dither);
    } else {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, v0 += d0, v1 += d1, v2 += d2)
        store_rgb<F>(p, uint8_t(v0 >> s), uint8_t(v1 >> s), uint8_t(v2 >> s), x, y, Dither);
    }
  }
  // put_span's RGB565 pixels with dithering: one of the row's four scaled Bayer offsets per pixel,
  // chosen by the pixel's address (dither_span_offsets).
  TS_INLINE void put_span_dithered(uint8_t* p, int32_t x0, int32_t x1, int32_t y, uint32_t v0, uint32_t v1,
                                   uint32_t v2, uint32_t d0, uint32_t d1, uint32_t d2) const {
    constexpr int s = q16_16::frac_bits;
    constexpr int bpp = bytes_per_pixel(F);
    const uint32_t* const offset = dither_span_offsets(y, x0, p);
    const uint32_t k31 = in_register(dither_k31), k63 = in_register(dither_k63);
    uint8_t* const end = p + (x1 - x0 + 1) * bpp;
    for (; p != end; p += bpp, v0 += d0, v1 += d1, v2 += d2) {
      const uint32_t o = offset[dither_index(p)];
      if constexpr (Channels == 1) {
        const uint32_t u = v0 >> s;
        store565_bytes(p, rgb565_bytes<F>(pack565_dithered(u, u, u, o, k31, k63)));
      } else {
        store565_bytes(p, rgb565_bytes<F>(pack565_dithered(v0 >> s, v1 >> s, v2 >> s, o, k31, k63)));
      }
    }
  }

  void put(uint8_t* p, int32_t x, int32_t y, const int32_t* v) const {
    if constexpr (F == PixelFormat::coverage8) {
      store_rgb<F>(p, 0, 0, 0, x, y, false);
    } else if constexpr (Channels == 1) {
      store_grey<F>(p, to_u8(v[0]), x, y, dither);
    } else if constexpr (YCbCr) {
      int32_t rgb[3];
      ycbcr_to_rgb_q8(v[0], v[1], v[2], rgb);
      store_rgb<F>(p, to_u8(rgb[0]), to_u8(rgb[1]), to_u8(rgb[2]), x, y, dither);
    } else {
      store_rgb<F>(p, to_u8(v[0]), to_u8(v[1]), to_u8(v[2]), x, y, dither);
    }
  }
};

}  // namespace
}  // namespace tristream::core::detail
