/* SPDX-License-Identifier: MIT */
#pragma once
// DirectWriter's pixels (pixel_writers.h) from three channels in SSE2 lanes, for the shaders' RGB
// paths on x86-64 (BilinearShader's spans, ZienkiewiczShader's forward-differenced rows): the
// same bytes as DirectWriter::put_rounded of the same rounded values (the golden images run with
// and without SSE2).
#include <stdint.h>
#include <string.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../pixel_conversion.h"
#include "tristream/fixed_point.h"
#include "tristream/pixel_format.h"

namespace tristream::core::detail::sse2 {
namespace {

// The pixels of format F from int32 lanes (dither: DirectWriter's flag).
template <PixelFormat F>
struct PixelLanes {
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
  static void put_lanes(uint8_t* p, __m128i q, int32_t x, int32_t y, bool dither, bool wide) {
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
  // Pixels x0..x1 of row y from the three q16_16 values in lanes 0..2 of v (rounding offset
  // included), stepped by the lanes of dv: a pixel is one vector addition, its bytes come from
  // saturating packs, which clamp int32(v) >> 16 to [0, 255] exactly as clamp_u8 does (the
  // shifted value fits int16), so no range check is needed.
  static void put_span_lanes(uint8_t* p, int32_t x0, int32_t x1, int32_t y, bool dither, __m128i value,
                             __m128i step) {
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
};

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
