#include "tristream/render.h"

#include <string.h>

#include "tristream/config.h"
#if TS_USE_SSE2
#include <emmintrin.h>
#endif

#include "tristream/detail/arith.h"
#include "tristream/detail/bytes.h"
#include "tristream/detail/edge.h"
#include "tristream/detail/interpolate.h"
#include "tristream/detail/pixel_writer.h"
#include "tristream/fixed_point.h"

namespace tristream::core {
namespace detail {
namespace {

constexpr size_t workspace_alignment = 8;
constexpr int16_t scratch_empty = INT16_MIN;

// Domain position_fx -> output position_fx, corner to corner, rounded to nearest.
struct Mapping {
  int64_t nx = 1, dx = 1, ny = 1, dy = 1;
  bool identity = true;

  int32_t x(int32_t v) const { return identity ? v : int32_t((v * nx + dx / 2) / dx); }
  int32_t y(int32_t v) const { return identity ? v : int32_t((v * ny + dy / 2) / dy); }
};

struct Resolved {
  int32_t out_w = 0, out_h = 0;
  Rect view;
  int32_t tile_w = 0, tile_h = 0;
  PixelFormat format = PixelFormat::rgb888;
  Mapping map;
};

Status resolve(const Blob& blob, const RenderParams& p, Resolved* r) {
  if (!blob.bytes) return Status::null_argument;
  r->out_w = p.output_width ? p.output_width : blob.width;
  r->out_h = p.output_height ? p.output_height : blob.height;
  if (r->out_w < 2 || r->out_h < 2 || r->out_w > config::max_dimension || r->out_h > config::max_dimension)
    return Status::bad_params;
  r->view = p.viewport;
  if (r->view.empty()) r->view = Rect{0, 0, r->out_w, r->out_h};
  if (r->view.x0 < 0 || r->view.y0 < 0 || r->view.x1 > r->out_w || r->view.y1 > r->out_h) return Status::bad_params;
  r->tile_w = p.tile_width ? p.tile_width : r->view.width();
  r->tile_h = p.tile_height ? p.tile_height : r->view.height();
  if (r->tile_w > r->view.width()) r->tile_w = r->view.width();
  if (r->tile_h > r->view.height()) r->tile_h = r->view.height();
  if (bytes_per_pixel(p.format) == 0) return Status::bad_params;
  if (!(config::pixel_formats >> int(p.format) & 1) || !(config::methods >> int(blob.method) & 1))
    return Status::not_compiled;
  r->format = p.format;
  r->map.identity = r->out_w == blob.width && r->out_h == blob.height;
  r->map.nx = r->out_w - 1;
  r->map.dx = blob.width - 1;
  r->map.ny = r->out_h - 1;
  r->map.dy = blob.height - 1;
  return Status::ok;
}

// A triangle of a layer with its vertices in output position_fx.
struct TriangleView {
  uint16_t v[3];
  uint16_t flags;
  int32_t x[4], y[4];  // x[3], y[3]: 0 (whole vectors for SSE2)
};

// What a shader's begin needs besides the vertices: the edge coefficients (|a|, |b| < 2^20, see
// detail/edge.h), the exact edge values at the reference pixel (xr, yr) (vertex 0 floored), and the
// doubled area.
struct TriangleSetup {
  int32_t a[4], b[4];  // a[3], b[3] unused (whole vectors for SSE2)
  int64_t e_ref[3];
  int32_t xr, yr;
  int64_t area2;
  bool scan_path;  // a triangle of the scan path (small: see SmallEdges)
};

// Whether bilinear setup of scan-path triangles may use ShortRoundingDivider: |2n + d| 2d < 2^64 for
// every numerator n. Such a triangle's box is below 16 pixels, so its extents (and |dx|, |dy| of its
// edges) are below 17 * 2^S, the offsets of its vertices from the reference pixel below 18 * 2^S,
// its doubled area d below (17 * 2^S)^2 (at most its box), and |e_ref| < 2 * 17 * 18 * 2^(2S) =
// 612 * 2^(2S). With values below 2^16 the largest numerator, 2^8 sum v e_ref (dv/dx and dv/dy
// have |A|, |B| < 17 * 2^(2S) instead), is below 2^24 * 3 * 612 * 2^(2S). S = 4: |2n + d| < 2^43.9
// and 2d < 2^17.2.
constexpr bool short_division_fits(int s) {
  const uint64_t d = uint64_t(17 * 17) << (2 * s);
  const uint64_t x = (uint64_t(3 * 612) << (25 + 2 * s)) + d;
  return x < ~uint64_t(0) / (2 * d);
}
// Only where the high multiply is one instruction (a 128-bit type): elsewhere (Cortex-M) it saves
// less than the flash of a second copy of the channel setup costs.
#if defined(__SIZEOF_INT128__)
constexpr bool bilinear_short_division = short_division_fits(config::subpixel_bits);
#else
constexpr bool bilinear_short_division = false;
#endif
static_assert(short_division_fits(4), "the default configuration divides scan-path numerators without correction");

inline void load_triangle(const BlobLayer& layer, uint32_t t, const Mapping& map, TriangleView* tv) {
  const uint8_t* p = layer.triangles + size_t(t) * blob_triangle_size;
  for (int k = 0; k < 3; ++k) {
    tv->v[k] = load_u16(p + 2 * k);
    const uint8_t* pos = layer.positions + 4 * size_t(tv->v[k]);
    tv->x[k] = map.x(load_u16(pos));
    tv->y[k] = map.y(load_u16(pos + 2));
  }
  tv->flags = load_u16(p + 6);
  tv->x[3] = tv->y[3] = 0;
}

// First and last pixel row whose sample points may lie in the triangle.
inline void row_extent(const BlobLayer& layer, uint32_t t, const Mapping& map, int32_t* top, int32_t* bottom) {
  const uint8_t* p = layer.triangles + size_t(t) * blob_triangle_size;
  const int32_t y0 = load_u16(layer.positions + 4 * size_t(load_u16(p)) + 2);
  const int32_t y1 = load_u16(layer.positions + 4 * size_t(load_u16(p + 2)) + 2);
  const int32_t y2 = load_u16(layer.positions + 4 * size_t(load_u16(p + 4)) + 2);
  *top = position_fx::from_raw(map.y(min3(y0, y1, y2))).ceil_to_int();
  *bottom = position_fx::from_raw(map.y(max3(y0, y1, y2))).floor_to_int();
}

#if TS_USE_SSE2
// Lane by lane, the low 32 bits of v * k (SSE2 has no 32-bit lane product: two 32 x 32 -> 64
// products of the even and the odd lanes).
inline __m128i mullo_lanes(__m128i v, uint32_t k) {
  const __m128i kk = _mm_set1_epi32(int32_t(k));
  const __m128i even = _mm_mul_epu32(v, kk), odd = _mm_mul_epu32(_mm_srli_epi64(v, 32), kk);
  return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)), _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
}
#endif

// Pixel writers. A writer receives q24_8 channel values of one covered pixel.
template <PixelFormat F, int Channels, bool YCbCr>
struct DirectWriter {
  uint8_t* base;
  int32_t stride;
  Rect rect;
  bool dither;

  uint8_t* at(int32_t x, int32_t y) const {
    return base + (y - rect.y0) * stride + (x - rect.x0) * bytes_per_pixel(F);
  }
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
  // Pixels x0..x1 of row y from q16_16 values v (rounding offset included) stepped by dv, every
  // one known to round into [0, 255].
  void put_span_in_range(uint8_t* p, int32_t x0, int32_t x1, int32_t y, const uint32_t* v, const uint32_t* dv) const {
    constexpr int s = q16_16::frac_bits;
    constexpr int bpp = bytes_per_pixel(F);
    if constexpr (Channels == 1) {
      uint32_t g = v[0];
      for (int32_t x = x0; x <= x1; ++x, p += bpp, g += dv[0]) store_grey<F>(p, uint8_t(g >> s), x, y, dither);
    } else {
      uint32_t r = v[0], g = v[1], b = v[2];
      for (int32_t x = x0; x <= x1; ++x, p += bpp, r += dv[0], g += dv[1], b += dv[2])
        store_rgb<F>(p, uint8_t(r >> s), uint8_t(g >> s), uint8_t(b >> s), x, y, dither);
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

// Values of vertex v for `channels` channels starting at `first` (q8_8).
inline void vertex_values(const BlobLayer& layer, int per_vertex, int first, int channels, uint16_t v, int32_t* out) {
  const uint8_t* p = layer.values + 2 * (size_t(v) * per_vertex + first);
  for (int c = 0; c < channels; ++c) out[c] = load_u16(p + 2 * c);
}

template <int Channels, typename Writer>
struct BilinearShader {
  const BlobLayer* layer;
  int per_vertex;
  int first_channel;
  Writer writer;
  int bpp;
  BilinearChannel ch[Channels];
  int32_t xr = 0, yr = 0;
#if TS_USE_SSE2
  // RGB to a writer that takes rounded values: the channels' values (rounding offset included),
  // steps per column and per row in the writer's lanes.
  static constexpr bool in_lanes = Channels == 3 && Writer::takes_rounded;
  __m128i lane_ref{}, lane_dx{}, lane_dy{};
#endif

  void begin(const TriangleView& tv, const TriangleSetup& s) {
    xr = s.xr;
    yr = s.yr;
    int32_t vals[3][Channels];
    for (int k = 0; k < 3; ++k) vertex_values(*layer, per_vertex, first_channel, Channels, tv.v[k], vals[k]);
    auto setup = [&](const auto& by_area2) {
      for (int c = 0; c < Channels; ++c) {
        const int32_t v3[3] = {vals[0][c], vals[1][c], vals[2][c]};
        ch[c].setup(s.a, s.b, s.e_ref, by_area2, v3);
      }
    };
    // The scan path's numerators are small enough for the division without correction.
    if (bilinear_short_division && s.scan_path) {
      setup(ShortRoundingDivider(s.area2));
    } else {
      setup(RoundingDivider(s.area2));
    }
#if TS_USE_SSE2
    if constexpr (in_lanes) {
      // (int32(v) >> 8 + 128) >> 8 == int32(v + 2^15) >> 16: the rounding of to_u8 folded in.
      constexpr uint32_t half = 1u << (q16_16::frac_bits - 1);
      lane_ref = Writer::lanes(uint32_t(ch[0].v_ref) + half, uint32_t(ch[1].v_ref) + half, uint32_t(ch[2].v_ref) + half,
                               true);
      lane_dx = Writer::lanes(uint32_t(ch[0].dvdx), uint32_t(ch[1].dvdx), uint32_t(ch[2].dvdx), false);
      lane_dy = Writer::lanes(uint32_t(ch[0].dvdy), uint32_t(ch[1].dvdy), uint32_t(ch[2].dvdy), false);
    }
#endif
  }
  void span(int32_t y, int32_t, int32_t, int32_t x0, int32_t x1) {
#if TS_USE_SSE2
    if constexpr (in_lanes) {
      // BilinearChannel::at in lanes: the same sums modulo 2^32.
      const __m128i v = _mm_add_epi32(lane_ref, _mm_add_epi32(mullo_lanes(lane_dx, uint32_t(x0 - xr)),
                                                              mullo_lanes(lane_dy, uint32_t(y - yr))));
      writer.put_span_lanes(writer.at(x0, y), x0, x1, y, v, lane_dx);
      return;
    }
#endif
    uint32_t v[Channels], dv[Channels];
    for (int c = 0; c < Channels; ++c) {
      v[c] = ch[c].at(x0, y, xr, yr);
      dv[c] = ch[c].step();
    }
    auto* p = writer.at(x0, y);
    if constexpr (Writer::takes_rounded) {
      // (int32(v) >> 8 + 128) >> 8 == int32(v + 2^15) >> 16: the rounding of to_u8 folded into
      // the start value (covered pixels hold values far from the int32 limits).
      for (int c = 0; c < Channels; ++c) v[c] += 1u << (q16_16::frac_bits - 1);
      // Values are linear along the span, so when both ends round into [0, 255] every pixel
      // does: no clamping (the exact values of covered pixels are far from the int32 limits).
      uint32_t out_of_range = 0;
      for (int c = 0; c < Channels; ++c) {
        const int32_t first = int32_t(v[c]) >> q16_16::frac_bits;
        const int32_t last = int32_t(v[c] + dv[c] * uint32_t(x1 - x0)) >> q16_16::frac_bits;
        out_of_range |= uint32_t(first) | uint32_t(last);
      }
      if (out_of_range <= 255) {
        writer.put_span_in_range(p, x0, x1, y, v, dv);
        return;
      }
      for (int32_t x = x0; x <= x1; ++x) {
        int32_t r[Channels];
        for (int c = 0; c < Channels; ++c) {
          r[c] = int32_t(v[c]) >> q16_16::frac_bits;
          v[c] += dv[c];
        }
        writer.put_rounded(p, x, y, r);
        p += bpp;
      }
      return;
    }
    for (int32_t x = x0; x <= x1; ++x) {
      int32_t q8[Channels];
      for (int c = 0; c < Channels; ++c) {
        q8[c] = int32_t(v[c]) >> (q16_16::frac_bits - q24_8::frac_bits);
        v[c] += dv[c];
      }
      writer.put(p, x, y, q8);
      p += bpp;
    }
  }
};

template <int Channels, typename Writer>
struct ZienkiewiczShader {
  const BlobLayer* layer;
  int per_vertex;
  int first_channel;
  Writer writer;
  int bpp;
  ZienkiewiczChannel ch[Channels];
  BarycentricStepper steps;
  int fd_state = 0;  // forward differencing of this triangle: 0 not set up yet, 1 ready, -1 out of budget

  void begin(const TriangleView& tv, const TriangleSetup& s) {
    const int64_t a2 = s.area2;
    const RoundingDivider by_area2(a2);
    steps.setup(s.a, s.b, s.e_ref, by_area2, s.xr, s.yr);
    int32_t dx[3], dy[3];
    const uint8_t* values[3];
    const uint8_t* gradients[3];
    for (int k = 0; k < 3; ++k) {
      const uint8_t* pk = layer->positions + 4 * size_t(tv.v[k]);
      const uint8_t* pn = layer->positions + 4 * size_t(tv.v[(k + 1) % 3]);
      dx[k] = int32_t(load_u16(pn)) - int32_t(load_u16(pk));
      dy[k] = int32_t(load_u16(pn + 2)) - int32_t(load_u16(pk + 2));
      const size_t first = size_t(tv.v[k]) * per_vertex + first_channel;
      values[k] = layer->values + 2 * first;
      gradients[k] = layer->gradients + 8 * first;
    }
    fd_state = a2 >= zienkiewicz_fd_min_area2 ? 0 : -1;
    // Each channel's values and gradients loaded where its setup uses them (no staging arrays of
    // all channels, which kept the compiler spilling registers to the stack).
    for (int c = 0; c < Channels; ++c) {
      const int32_t v3[3] = {load_u16(values[0] + 2 * c), load_u16(values[1] + 2 * c), load_u16(values[2] + 2 * c)};
      const int32_t g6[6] = {load_i32(gradients[0] + 8 * c), load_i32(gradients[0] + 8 * c + 4),
                             load_i32(gradients[1] + 8 * c), load_i32(gradients[1] + 8 * c + 4),
                             load_i32(gradients[2] + 8 * c), load_i32(gradients[2] + 8 * c + 4)};
      ch[c].setup(dx, dy, v3, g6);
    }
  }
  // Forward differencing set up on the first row that uses it; false for a small triangle or one
  // outside the bit budget (then every row is evaluated per pixel).
  __attribute__((noinline)) bool rows_ready_slow() {
    fd_state = 1;
    for (int c = 0; c < Channels; ++c)
      if (!ch[c].setup_rows(int32_t(steps.dadx), int32_t(steps.dbdx))) fd_state = -1;
    return fd_state > 0;
  }
  bool rows_ready() { return fd_state == 0 ? rows_ready_slow() : fd_state > 0; }
  // Row y of the triangle covers [xs, xe]; pixels x0..x1 of it are in the tile. Rows of at least
  // zienkiewicz_fd_min_length pixels (of large enough triangles) are forward-differenced, others
  // evaluated per pixel: the choice depends on the whole row, not on the tile. Out of line (both
  // loops): their code generation then does not depend on the rest of the tile function (inlined,
  // changes elsewhere in it swung its speed by 20%).
  __attribute__((noinline)) void span(int32_t y, int32_t xs, int32_t xe, int32_t x0, int32_t x1) {
    uint32_t a, b;
    if (xe - xs + 1 >= zienkiewicz_fd_min_length && rows_ready()) {
      steps.at(xs, y, &a, &b);
      forward_differenced(y, xs, x0, x1, a, b);
      return;
    }
    // The weights at x0 directly: the same sums modulo 2^32 as at xs plus (x0 - xs) steps.
    steps.at(x0, y, &a, &b);
    constexpr int down = q2_30::frac_bits - q17_15::frac_bits;
    auto* p = writer.at(x0, y);
    for (int32_t x = x0; x <= x1; ++x) {
      const int64_t a15 = int32_t(a) >> down, b15 = int32_t(b) >> down;
      if constexpr (Writer::takes_rounded) {
        // Rounded and clamped in 64 bits (as to_u8 of the int32-clamped value); the writer's
        // clamp then folds away, and values are rarely out of range.
        int32_t r[Channels];
        for (int c = 0; c < Channels; ++c) {
          int64_t v = (ch[c].eval_wide(a15, b15) + (1 << (q24_8::frac_bits - 1))) >> q24_8::frac_bits;
          if (uint64_t(v) > 255) v = v < 0 ? 0 : 255;
          r[c] = int32_t(v);
        }
        writer.put_rounded(p, x, y, r);
      } else {
        int32_t q8[Channels];
        for (int c = 0; c < Channels; ++c) q8[c] = ch[c].eval(a15, b15);
        writer.put(p, x, y, q8);
      }
      p += bpp;
      a += steps.dadx;
      b += steps.dbdx;
    }
  }
  // Pixels x0..x1 of row y by forward differencing from the weights a, b at xs.
  __attribute__((noinline)) void forward_differenced(int32_t y, int32_t xs, int32_t x0, int32_t x1, uint32_t a,
                                                     uint32_t b) {
    constexpr int vf = ZienkiewiczChannel::value_frac_bits;
    auto* p = writer.at(x0, y);
    const int step = bpp;  // a local: the pixel stores could alias the member
#if TS_USE_SSE2
    if constexpr (Writer::takes_rounded && Channels == 3) {
      // The three channels' values and differences in 64-bit lanes (channels 0, 1 in one vector,
      // 2 in another): six additions a pixel, the rounded values are the high words.
      const int32_t last = x1 - xs;
      zienkiewicz_row_chunks<3>(ch, a, b, steps.dadx, steps.dbdx, x0 - xs, last, uint64_t(1) << (vf - 1),
                                [&](int32_t n, int32_t end, const CubicSteps* s) {
                                  auto pair = [](uint64_t c0, uint64_t c1) {
                                    return _mm_set_epi64x(int64_t(c1), int64_t(c0));
                                  };
                                  __m128i v01 = pair(s[0].v, s[1].v), v2 = pair(s[2].v, 0);
                                  __m128i d01 = pair(s[0].d1, s[1].d1), d2 = pair(s[2].d1, 0);
                                  __m128i e01 = pair(s[0].d2, s[1].d2), e2 = pair(s[2].d2, 0);
                                  const __m128i f01 = pair(s[0].d3, s[1].d3), f2 = pair(s[2].d3, 0);
                                  for (; n <= end; ++n) {
                                    const __m128i q = _mm_unpacklo_epi64(_mm_shuffle_epi32(v01, _MM_SHUFFLE(3, 1, 3, 1)),
                                                                         _mm_shuffle_epi32(v2, _MM_SHUFFLE(1, 1, 1, 1)));
                                    writer.put_lanes(p, Writer::ordered(q), xs + n, y, n != last);
                                    p += step;
                                    v01 = _mm_add_epi64(v01, d01), v2 = _mm_add_epi64(v2, d2);
                                    d01 = _mm_add_epi64(d01, e01), d2 = _mm_add_epi64(d2, e2);
                                    e01 = _mm_add_epi64(e01, f01), e2 = _mm_add_epi64(e2, f2);
                                  }
                                });
      return;
    }
#endif
    if constexpr (Writer::takes_rounded) {
      // Rounding to nearest folded into the values (exact: the differences are unchanged).
      zienkiewicz_row<Channels>(ch, a, b, steps.dadx, steps.dbdx, x0 - xs, x1 - xs, uint64_t(1) << (vf - 1),
                                [&](int32_t n, const CubicSteps* s) {
                                  int32_t r[Channels];
                                  for (int c = 0; c < Channels; ++c) {
                                    int32_t v = int32_t(int64_t(s[c].v) >> vf);
                                    // Clamped here, rarely needed: the writer's clamp then folds away.
                                    if (uint32_t(v) > 255) v = v < 0 ? 0 : 255;
                                    r[c] = v;
                                  }
                                  writer.put_rounded(p, xs + n, y, r);
                                  p += step;
                                });
    } else {
      zienkiewicz_row<Channels>(ch, a, b, steps.dadx, steps.dbdx, x0 - xs, x1 - xs, 0,
                                [&](int32_t n, const CubicSteps* s) {
                                  int32_t q8[Channels];
                                  for (int c = 0; c < Channels; ++c) {
                                    const int64_t v = int64_t(s[c].v) >> (vf - q24_8::frac_bits);
                                    q8[c] = int32_t(v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : v));
                                  }
                                  writer.put(p, xs + n, y, q8);
                                  p += step;
                                });
    }
  }
};

struct Corner {
  int32_t x, y;
  bool owned;
};

// Rasterizes one triangle inside `clip`, calling shader.begin once before the first span.
// Small triangles: the rows and columns of their pixel box (at most this many) are scanned
// with the three edge functions stepped in int32, instead of the span steppers and their
// divisions. Both paths test the same exact predicate, so they cover the same pixels.
// With SSE2 a row of a 16-column box costs about as much as the span steppers' row, without their
// setup; the column scan of other targets pays per column.
constexpr int32_t scan_max_extent = TS_USE_SSE2 ? 16 : 12;
static_assert(scan_max_extent <= 62, "the scan path's int32 edge values need boxes below 64 pixels");

// Edge values on the pixel box of a triangle whose box is below 64 x 64 pixels: for a pixel x of
// the box, |x 2^S - Px| < 64 * 2^S and |dy| < 64 * 2^S, so |E| < 2 * (64 * 2^S)^2 = 2^21 for
// S = 4 (and below 2^31 for every S up to 8), plus the bias; int32 suffices.
static_assert(2 * (int64_t(64) << config::subpixel_bits) * (int64_t(64) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path edge values must fit int32");

// Covered columns of a box row as a 16-bit mask (bit i: column left + i), from the three edge
// values at the row's first column and their steps per column (a) and per row (b). With SSE2
// (TS_USE_SSE2, x86-64 hosts) four columns at a time and without branches, whose mispredictions
// cost more than the rest of a small triangle's rows; elsewhere column by column, stopping at the
// first uncovered column after the covered ones (a row's covered columns are contiguous).
#if TS_USE_SSE2
// Whether the x coefficient A = -dy 2^S of a scan-path edge fits int16 (|dy| < 18 * 2^S, see
// SmallEdges).
constexpr bool small_a_fits_int16 = (int32_t(18) << (2 * config::subpixel_bits)) <= 32768;

// Groups: vectors of four columns per edge, as many as the box needs (at most 4 for boxes below 16
// columns), so the whole state stays in registers.
template <int Groups>
class RowMasks {
 public:
  // From the edges in lanes 0..2 of row, a and b.
  __attribute__((always_inline)) RowMasks(__m128i row, __m128i a, __m128i b) {
    init<0>(row, a, b);
    init<1>(row, a, b);
    init<2>(row, a, b);
  }
  __attribute__((always_inline)) uint32_t covered() const {
    __m128i any_negative[4];
    for (int j = 0; j < Groups; ++j) any_negative[j] = _mm_or_si128(_mm_or_si128(e_[0][j], e_[1][j]), e_[2][j]);
    // Columns past the groups: negative (not covered).
    for (int j = Groups; j < 4; ++j) any_negative[j] = _mm_set1_epi32(-1);
    // Saturating packs keep each lane's sign: 16 signs in 16 bytes, one bit each by movemask.
    const __m128i lo = _mm_packs_epi32(any_negative[0], any_negative[1]);
    const __m128i hi = _mm_packs_epi32(any_negative[2], any_negative[3]);
    return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(lo, hi))) & 0xFFFFu;
  }
  __attribute__((always_inline)) void next_row() {
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < Groups; ++j) e_[k][j] = _mm_add_epi32(e_[k][j], b_[k]);
  }

 private:
  template <int K>
  __attribute__((always_inline)) void init(__m128i row, __m128i a, __m128i b) {
    const __m128i ak = _mm_shuffle_epi32(a, K * 0x55);
    const __m128i four_a = _mm_slli_epi32(ak, 2);
    // Lanes 0..3: row + (0, 1, 2, 3) a (SSE2 has no 32-bit lane product).
    __m128i ramp;
    if constexpr (small_a_fits_int16) {
      // One int16 multiply-add: a's low half (a itself) times 0..3, its high half times 0.
      ramp = _mm_madd_epi16(ak, _mm_setr_epi32(0, 1, 2, 3));
    } else {
      ramp = _mm_and_si128(ak, _mm_set_epi32(-1, -1, -1, 0));
      ramp = _mm_add_epi32(ramp, _mm_and_si128(ak, _mm_set_epi32(-1, -1, 0, 0)));
      ramp = _mm_add_epi32(ramp, _mm_and_si128(ak, _mm_set_epi32(-1, 0, 0, 0)));
    }
    __m128i e = _mm_add_epi32(_mm_shuffle_epi32(row, K * 0x55), ramp);
    for (int j = 0; j < Groups; ++j) {
      e_[K][j] = e;
      e = _mm_add_epi32(e, four_a);
    }
    b_[K] = _mm_shuffle_epi32(b, K * 0x55);
  }

  __m128i e_[3][Groups];
  __m128i b_[3];
};
#else
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
#endif

// The edges of a scan-path triangle (edge k from vertex k to vertex k + 1) in int32, with its doubled
// area. Its vertices span fewer than scan_max_extent + 2 pixels each way, so every coordinate
// difference, and the offset of every vertex from a pixel of the box or from vertex 0 floored, is
// below 19 * 2^S: int16 (S <= 8), and the area is below 2 * (19 * 2^S)^2. Edge values
// E_k(x, y) = -dy_k (x 2^S - x_k) + dx_k (y 2^S - y_k): the same integer as A x + B y + C of
// detail/edge.h.
static_assert((int32_t(19) << config::subpixel_bits) < 32768, "scan-path differences must fit int16");
static_assert(2 * (int64_t(19) << config::subpixel_bits) * (int64_t(19) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path areas must fit int32");
struct SmallEdges {
#if TS_USE_SSE2
  // Lane k: the int16 pair (-dy_k, dx_k) (low half, high half); A_k; B_k; E_k - bias_k at the box's
  // first pixel.
  __m128i pairs, a, b, row;
#else
  int32_t dx[3], dy[3];
  int32_t a[3], b[3], row[3];
#endif
  int32_t area2;
};

#if TS_USE_SSE2
// Lanes 0..2 (int32, each below 2^15 in magnitude) of lo and hi as int16 pairs (lo low, hi high).
inline __m128i int16_pairs(__m128i lo, __m128i hi) {
  return _mm_or_si128(_mm_and_si128(lo, _mm_set1_epi32(0xFFFF)), _mm_slli_epi32(hi, 16));
}
#endif

// The edges of a scan-path triangle, for its rows from (left, y0).
inline void small_edges(const TriangleView& tv, int32_t area2, int32_t left, int32_t y0, SmallEdges* e) {
  constexpr int S = config::subpixel_bits;
  e->area2 = area2;
#if TS_USE_SSE2
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i dx = _mm_sub_epi32(_mm_shuffle_epi32(x, _MM_SHUFFLE(3, 0, 2, 1)), x);
  const __m128i dy = _mm_sub_epi32(_mm_shuffle_epi32(y, _MM_SHUFFLE(3, 0, 2, 1)), y);
  const __m128i zero = _mm_setzero_si128();
  const __m128i neg_dy = _mm_sub_epi32(zero, dy);
  e->pairs = int16_pairs(neg_dy, dx);
  e->a = _mm_slli_epi32(neg_dy, S);
  e->b = _mm_slli_epi32(dx, S);
  // The tie rule of make_edge: inclusive when on the boundary, or A < 0, or A == 0 and B < 0.
  const __m128i bits = _mm_setr_epi32(boundary_edge0, boundary_edge0 << 1, boundary_edge0 << 2, 0);
  const __m128i boundary = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(tv.flags), bits), bits);
  const __m128i inclusive = _mm_or_si128(
      _mm_or_si128(_mm_cmpgt_epi32(dy, zero), _mm_and_si128(_mm_cmpeq_epi32(dy, zero), _mm_cmpgt_epi32(zero, dx))),
      boundary);
  const __m128i offsets = int16_pairs(_mm_sub_epi32(_mm_set1_epi32(left * (1 << S)), x),
                                      _mm_sub_epi32(_mm_set1_epi32(y0 * (1 << S)), y));
  // E - bias = E - 1 - (inclusive ? -1 : 0) = E + ~inclusive.
  e->row = _mm_add_epi32(_mm_madd_epi16(e->pairs, offsets), _mm_xor_si128(inclusive, _mm_set1_epi32(-1)));
#else
  for (int k = 0; k < 3; ++k) {
    const int n = k == 2 ? 0 : k + 1;
    e->dx[k] = tv.x[n] - tv.x[k];
    e->dy[k] = tv.y[n] - tv.y[k];
    e->a[k] = -e->dy[k] * (1 << S);
    e->b[k] = e->dx[k] * (1 << S);
    // The tie rule of make_edge: inclusive when on the boundary, or A < 0, or A == 0 and B < 0.
    const bool inclusive =
        ((tv.flags & (boundary_edge0 << k)) != 0) | (e->dy[k] > 0) | ((e->dy[k] == 0) & (e->dx[k] < 0));
    e->row[k] = -e->dy[k] * (left * (1 << S) - tv.x[k]) + e->dx[k] * (y0 * (1 << S) - tv.y[k]) - (inclusive ? 0 : 1);
  }
#endif
}

// The setup of a scan-path triangle for the shader (on its first covered row in the clip).
inline void small_setup(const TriangleView& tv, const SmallEdges& e, TriangleSetup* s) {
  constexpr int S = config::subpixel_bits;
  const int32_t xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  const int32_t yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  s->xr = xr;
  s->yr = yr;
  s->area2 = e.area2;
  s->scan_path = true;
#if TS_USE_SSE2
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i ref = _mm_madd_epi16(e.pairs, int16_pairs(_mm_sub_epi32(_mm_set1_epi32(xr * (1 << S)), x),
                                                          _mm_sub_epi32(_mm_set1_epi32(yr * (1 << S)), y)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->a), e.a);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->b), e.b);
  const __m128i sign = _mm_srai_epi32(ref, 31);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->e_ref), _mm_unpacklo_epi32(ref, sign));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(s->e_ref + 2), _mm_unpackhi_epi32(ref, sign));
#else
  for (int k = 0; k < 3; ++k) {
    s->a[k] = e.a[k];
    s->b[k] = e.b[k];
    s->e_ref[k] = -e.dy[k] * (xr * (1 << S) - tv.x[k]) + e.dx[k] * (yr * (1 << S) - tv.y[k]);
  }
#endif
}

template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader);

// Rows y0..y1 (already clipped) of a triangle whose pixel box has columns left..right: each row
// is scanned over the whole box, so xs is the row's first covered pixel even when the clip
// (columns cx0..cx1) cuts the span.
template <typename Shader>
void scan_small(const TriangleView& tv, int32_t area2, int32_t left, int32_t right, int32_t y0, int32_t y1,
                int32_t cx0, int32_t cx1, Shader& shader) {
  if (right < left) return;  // no pixel column between the vertices
  SmallEdges e;
  small_edges(tv, area2, left, y0, &e);
  const uint32_t box = (2u << (right - left)) - 1;  // covered columns at most; right - left < 16
  static_assert(scan_max_extent <= 16, "scan rows are at most four groups of four columns");
#if TS_USE_SSE2
  switch ((right - left) / 4) {
    case 0: return scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    case 1: return scan_rows<2>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    case 2: return scan_rows<3>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    default: return scan_rows<4>(tv, e, left, box, y0, y1, cx0, cx1, shader);
  }
#else
  scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);  // one copy: Groups unused
#endif
}

// The rows of scan_small with masks of Groups * 4 columns (the box's width at most).
template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader) {
  RowMasks<Groups> masks(e.row, e.a, e.b);
  bool started = false;
  for (int32_t y = y0; y <= y1; ++y, masks.next_row()) {
    const uint32_t mask = masks.covered() & box;
    if (!mask) continue;
    const int32_t xs = left + __builtin_ctz(mask);
    const int32_t x = left + 32 - __builtin_clz(mask);  // one past the last covered column
    const int32_t cs = xs > cx0 ? xs : cx0;
    const int32_t ce = x - 1 < cx1 ? x - 1 : cx1;
    if (cs > ce) continue;
    if (!started) {
      TriangleSetup s;
      small_setup(tv, e, &s);
      shader.begin(tv, s);
      started = true;
    }
    shader.span(y, xs, x - 1, cs, ce);
  }
}

// The setup of a span-path triangle for the shader, from its edges.
inline void edge_setup(const TriangleView& tv, const Edge* e, int64_t area2, TriangleSetup* s) {
  s->xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  s->yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  for (int k = 0; k < 3; ++k) {
    s->a[k] = int32_t(e[k].a);
    s->b[k] = int32_t(e[k].b);
    s->e_ref[k] = e[k].exact_at(s->xr, s->yr);
  }
  s->area2 = area2;
  s->scan_path = false;
}

// Returns whether the triangle is done with the band: no pixel column right of the clip, no
// pixel row below it.
template <typename Shader>
bool rasterize(const TriangleView& tv, const Rect& clip, Shader& shader) {
  const int32_t top = position_fx::from_raw(min3(tv.y[0], tv.y[1], tv.y[2])).ceil_to_int();
  const int32_t bottom = position_fx::from_raw(max3(tv.y[0], tv.y[1], tv.y[2])).floor_to_int();
  const int32_t left = position_fx::from_raw(min3(tv.x[0], tv.x[1], tv.x[2])).ceil_to_int();
  const int32_t right = position_fx::from_raw(max3(tv.x[0], tv.x[1], tv.x[2])).floor_to_int();
  const bool done = (right < clip.x1) & (bottom < clip.y1);
  int32_t y0 = top, y1 = bottom;
  if (y0 < clip.y0) y0 = clip.y0;
  if (y1 > clip.y1 - 1) y1 = clip.y1 - 1;
  if (y0 > y1) return done;
  if (right < clip.x0 || left >= clip.x1) return done;
  // The scan path: small boxes without explicit corners, in int32.
  constexpr uint16_t any_corner = corner_explicit0 | corner_explicit0 << 1 | corner_explicit0 << 2;
  if (!(tv.flags & any_corner) && right - left < scan_max_extent && bottom - top < scan_max_extent) {
    const int32_t area2 = (tv.x[1] - tv.x[0]) * (tv.y[2] - tv.y[0]) - (tv.y[1] - tv.y[0]) * (tv.x[2] - tv.x[0]);
    if (area2 <= 0) return done;  // collapsed by down-scaling
    scan_small(tv, area2, left, right, y0, y1, clip.x0, clip.x1 - 1, shader);
    return done;
  }
  const int64_t area2 = (int64_t(tv.x[1]) - tv.x[0]) * (int64_t(tv.y[2]) - tv.y[0]) -
                        (int64_t(tv.y[1]) - tv.y[0]) * (int64_t(tv.x[2]) - tv.x[0]);
  if (area2 <= 0) return done;  // collapsed by down-scaling
  Edge edges[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    edges[k] = make_edge(tv.x[k], tv.y[k], tv.x[n], tv.y[n], (tv.flags & (boundary_edge0 << k)) != 0);
  }
  // Rows [r0, r1] pass the horizontal edges; an owned corner on an excluded row adds that row.
  int32_t r0 = y0, r1 = y1;
  restrict_rows(edges, &r0, &r1);
  Corner corners[3];
  int corner_count = 0;
  int32_t first = r0, last = r1;
  for (int k = 0; k < 3; ++k) {
    if (!(tv.flags & (corner_explicit0 << k))) continue;
    const position_fx cx = position_fx::from_raw(tv.x[k]), cy = position_fx::from_raw(tv.y[k]);
    if (!cx.is_integer() || !cy.is_integer()) continue;
    const Corner c{cx.floor_to_int(), cy.floor_to_int(), (tv.flags & (corner_owned0 << k)) != 0};
    corners[corner_count++] = c;
    if (c.owned && c.y >= y0 && c.y <= y1) {
      first = c.y < first ? c.y : first;
      last = c.y > last ? c.y : last;
    }
  }
  if (first > last) return done;
  SpanStepper spans;
  spans.init(edges, first);
  bool started = false;
  for (int32_t y = first; y <= last; ++y, spans.next_row()) {
    int32_t xs = 1, xe = 0;
    if (y >= r0 && y <= r1) spans.span(&xs, &xe);
    for (int k = 0; k < corner_count; ++k) {
      const Corner& c = corners[k];
      if (c.y != y) continue;
      if (c.owned) {
        if (xs > xe) {
          xs = xe = c.x;
        } else {
          xs = c.x < xs ? c.x : xs;
          xe = c.x > xe ? c.x : xe;
        }
      } else if (xs == c.x) {
        ++xs;
      } else if (xe == c.x) {
        --xe;
      }
    }
    if (xs > xe) continue;
    const int32_t cs = xs > clip.x0 ? xs : clip.x0;
    const int32_t ce = xe < clip.x1 - 1 ? xe : clip.x1 - 1;
    if (cs > ce) continue;
    if (!started) {
      TriangleSetup s;
      edge_setup(tv, edges, area2, &s);
      shader.begin(tv, s);
      started = true;
    }
    shader.span(y, xs, xe, cs, ce);
  }
  return done;
}

// The active triangles of one layer: a bitmap over the window [base, cursor) of the triangle
// stream (sorted by top row), in caller memory, addressed as a ring (triangle t at bit
// t mod capacity, unique while the window is no longer than the capacity). base only passes
// triangles that ended above the current band, so the window is the stretch from the oldest
// live triangle to the newest started one: at most the layer's triangle count, and one bit per
// triangle instead of an index per live triangle.
struct ActiveSet {
  const BlobLayer* layer = nullptr;
  uint32_t* words = nullptr;
  uint32_t capacity = 0;  // bits, a multiple of 32
  uint32_t base = 0;
  uint32_t cursor = 0;
  int32_t view_x1 = 0;  // the viewport's right end: tiles ending there are the last of their band

  // Bit positions: pos(t) = t mod capacity, stepped with next() to avoid a division per test.
  uint32_t pos(uint32_t t) const { return t % capacity; }
  uint32_t next(uint32_t p) const { return p + 1 == capacity ? 0 : p + 1; }
  bool test_at(uint32_t p) const { return (words[p / 32] >> (p % 32)) & 1u; }
  void set_at(uint32_t p) { words[p / 32] |= 1u << (p % 32); }

  // Calls f(t, w, span, p) for the live triangles of the window a word at a time, in order: bit i
  // of w (nonzero) is triangle t + i, triangles t .. t + span - 1 are in the window (span <= 32),
  // and p is the bit position of triangle t (bit p % 32 of words[p / 32]).
  template <typename F>
  void for_each_live_word(F&& f) const {
    uint32_t t = base, p = base < cursor ? pos(base) : 0;
    while (t < cursor) {
      uint32_t w = words[p / 32] >> (p % 32);
      uint32_t span = 32 - p % 32;
      if (span > cursor - t) {
        span = cursor - t;
        w &= (1u << span) - 1;  // span < 32 here
      }
      if (w) f(t, w, span, p);
      t += span;
      p += span;
      if (p == capacity) p = 0;
    }
  }

  void reset() {
    for (uint32_t i = 0; i < capacity / 32; ++i) words[i] = 0;
    base = cursor = 0;
  }
  // Drops triangles ending above row y0, adds those starting at or before row y1 (inclusive).
  // False when the window would exceed the capacity.
  bool advance(const Mapping& map, int32_t y0, int32_t y1) {
    if (base < cursor) {
      // A word of the bitmap at a time: the ended triangles' bits collected without branches on
      // the data, then cleared at once (no division per triangle for its bit position).
      for_each_live_word([&](uint32_t t, uint32_t w, uint32_t, uint32_t p) {
        uint32_t ended = 0;
        for (; w; w &= w - 1) {
          const uint32_t i = uint32_t(__builtin_ctz(w));
          int32_t top, bottom;
          row_extent(*layer, t + i, map, &top, &bottom);
          ended |= uint32_t(bottom < y0) << i;
        }
        words[p / 32] &= ~(ended << (p % 32));
      });
      uint32_t p = pos(base);
      while (base < cursor && !test_at(p)) ++base, p = next(p);
    }
    for (uint32_t p = cursor < layer->triangle_count ? pos(cursor) : 0; cursor < layer->triangle_count; p = next(p)) {
      int32_t top, bottom;
      row_extent(*layer, cursor, map, &top, &bottom);
      if (top > y1) break;
      const bool live = bottom >= y0 && top <= bottom;
      if (live) {
        if (cursor - base >= capacity) return false;
        set_at(p);
      } else if (base == cursor) {
        ++base;
      }
      ++cursor;
    }
    return true;
  }
};

// Longest window of a layer's active set over the bands of the viewport (see ActiveSet).
uint32_t max_window(const BlobLayer& layer, const Resolved& r) {
  uint32_t best = 0, base = 0, cursor = 0;
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t y1 = (by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1) - 1;
    int32_t top, bottom;
    while (cursor < layer.triangle_count) {
      row_extent(layer, cursor, r.map, &top, &bottom);
      if (top > y1) break;
      ++cursor;
    }
    while (base < cursor) {
      row_extent(layer, base, r.map, &top, &bottom);
      if (bottom >= by && top <= bottom) break;
      ++base;
    }
    best = cursor - base > best ? cursor - base : best;
  }
  return best;
}

// Bytes of a bitmap of `bits` bits in whole 32-bit words.
inline size_t bitmap_bytes(uint32_t bits) { return size_t((bits + 31) / 32) * 4; }

bool layered(const Blob& blob) { return blob.layer_count > 1; }

size_t scratch_bytes(const Blob& blob, const Resolved& r, PixelFormat f) {
  if (!layered(blob) || f == PixelFormat::coverage8) return 0;
  // Rounded up to the alignment so that the bitmaps after it are word aligned.
  const size_t bytes = size_t(r.tile_w) * r.tile_h * 3 * sizeof(int16_t);
  return (bytes + workspace_alignment - 1) / workspace_alignment * workspace_alignment;
}

// The columns [rect.x0, rect.x1) of a tile as thresholds on raw (domain, unmapped) vertex x:
// a triangle's columns [ceil(min x'), floor(max x')] (x' mapped) miss the tile exactly when
// max x < lo or min x >= hi, because the mapping is monotone: floor(m / 2^S) < x0 iff m < x0 2^S,
// and ceil(m / 2^S) >= x1 iff m >= (x1 - 1) 2^S + 1. One cheap test per live triangle and tile.
struct ColumnWindow {
  int32_t lo, hi;

  // Smallest raw v in [0, 65536] with map.x(v) >= target (65536 when there is none).
  static int32_t first_at_least(const Mapping& map, int32_t target) {
    if (map.identity) return target < 0 ? 0 : (target > 65536 ? 65536 : target);
    int32_t lo = 0, hi = 65536;
    while (lo < hi) {
      const int32_t mid = lo + (hi - lo) / 2;
      if (map.x(mid) >= target) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    return lo;
  }
  ColumnWindow(const Mapping& map, const Rect& rect)
      : lo(first_at_least(map, rect.x0 * (1 << config::subpixel_bits))),
        hi(first_at_least(map, (rect.x1 - 1) * (1 << config::subpixel_bits) + 1)) {}

  // The triangles t + i (bit i of live) whose columns meet the tile, as bits. A loop without
  // branches on the data and without calls (so its pointers and bounds stay in registers): the
  // test is one sign, not (max < lo) | (min >= hi), which compilers turn into two branches, the
  // first taken for a share of the triangles that grows along the band (unpredictable in the
  // middle tiles).
  uint32_t meeting(const BlobLayer& layer, uint32_t t, uint32_t live, uint32_t span) const {
    const uint8_t* const triangles = layer.triangles + size_t(t) * blob_triangle_size;
    const uint8_t* const positions = layer.positions;
    const int32_t low = lo, high = hi - 1;
    uint32_t hits = 0;
#if TS_USE_SSE2
    if (span == 32) {
      // Bytes of the word with two live triangles or more: all eight triangles in 16-bit lanes
      // (they are in the window, so their records are valid), the other bytes one by one below.
      uint32_t rest = 0;
      for (int g = 0; g < 4; ++g) {
        const uint32_t byte = (live >> (8 * g)) & 0xFFu;
        if (byte & (byte - 1)) {
          hits |= (meeting8(triangles + size_t(8 * g) * blob_triangle_size, positions) & byte) << (8 * g);
        } else {
          rest |= byte << (8 * g);
        }
      }
      live = rest;
    }
#else
    (void)span;
#endif
    for (; live; live &= live - 1) {
      const uint32_t i = uint32_t(__builtin_ctz(live));
      const uint8_t* p = triangles + size_t(i) * blob_triangle_size;
      const int32_t x0 = load_u16(positions + 4 * size_t(load_u16(p)));
      const int32_t x1 = load_u16(positions + 4 * size_t(load_u16(p + 2)));
      const int32_t x2 = load_u16(positions + 4 * size_t(load_u16(p + 4)));
      const int32_t outside = (max3(x0, x1, x2) - low) | (high - min3(x0, x1, x2));  // < 0: misses
      hits |= uint32_t(outside >= 0) << i;
    }
    return hits;
  }
#if TS_USE_SSE2
  // Bit j: triangle j of the eight records at p meets the columns. Coordinates (16 bits) and
  // bounds are compared as signed 16-bit lanes after flipping the top bit (the order of the
  // unsigned values); the bounds are clamped to 16 bits only in the direction that keeps more
  // triangles (a triangle kept in error is clipped away exactly by rasterize, one missed would be
  // wrong): min(lo, 65535) for max < lo, max(hi - 1, 0) for min > hi - 1.
  uint32_t meeting8(const uint8_t* p, const uint8_t* positions) const {
    // As the 16-bit lane it goes to (the same bits).
    auto x = [&](int j, int k) {
      return int16_t(load_u16(positions + 4 * size_t(load_u16(p + j * blob_triangle_size + 2 * k))));
    };
    const __m128i top_bit = _mm_set1_epi16(int16_t(0x8000));
    __m128i v[3];
    for (int k = 0; k < 3; ++k) {
      __m128i w = _mm_cvtsi32_si128(x(0, k));
      w = _mm_insert_epi16(w, x(1, k), 1);
      w = _mm_insert_epi16(w, x(2, k), 2);
      w = _mm_insert_epi16(w, x(3, k), 3);
      w = _mm_insert_epi16(w, x(4, k), 4);
      w = _mm_insert_epi16(w, x(5, k), 5);
      w = _mm_insert_epi16(w, x(6, k), 6);
      w = _mm_insert_epi16(w, x(7, k), 7);
      v[k] = _mm_xor_si128(w, top_bit);
    }
    const __m128i mn = _mm_min_epi16(_mm_min_epi16(v[0], v[1]), v[2]);
    const __m128i mx = _mm_max_epi16(_mm_max_epi16(v[0], v[1]), v[2]);
    const int32_t low = lo < 65535 ? lo : 65535, high = hi - 1 > 0 ? hi - 1 : 0;
    const __m128i outside = _mm_or_si128(_mm_cmpgt_epi16(_mm_set1_epi16(int16_t(low ^ 0x8000)), mx),
                                         _mm_cmpgt_epi16(mn, _mm_set1_epi16(int16_t(high ^ 0x8000))));
    return ~uint32_t(_mm_movemask_epi8(_mm_packs_epi16(outside, outside))) & 0xFFu;
  }
#endif
};

// Draws the live triangles of a layer that meet the tile `rect`. A triangle whose last pixel column
// is in this tile or left of it (nothing for the band's later tiles) and whose last row is in this
// band (the band advance would drop it) leaves the active set now: the later tiles of the band then
// skip it without the column test. The pixels are the same (those tiles would have culled it).
template <typename Shader>
void draw_layer(ActiveSet& set, const Mapping& map, const Rect& rect, Shader& shader) {
  const ColumnWindow columns(map, rect);
  const bool later_tiles = rect.x1 < set.view_x1;
  set.for_each_live_word([&](uint32_t t, uint32_t live, uint32_t span, uint32_t p) {
    uint32_t done = 0;
    for (uint32_t hits = columns.meeting(*set.layer, t, live, span); hits; hits &= hits - 1) {
      const uint32_t i = uint32_t(__builtin_ctz(hits));
      TriangleView tv;
      load_triangle(*set.layer, t + i, map, &tv);
      done |= uint32_t(rasterize(tv, rect, shader)) << i;
    }
    if (later_tiles) set.words[p / 32] &= ~(done << (p % 32));
  });
}

template <int Channels, typename Writer>
void draw_with(const Blob& blob, int layer_index, int first_channel, ActiveSet& list, const Mapping& map,
               const Rect& rect, const Writer& writer, int step) {
  const BlobLayer* layer = &blob.layers[layer_index];
  // Only the methods compiled in (resolve rejects the others before any tile is drawn).
  if (blob.method == Method::bilinear) {
    if constexpr (config::methods & 1) {
      BilinearShader<Channels, Writer> s{layer, blob.values_per_vertex, first_channel, writer, step, {}, 0, 0};
      draw_layer(list, map, rect, s);
    }
  } else {
    if constexpr (config::methods & 2) {
      ZienkiewiczShader<Channels, Writer> s{layer, blob.values_per_vertex, first_channel, writer, step, {}, {}, 0};
      draw_layer(list, map, rect, s);
    }
  }
}

template <PixelFormat F>
void fill_background(uint8_t* base, int32_t stride, const Rect& rect, const RenderParams& p, bool grey) {
  // Without dithering every row is the same: write the first, copy it to the others.
  const bool same_rows = !(p.dither && (F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be));
  for (int32_t y = rect.y0; y < rect.y1; ++y) {
    uint8_t* row = base + (y - rect.y0) * stride;
    if (same_rows && y > rect.y0) {
      memcpy(row, base, size_t(rect.width()) * bytes_per_pixel(F));
      continue;
    }
    for (int32_t x = rect.x0; x < rect.x1; ++x) {
      uint8_t* px = row + (x - rect.x0) * bytes_per_pixel(F);
      if constexpr (F == PixelFormat::coverage8) {
        px[0] = 0;
      } else if (grey) {
        store_grey<F>(px, p.background[0], x, y, p.dither);
      } else {
        store_rgb<F>(px, p.background[0], p.background[1], p.background[2], x, y, p.dither);
      }
    }
  }
}

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

template <PixelFormat F>
void render_tile(const Blob& blob, const RenderParams& p, const Mapping& map, ActiveSet* sets, const Rect& rect,
                 uint8_t* base, int32_t stride, int16_t* scratch) {
  const bool grey = blob.space == ColorSpace::grey;
  fill_background<F>(base, stride, rect, p, grey);
  constexpr int bpp = bytes_per_pixel(F);
  if (F == PixelFormat::coverage8 || !layered(blob)) {
    if (F == PixelFormat::coverage8 && layered(blob)) {
      const DirectWriter<F, 1, false> w{base, stride, rect, p.dither};
      for (int l = 0; l < blob.layer_count; ++l) draw_with<1>(blob, l, 0, sets[l], map, rect, w, bpp);
    } else if (grey) {
      const DirectWriter<F, 1, false> w{base, stride, rect, p.dither};
      draw_with<1>(blob, 0, 0, sets[0], map, rect, w, bpp);
    } else if (blob.space == ColorSpace::ycbcr) {
      const DirectWriter<F, 3, true> w{base, stride, rect, p.dither};
      draw_with<3>(blob, 0, 0, sets[0], map, rect, w, bpp);
    } else {
      const DirectWriter<F, 3, false> w{base, stride, rect, p.dither};
      draw_with<3>(blob, 0, 0, sets[0], map, rect, w, bpp);
    }
    return;
  }
  const int32_t n = rect.width() * rect.height() * 3;
  for (int32_t i = 0; i < n; ++i) scratch[i] = scratch_empty;
  for (int l = 0; l < blob.layer_count; ++l) {
    const ScratchWriter w{scratch, rect.width(), rect, l};
    draw_with<1>(blob, l, 0, sets[l], map, rect, w, 3);
  }
  convert_scratch<F>(scratch, base, stride, rect, p, blob.space == ColorSpace::ycbcr);
}

using TileRenderer = void (*)(const Blob&, const RenderParams&, const Mapping&, ActiveSet*, const Rect&, uint8_t*,
                              int32_t, int16_t*);

template <PixelFormat F>
constexpr TileRenderer compiled_renderer() {
  if constexpr (config::pixel_formats >> int(F) & 1) {
    return render_tile<F>;
  } else {
    return nullptr;
  }
}

// The tile function of a format; null for a format not compiled in (resolve rejects those).
TileRenderer tile_renderer(PixelFormat f) {
  switch (f) {
    case PixelFormat::l8: return compiled_renderer<PixelFormat::l8>();
    case PixelFormat::rgb888: return compiled_renderer<PixelFormat::rgb888>();
    case PixelFormat::rgb565_le: return compiled_renderer<PixelFormat::rgb565_le>();
    case PixelFormat::rgb565_be: return compiled_renderer<PixelFormat::rgb565_be>();
    case PixelFormat::xrgb8888: return compiled_renderer<PixelFormat::xrgb8888>();
    case PixelFormat::coverage8: return compiled_renderer<PixelFormat::coverage8>();
  }
  return nullptr;
}

}  // namespace
}  // namespace detail

Status tile_buffer_size(const Blob& blob, const RenderParams& params, size_t* bytes) {
  if (!bytes) return Status::null_argument;
  detail::Resolved r;
  Status s = detail::resolve(blob, params, &r);
  if (s != Status::ok) return s;
  *bytes = size_t(r.tile_w) * r.tile_h * bytes_per_pixel(r.format);
  return Status::ok;
}

Status workspace_size(const Blob& blob, const RenderParams& params, size_t* bytes) {
  if (!bytes) return Status::null_argument;
  detail::Resolved r;
  Status s = detail::resolve(blob, params, &r);
  if (s != Status::ok) return s;
  uint32_t longest = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    const uint32_t n = detail::max_window(blob.layers[l], r);
    longest = n > longest ? n : longest;
  }
  *bytes = detail::workspace_alignment + detail::scratch_bytes(blob, r, r.format) +
           size_t(blob.layer_count) * detail::bitmap_bytes(longest);
  return Status::ok;
}

Status render(const Blob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context) {
  if (!tile_buffer || !sink || (!workspace && workspace_bytes)) return Status::null_argument;
  detail::Resolved r;
  Status s = detail::resolve(blob, params, &r);
  if (s != Status::ok) return s;
  const int bpp = bytes_per_pixel(r.format);
  const int32_t stride = r.tile_w * bpp;
  if (tile_buffer_bytes < size_t(stride) * r.tile_h) return Status::buffer_too_small;

  // Workspace: [alignment padding][channel scratch][active-set bitmaps, one equal share per layer].
  uint8_t* ws = static_cast<uint8_t*>(workspace);
  const size_t pad = ws ? (detail::workspace_alignment - uintptr_t(ws) % detail::workspace_alignment) %
                              detail::workspace_alignment
                        : 0;
  const size_t scratch = detail::scratch_bytes(blob, r, r.format);
  if (workspace_bytes < pad + scratch) return Status::buffer_too_small;
  int16_t* scratch_ptr = scratch ? reinterpret_cast<int16_t*>(ws + pad) : nullptr;
  const size_t set_bytes = (workspace_bytes - pad - scratch) / blob.layer_count / 4 * 4;
  detail::ActiveSet sets[3];
  for (int l = 0; l < blob.layer_count; ++l) {
    sets[l].layer = &blob.layers[l];
    sets[l].words = reinterpret_cast<uint32_t*>(ws + pad + scratch + size_t(l) * set_bytes);
    sets[l].capacity = uint32_t(set_bytes * 8 > 0xFFFFFFE0u ? 0xFFFFFFE0u : set_bytes * 8);
    sets[l].view_x1 = r.view.x1;
    if (sets[l].capacity) sets[l].reset();
  }
  const detail::TileRenderer draw = detail::tile_renderer(r.format);
  uint8_t* base = static_cast<uint8_t*>(tile_buffer);
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t by1 = by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1;
    for (int l = 0; l < blob.layer_count; ++l)
      if (!sets[l].advance(r.map, by, by1 - 1)) return Status::buffer_too_small;
    for (int32_t bx = r.view.x0; bx < r.view.x1; bx += r.tile_w) {
      const int32_t bx1 = bx + r.tile_w < r.view.x1 ? bx + r.tile_w : r.view.x1;
      Tile tile;
      tile.pixels = base;
      tile.stride = stride;
      tile.rect = Rect{bx, by, bx1, by1};
      tile.format = r.format;
      draw(blob, params, r.map, sets, tile.rect, base, stride, scratch_ptr);
      sink(context, &tile);
    }
  }
  return Status::ok;
}

}  // namespace tristream::core
