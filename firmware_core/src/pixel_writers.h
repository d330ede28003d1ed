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
// and with SSE2, for three channels in vector lanes, lanes/ordered/put_lanes/put_span_lanes.
// (x, y) is the absolute output position (dithering is keyed on it).
#include <stdint.h>
#include <string.h>

#include "tristream/config.h"
#if TS_USE_SSE2
#include <emmintrin.h>
#endif
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
    constexpr int s = q16_16::frac_bits;
    constexpr int bpp = bytes_per_pixel(F);
    if constexpr (F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be) {
      // Without dithering the loop neither reads the flag nor the position.
      // The pixel pointer is the loop counter (no column count kept beside it).
      if (!dither) {
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
        return;
      }
      // Dithered: one of the row's four scaled Bayer offsets per pixel, chosen by the pixel's
      // address (dither_span_offsets).
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
      return;
    }
    if constexpr (Channels == 1) {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, v0 += d0) store_grey<F>(p, uint8_t(v0 >> s), x, y, dither);
    } else {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, v0 += d0, v1 += d1, v2 += d2)
        store_rgb<F>(p, uint8_t(v0 >> s), uint8_t(v1 >> s), uint8_t(v2 >> s), x, y, dither);
    }
  }

#if TS_USE_SSE2
  // Pixels x0..x1 of row y from the three q16_16 values in lanes 0..2 of v (rounding offset
  // included), stepped by the lanes of dv: a pixel is one vector addition, its bytes come from
  // saturating packs, which clamp int32(v) >> 16 to [0, 255] exactly as clamp_u8 does (the
  // shifted value fits int16), so no range check is needed.
  // The lanes of put_span_lanes from channels 0, 1, 2: in memory order (B, G, R and 0xFF in lane
  // 3 for a value, 0 for a step, for XRGB8888).
  static __m128i lanes(uint32_t c0, uint32_t c1, uint32_t c2, bool value) {
    constexpr bool bgr = F == PixelFormat::xrgb8888;
    return bgr ? _mm_setr_epi32(int32_t(c2), int32_t(c1), int32_t(c0), value ? 0xFF << 16 : 0)
               : _mm_setr_epi32(int32_t(c0), int32_t(c1), int32_t(c2), 0);
  }
  // Channels 0, 1, 2 in lanes 0, 1, 2 to the lanes of put_lanes.
  static __m128i ordered(__m128i rgb) {
    if constexpr (F == PixelFormat::xrgb8888) return _mm_shuffle_epi32(rgb, _MM_SHUFFLE(3, 0, 1, 2));
    return rgb;
  }
  // pack565 in lanes of rounded int32 R, G, B (not dithered): clamp_u8, v * max + 127 (at most
  // 255 * 63 + 127), divided by 255 as (t * 0x8081) >> 23 (exact for t <= 16313; test_formats
  // checks every 8-bit value), then the fields placed by one multiply-add: lane 0 R * 2^11 + G * 2^5,
  // lane 1 B.
  static void put565(uint8_t* p, __m128i q) {
    const __m128i scale = _mm_setr_epi16(31, 63, 31, 0, 0, 0, 0, 0);
    const __m128i place = _mm_setr_epi16(1 << 11, 1 << 5, 1, 0, 0, 0, 0, 0);
    __m128i c = _mm_min_epi16(_mm_max_epi16(_mm_packs_epi32(q, q), _mm_setzero_si128()), _mm_set1_epi16(255));
    c = _mm_add_epi16(_mm_mullo_epi16(c, scale), _mm_set1_epi16(127));
    c = _mm_madd_epi16(_mm_srli_epi16(_mm_mulhi_epu16(c, _mm_set1_epi16(int16_t(0x8081))), 7), place);
    const uint32_t w = uint32_t(_mm_cvtsi128_si32(_mm_add_epi32(c, _mm_srli_epi64(c, 32))));
    constexpr int lo = F == PixelFormat::rgb565_le ? 0 : 1;
    p[lo] = uint8_t(w);
    p[1 - lo] = uint8_t(w >> 8);
  }
  // One pixel at p from rounded int32 channel values in the lanes of put_span_lanes (unclamped:
  // the saturating packs clamp exactly as clamp_u8). wide: RGB888 may write the byte after the
  // pixel (the next pixel's, written later).
  void put_lanes(uint8_t* p, __m128i q, int32_t x, int32_t y, bool wide) const {
    constexpr bool is_rgb565 = F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be;
    const __m128i q16 = _mm_packs_epi32(q, q);
    uint32_t u = uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(q16, q16)));
    if constexpr (F == PixelFormat::rgb888) {
      if (wide) {
        memcpy(p, &u, 4);
      } else {
        p[0] = uint8_t(u);
        p[1] = uint8_t(u >> 8);
        p[2] = uint8_t(u >> 16);
      }
    } else if constexpr (F == PixelFormat::xrgb8888) {
      u |= 0xFF000000u;
      memcpy(p, &u, 4);
    } else if (is_rgb565 && !dither) {
      put565(p, q);
    } else {
      store_rgb<F>(p, uint8_t(u), uint8_t(u >> 8), uint8_t(u >> 16), x, y, dither);
    }
  }
  void put_span_lanes(uint8_t* p, int32_t x0, int32_t x1, int32_t y, __m128i value, __m128i step) const {
    constexpr int bpp = bytes_per_pixel(F);
    constexpr bool is_rgb565 = F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be;
    auto bytes = [](__m128i w) {
      const __m128i t = _mm_srai_epi32(w, q16_16::frac_bits);
      const __m128i t16 = _mm_packs_epi32(t, t);
      return uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(t16, t16)));
    };
    if constexpr (F == PixelFormat::rgb888) {
      // Four bytes per pixel but the last: the fourth is the next pixel's first, written next.
      for (int32_t x = x0; x < x1; ++x, p += bpp, value = _mm_add_epi32(value, step)) {
        const uint32_t u = bytes(value);
        memcpy(p, &u, 4);
      }
      const uint32_t u = bytes(value);
      p[0] = uint8_t(u);
      p[1] = uint8_t(u >> 8);
      p[2] = uint8_t(u >> 16);
    } else if constexpr (F == PixelFormat::xrgb8888) {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, value = _mm_add_epi32(value, step)) {
        const uint32_t u = bytes(value);
        memcpy(p, &u, 4);
      }
    } else if (is_rgb565 && !dither) {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, value = _mm_add_epi32(value, step))
        put565(p, _mm_srai_epi32(value, q16_16::frac_bits));
    } else {
      for (int32_t x = x0; x <= x1; ++x, p += bpp, value = _mm_add_epi32(value, step)) {
        const uint32_t u = bytes(value);
        store_rgb<F>(p, uint8_t(u), uint8_t(u >> 8), uint8_t(u >> 16), x, y, dither);
      }
    }
  }
#endif
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
