/* SPDX-License-Identifier: MIT */
#pragma once
// Turning interpolated channel values (q24_8, unclamped) into output pixels: colour conversion,
// clamping, rounding, RGB565 packing (with optional Bayer dithering on absolute position).
#include <stdint.h>
#include <string.h>

#include "bytes.h"
#include "tuning.h"
#include "tristream/pixel_format.h"

namespace tristream::core::detail {

// Round a q24_8 value to nearest and clamp to [0, 255].
inline uint8_t to_u8(int32_t v_q8) {
  int32_t r = (v_q8 + 128) >> 8;
  return uint8_t(r < 0 ? 0 : (r > 255 ? 255 : r));
}

// Clamp a rounded value to [0, 255].
inline uint8_t clamp_u8(int32_t r) { return uint8_t(r < 0 ? 0 : (r > 255 ? 255 : r)); }

// JPEG YCbCr (BT.601 full range) to RGB on q24_8 values, coefficients in q16.
inline void ycbcr_to_rgb_q8(int32_t y, int32_t cb, int32_t cr, int32_t* rgb) {
  const int64_t dcb = int64_t(cb) - 128 * 256;
  const int64_t dcr = int64_t(cr) - 128 * 256;
  constexpr int64_t k_r_cr = 91881;   // 1.402 * 2^16
  constexpr int64_t k_g_cb = 22554;   // 0.344136286 * 2^16
  constexpr int64_t k_g_cr = 46802;   // 0.714136286 * 2^16
  constexpr int64_t k_b_cb = 116130;  // 1.772 * 2^16
  constexpr int64_t half = 1 << 15;
  rgb[0] = int32_t(y + ((k_r_cr * dcr + half) >> 16));
  rgb[1] = int32_t(y - ((k_g_cb * dcb + k_g_cr * dcr - half) >> 16));
  rgb[2] = int32_t(y + ((k_b_cb * dcb + half) >> 16));
}

// BT.601 luma of 8-bit RGB, rounded.
inline uint8_t luma(uint8_t r, uint8_t g, uint8_t b) {
  return uint8_t((19595u * r + 38470u * g + 7471u * b + 32768u) >> 16);
}

// The per-pixel helpers below are always inlined: at -Os GCC otherwise calls them once per pixel.

// 4x4 Bayer thresholds scaled to [8, 248]: the rounding offset of an 8-bit to n-bit conversion.
inline constexpr uint8_t bayer_matrix[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
TS_INLINE constexpr uint32_t bayer_offset(int32_t x, int32_t y) {
  return uint32_t(bayer_matrix[y & 3][x & 3]) * 16u + 8u;
}

// n-bit value of an 8-bit one: round(v * max / 255) without dithering (offset 127).
constexpr uint32_t reduce(uint32_t v, uint32_t max, uint32_t offset) { return (v * max + offset) / 255u; }

TS_INLINE inline uint16_t pack565(uint8_t r, uint8_t g, uint8_t b, uint32_t offset) {
  return uint16_t((reduce(r, 31, offset) << 11) | (reduce(g, 63, offset) << 5) | reduce(b, 31, offset));
}

// pack565 with a dithering offset o by multiply-adds: t / 255 = (t 0x8081) >> 23 for t <= 16313
// (t = v 63 + o is at most 16313), so reduce(v, max, o) = (v (max 0x8081) + o 0x8081) >> 23, one
// multiply-add per channel with o_scaled = o 0x8081 computed once per offset (test_formats checks
// every value and offset against pack565).
inline constexpr uint32_t dither_scale = 0x8081u;
inline constexpr uint32_t dither_k31 = 31u * dither_scale, dither_k63 = 63u * dither_scale;
// k31 and k63: dither_k31 and dither_k63, passed in by loops that keep them in registers (see
// in_register). t < 2^28 for 31 and 2^29 for 63, so t >> 23 fits its field: the fields are joined
// by shifted ORs, ((R << 6 | G) << 5) | B, with no mask (a mask constant is one more register in a
// pixel loop that has none to spare).
TS_INLINE inline uint16_t pack565_dithered(uint32_t r, uint32_t g, uint32_t b, uint32_t o_scaled,
                                                                uint32_t k31 = dither_k31, uint32_t k63 = dither_k63) {
  const uint32_t tr = r * k31 + o_scaled, tg = g * k63 + o_scaled, tb = b * k31 + o_scaled;
  return uint16_t(((tr >> 23) << 6 | (tg >> 23)) << 5 | (tb >> 23));
}

// The scaled offsets bayer_offset(x, y) * dither_scale of pack565_dithered, row (y & 3) by row,
// each row twice (eight entries: a row read from any of its first four entries on, see
// dither_span_offsets).
struct DitherOffsets {
  uint32_t v[32];
};
constexpr DitherOffsets make_dither_offsets() {
  DitherOffsets t{};
  for (int32_t y = 0; y < 4; ++y)
    for (int32_t x = 0; x < 8; ++x) t.v[8 * y + x] = bayer_offset(x, y) * dither_scale;
  return t;
}
inline constexpr DitherOffsets dither_offsets = make_dither_offsets();
TS_INLINE inline uint32_t dither_offset_scaled(int32_t x, int32_t y) {
  return dither_offsets.v[8 * (y & 3) + (x & 3)];
}
// The offsets of a span of row y whose pixel x0 is at address p0, by pixel address: the pixel of
// address p (2 bytes per pixel, any alignment) takes o[(p >> 1) & 3]. floor(p / 2) grows by one a
// pixel, so x & 3 = ((p >> 1) + x0 - (p0 >> 1)) & 3, and the row's entry s + i (s, i < 4) is its
// entry (s + i) & 3: the pixel loop needs no column count.
TS_INLINE inline const uint32_t* dither_span_offsets(int32_t y, int32_t x0, const uint8_t* p0) {
  const uint32_t s = (uint32_t(x0) - uint32_t(reinterpret_cast<uintptr_t>(p0) >> 1)) & 3u;
  const uint32_t* o = dither_offsets.v + 8 * (y & 3) + s;
  __asm__("" : "+r"(o));  // one pointer in a register, not the table's address and an index
  return o;
}
TS_INLINE inline uint32_t dither_index(const uint8_t* p) {
  return uint32_t(reinterpret_cast<uintptr_t>(p) >> 1) & 3u;
}

// v unchanged, but opaque to the optimizer: a constant multiplier kept in a register for a
// multiply-add (GCC expands a multiplication by a constant into shifts and adds: four instructions
// where the Cortex-M4's MLA is one).
TS_INLINE inline uint32_t in_register(uint32_t v) {
  __asm__("" : "+r"(v));
  return v;
}

// pack565 without dithering (offset 127) by multiply-adds: (v 31 + 127) / 255 = (v 249 + 1014) >> 11
// and (v 63 + 127) / 255 = (v 253 + 505) >> 10 for every 8-bit v (test_formats checks all of them),
// and the fields placed by masks: no division and no shift back.
inline uint16_t pack565_nearest(uint32_t r, uint32_t g, uint32_t b) {
  return uint16_t(((r * 249 + 1014) & 0xF800u) | (((g * 253 + 505) >> 5) & 0x07E0u) | ((b * 249 + 1014) >> 11));
}

// The two bytes of an RGB565 pixel in the format's byte order as one halfword of a little-endian
// host (the value that store565_bytes stores): for BE the bytes of w = R 2^11 + G 2^5 + B are
// swapped, so R lands at bit 3, B at bit 8 and G split around them.
template <PixelFormat F>
constexpr uint16_t rgb565_bytes(uint32_t w) {
  return F == PixelFormat::rgb565_be ? uint16_t((w >> 8 | w << 8) & 0xFFFFu) : uint16_t(w);
}

// The R and G fields of every 8-bit value without dithering, reduce(v, 31, 127) << 11 at v and
// reduce(v, 63, 127) << 5 at 256 + v, already in the format's byte order (rgb565_bytes): a pixel is
// three halfword loads and two ORs, with no shift, mask or byte swap. B is R's field moved: in LE
// order the R field shifted right by 11, in BE order shifted left by 5 (R at bit 3, B at bit 8), so
// one table serves both (1 KB of constant data per format; the same values by construction, and
// test_formats checks every one). One table, one base register: a row loop that keeps its G value
// biased by 256 (pack565_bytes_by_table_biased) reads all three fields without an offset per pixel.
struct Rgb565Table {
  uint16_t v[512];
};
template <PixelFormat F>
constexpr Rgb565Table make_rgb565_table() {
  Rgb565Table t{};
  for (uint32_t v = 0; v < 256; ++v) {
    t.v[v] = rgb565_bytes<F>(reduce(v, 31, 127) << 11);
    t.v[256 + v] = rgb565_bytes<F>(reduce(v, 63, 127) << 5);
  }
  return t;
}
template <PixelFormat F>
inline constexpr Rgb565Table rgb565_table = make_rgb565_table<F>();

// pack565_nearest by the table, in the format's byte order (rgb565_bytes), for r and b in [0, 255]
// and g256 = g + 256 (g in [0, 255]).
template <PixelFormat F>
TS_INLINE inline uint16_t pack565_bytes_by_table_biased(uint32_t r, uint32_t g256, uint32_t b,
                                                                            const uint16_t* t = rgb565_table<F>.v) {
  const uint32_t blue = F == PixelFormat::rgb565_be ? uint32_t(t[b]) << 5 : uint32_t(t[b]) >> 11;
  return uint16_t(t[r] | t[g256] | blue);
}

// The same for values r, g, b in [0, 255].
template <PixelFormat F>
TS_INLINE inline uint16_t pack565_bytes_by_table(uint32_t r, uint32_t g, uint32_t b) {
  return pack565_bytes_by_table_biased<F>(r, g + 256, b);
}

// Stores a halfword made by rgb565_bytes or pack565_bytes_by_table: its two bytes in the
// little-endian order of their bits, whatever the host's order (two byte stores where a halfword
// store needs alignment: TS_UNALIGNED_STORES).
TS_INLINE inline void store565_bytes(uint8_t* p, uint16_t h) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
  memcpy(p, &h, 2);  // one halfword store
#else
  p[0] = uint8_t(h & 0xFF);
  p[1] = uint8_t(h >> 8);
#endif
}

// The two bytes of an RGB565 pixel in the format's byte order, as one store where the host is
// little-endian (a halfword store on Cortex-M4; the byte order is that of the format, not the host's).
template <PixelFormat F>
inline void store565(uint8_t* p, uint16_t w) {
  static_assert(F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be, "an RGB565 format");
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
  const uint16_t bytes = F == PixelFormat::rgb565_be ? uint16_t(w >> 8 | w << 8) : w;
  memcpy(p, &bytes, 2);
#else
  const int lo = F == PixelFormat::rgb565_le ? 0 : 1;
  p[lo] = uint8_t(w & 0xFF);
  p[1 - lo] = uint8_t(w >> 8);
#endif
}

// Writes one pixel of 8-bit R, G, B at screen position (x, y) (used for dithering).
template <PixelFormat F>
inline void store_rgb(uint8_t* p, uint8_t r, uint8_t g, uint8_t b, int32_t x, int32_t y, bool dither) {
  if constexpr (F == PixelFormat::l8) {
    p[0] = luma(r, g, b);
  } else if constexpr (F == PixelFormat::rgb888) {
    p[0] = r;
    p[1] = g;
    p[2] = b;
  } else if constexpr (F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be) {
    store565<F>(p, dither ? pack565_dithered(r, g, b, dither_offset_scaled(x, y)) : pack565_nearest(r, g, b));
  } else if constexpr (F == PixelFormat::xrgb8888) {
    p[0] = b;
    p[1] = g;
    p[2] = r;
    p[3] = 0xFF;
  } else {
    p[0] = uint8_t(p[0] + 1);
  }
}

// Writes one grey pixel; grey is replicated to R, G and B.
template <PixelFormat F>
inline void store_grey(uint8_t* p, uint8_t v, int32_t x, int32_t y, bool dither) {
  if constexpr (F == PixelFormat::l8) {
    p[0] = v;
  } else {
    store_rgb<F>(p, v, v, v, x, y, dither);
  }
}

}  // namespace tristream::core::detail
