/* SPDX-License-Identifier: MIT */
#pragma once
// The Zienkiewicz (cubic) shader: values from integer barycentrics per pixel, or forward
// differenced along long rows of large triangles.
#include <stddef.h>
#include <stdint.h>

#include "pixel_writers.h"
#include "shader.h"
#include "triangle_view.h"
#include "tristream/config.h"
#include "tuning.h"
#include "arith.h"
#include "backend.h"
#include "bytes.h"
#include "interpolate.h"
#include "portable/zienkiewicz_shader.h"
#include "sse2/zienkiewicz_shader.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

// The blob's little-endian int32 at p, always inlined (optimized for size load_i32 is a call, one
// per gradient read).
TS_INLINE inline int32_t read_i32(const uint8_t* p) {
  return int32_t(uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24));
}

// Optimized for size, RGB565 without dithering is packed as with it, by pack565_dithered's fields
// with these offsets: those of pack565_nearest (the same values: t <= 16313 there too), no tables.
constexpr uint32_t nearest_offsets[4] = {127 * dither_scale, 127 * dither_scale, 127 * dither_scale,
                                         127 * dither_scale};

// A channel's q8_8 value of vertex k (at offset 2 c from the vertex's first) and its q19_12
// gradient component j (gx, gy of vertex j / 2; offset 8 c), read in place for
// ZienkiewiczChannel::setup. One type for every shader: one setup in the code.
struct VertexValues {
  const uint8_t* const* vertex;
  int offset;
  TS_INLINE int32_t operator[](int k) const { return load_u16(vertex[k] + offset); }
};
struct VertexGradients {
  const uint8_t* const* vertex;
  int offset;
  TS_INLINE int32_t operator[](int j) const {
    return read_i32(vertex[j >> 1] + offset + 4 * (j & 1));
  }
};

// RGB565 written by DirectWriter from three channels (rounded): the rows go straight into the
// pixels (ZienkiewiczShader::rgb565_rows, rgb565_pixels), with no staging.
template <typename W>
struct DirectRgb565 {
  static constexpr bool value = false;
};
template <PixelFormat F>
struct DirectRgb565<DirectWriter<F, 3, false>> {
  static constexpr bool value = F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be;
  static constexpr PixelFormat format = F;
};

// The writer-independent part of ZienkiewiczShader: a triangle's stepper and coefficients, and
// their set-up (begin), so that the writers of one channel count share one copy of begin in the
// code.
template <int Channels>
struct ZienkiewiczTriangle {
  const BlobLayer* layer;
  // Bytes, in one word beside the blob's layer: the shader lives in the frame of the tile
  // function, the largest of the deepest Cortex-M4 stack.
  uint8_t per_vertex;
  uint8_t first_channel;
  int8_t fd_state = 0;  // forward differencing of this triangle: 0 not set up yet, 1 ready, -1 out of budget
  bool narrow = false;  // every channel fits ZienkiewiczChannel::eval_narrow
  ZienkiewiczChannel ch[Channels];
  BarycentricStepper steps;

  // The set-up of a triangle in parts: the stepper (begin_steps), the coefficients (begin_channels)
  // and, on Cortex-M, the 64-bit expansion of the rare channels beyond the 32-bit budget
  // (begin_wide, a tail call). There each part is out of line, one called after another: the
  // deepest stack below draw_with is one part's frame, not the sum of begin's, the stepper's and
  // setup_wide's. Forward differencing is set up on the triangle's first long row in the tile
  // (set_up_rows).
  void begin(const TriangleView& tv, const TriangleSetup& s) {
    begin_steps(s);
    begin_channels(tv, s.area2);
  }
  TS_ZIENKIEWICZ_BEGIN_PART void begin_steps(const TriangleSetup& s) {
    const int64_t a2 = s.area2;
    // Where a 64 x 64 product is several instructions (Cortex-M) the division by a 32-bit
    // reciprocal, as the bilinear setup: one 32 x 32 -> 64 product a quotient against a four-multiply
    // high product and a 64-bit product (RoundingDivider for doubled areas of 2^31 or more).
    if (zienkiewicz_narrow_forms && PreinvRoundingDivider::fits(a2)) {
      steps.setup(s.a, s.b, s.e_ref, PreinvRoundingDivider(a2), s.xr, s.yr);
    } else {
      steps.setup(s.a, s.b, s.e_ref, RoundingDivider(a2), s.xr, s.yr);
    }
  }

  // The edge vectors of tv (domain space) and its vertices' values and gradients of the first
  // channel of this shader, in the blob.
  struct Inputs {
    int32_t dx[3], dy[3];
    const uint8_t* values[3];
    const uint8_t* gradients[3];
  };
  TS_INLINE void inputs(const TriangleView& tv, Inputs* in) const {
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
      edge(tv, k, &in->dx[k], &in->dy[k]);
      const size_t first = size_t(tv.v[k]) * per_vertex + first_channel;
      in->values[k] = layer->values + 2 * first;
      in->gradients[k] = layer->gradients + 8 * first;
    }
  }
  // Edge k of tv (from vertex k to the next) in domain space.
  TS_INLINE void edge(const TriangleView& tv, int k, int32_t* dx, int32_t* dy) const {
    const uint8_t* pk = layer->positions + 4 * size_t(tv.v[k]);
    const uint8_t* pn = layer->positions + 4 * size_t(tv.v[k == 2 ? 0 : k + 1]);
    *dx = int32_t(load_u16(pn)) - int32_t(load_u16(pk));
    *dy = int32_t(load_u16(pn + 2)) - int32_t(load_u16(pk + 2));
  }

  // Each channel's coefficients, values and gradients read from the blob where its setup uses
  // them (no staging arrays); with the 32-bit forms only the 32-bit expansion here (setup_narrow),
  // the channels it does not fit to begin_wide.
  TS_ZIENKIEWICZ_BEGIN_PART void begin_channels(const TriangleView& tv, int64_t area2) {
    Inputs in;
    inputs(tv, &in);
    fd_state = area2 >= zienkiewicz_fd_min_area2 ? 0 : -1;
    if constexpr (zienkiewicz_narrow_forms) {
      uint32_t wide = 0;
      // Unrolled: the blob's addresses stay in registers, not stepped on the stack.
#pragma GCC unroll 3
      for (int c = 0; c < Channels; ++c)
        if (!ch[c].setup_narrow(in.dx, in.dy, VertexValues{in.values, 2 * c}, VertexGradients{in.gradients, 8 * c}))
          wide |= 1u << c;
      narrow = true;
      if (wide) begin_wide(tv, wide);
    } else {
      bool fits = true;
#pragma GCC unroll 3  // as above
      for (int c = 0; c < Channels; ++c)
        fits &= ch[c].setup(in.dx, in.dy, VertexValues{in.values, 2 * c}, VertexGradients{in.gradients, 8 * c});
      narrow = fits;
    }
  }
  // Forward differencing set up (fd_state 1, or -1 outside its budget). The steps read again for
  // each channel, not kept across the calls: on Cortex-M the caller's frame (first_long_row's) is
  // below the set-up's, the deepest of the render.
  TS_INLINE bool set_up_rows() {
    fd_state = -1;
    if (!ZienkiewiczChannel::steps_fit_rows(int32_t(steps.dadx), int32_t(steps.dbdx))) return false;
#pragma GCC unroll 3
    for (int c = 0; c < Channels; ++c) {
      // The steps read here again: GCC knows the call leaves them, and kept them in registers
      // saved in this frame (the deepest stack's).
      __asm__("" ::: "memory");
      if (!ch[c].setup_rows_within(int32_t(steps.dadx), int32_t(steps.dbdx))) return false;
    }
    fd_state = 1;
    return true;
  }
  // The channels of the mask `wide` by the 64-bit expansion; narrow when their coefficients fit
  // the 32-bit evaluation all the same. A channel a call (wide_channel): only one channel's
  // 64-bit temporaries on the stack.
  TS_NOINLINE void begin_wide(const TriangleView& tv, uint32_t wide) {
    bool fits = true;
    for (int c = 0; c < Channels; ++c)
      if (wide >> c & 1) fits &= wide_channel(tv, c);
    narrow = fits;
  }
  // Channel c's values and gradients read through the triangle's vertex indices (no arrays of
  // addresses in the frame of this rare path).
  struct IndexedValues {
    const ZienkiewiczTriangle* t;
    const TriangleView* tv;
    int c;
    int32_t operator[](int k) const { return load_u16(t->layer->values + 2 * t->first_value(*tv, k, c)); }
  };
  struct IndexedGradients {
    const ZienkiewiczTriangle* t;
    const TriangleView* tv;
    int c;
    int32_t operator[](int j) const {
      return load_i32(t->layer->gradients + 8 * t->first_value(*tv, j >> 1, c) + 4 * (j & 1));
    }
  };
  size_t first_value(const TriangleView& tv, int k, int c) const {
    return size_t(tv.v[k]) * per_vertex + first_channel + c;
  }
  TS_NOINLINE bool wide_channel(const TriangleView& tv, int c) {
    int32_t dx[3], dy[3];
    for (int k = 0; k < 3; ++k) edge(tv, k, &dx[k], &dy[k]);
    return ch[c].expand_wide(dx, dy, IndexedValues{this, &tv, c}, IndexedGradients{this, &tv, c});
  }
};

// Forward-differenced rows with the channels in vector lanes where the platform has them:
// backend::ZienkiewiczLanes (portable/zienkiewicz_shader.h, sse2/zienkiewicz_shader.h).
template <int Channels, typename Writer>
struct ZienkiewiczShader : ZienkiewiczTriangle<Channels> {
  using Lanes = backend::ZienkiewiczLanes<Channels, Writer>;
  tuning::ZienkiewiczWriter<Writer> writer;
  int bpp;
  using ZienkiewiczTriangle<Channels>::ch;
  using ZienkiewiczTriangle<Channels>::steps;
  using ZienkiewiczTriangle<Channels>::fd_state;
  using ZienkiewiczTriangle<Channels>::narrow;

  // Eight rows a table of portable/rasterize.h (row_bounds.h: RowChunk), not 16: this shader's
  // frames are the deepest of the render (Cortex-M4, dithered tiles: 1,508 bytes, within 1.5 KB,
  // against 1,572), and its rows cost far more than a table's round (under 0.6 % of its cycles).
  static constexpr int32_t rows_a_chunk = 8;

  // Forward differencing set up on the first row that uses it; false for a small triangle or one
  // outside the budget (then every row is evaluated per pixel).
  TS_NOINLINE bool rows_ready_slow() { return this->set_up_rows(); }
  // The first row of at least zienkiewicz_fd_min_length pixels in the tile (without SSE2):
  // forward differencing set up, then the row drawn by it (a tail call) or, out of its budget
  // (fd_state now -1), by span per pixel (span reads xe only for the row's length: xs for it).
  // Out of span: the set-up's frames are not below span's. Set up here, not in begin: many
  // triangles large enough for it draw no such row in a tile or band. The row's end is not kept
  // across the set-up, so this frame, below the set-up's, stays small.
  TS_NOINLINE void first_long_row(int32_t y, int32_t xs, int32_t x0, int32_t x1) {
    if (this->set_up_rows()) {
      forward_differenced_row(y, xs, x0, x1);
    } else {
      span(y, xs, xs, x0, x1);  // per pixel (rare)
    }
  }
  // Row y of the triangle covers [xs, xe]; pixels x0..x1 of it are in the tile. Rows of at least
  // zienkiewicz_fd_min_length pixels (of large enough triangles) are forward-differenced, others
  // evaluated per pixel: the choice depends on the whole row, not on the tile. Out of line (both
  // loops): their code generation then does not depend on the rest of the tile function (inlined,
  // unrelated changes there swing its speed).
  TS_NOINLINE void span(int32_t y, int32_t xs, int32_t xe, int32_t x0, int32_t x1) {
    if constexpr (tuning::zienkiewicz_set_up_in_span) {
      if (xe - xs + 1 >= zienkiewicz_fd_min_length && (fd_state == 0 ? rows_ready_slow() : fd_state > 0)) {
        forward_differenced_row(y, xs, x0, x1);
        return;
      }
    } else if (xe - xs + 1 >= zienkiewicz_fd_min_length && fd_state >= 0) {
      // Tail calls: this frame is gone before the forward differencing's and the set-up's.
      if (fd_state > 0) {
        forward_differenced_row(y, xs, x0, x1);
      } else {
        first_long_row(y, xs, x0, x1);
      }
      return;
    }
    uint32_t a, b;
    // The weights at x0 directly: the same sums modulo 2^32 as at xs plus (x0 - xs) steps.
    steps.at(x0, y, &a, &b);
    if (narrow) {
      per_pixel<true>(y, x0, x1, a, b);
    } else {
      per_pixel<false>(y, x0, x1, a, b);
    }
  }
  // Pixels x0..x1 of row y evaluated one by one from the weights a, b at x0; Narrow: every
  // channel's coefficients fit ZienkiewiczChannel::eval_narrow (eval32 on Cortex-M; on 64-bit
  // hosts every triangle: the 128-bit form).
  template <bool Narrow>
  void per_pixel(int32_t y, int32_t x0, int32_t x1, uint32_t a, uint32_t b) {
    auto* p = writer.at(x0, y);
    if constexpr (Narrow && DirectRgb565<Writer>::value) {
      // RGB565 by eval_narrow: the dither flag read once a row, not a pixel, and each pixel
      // packed as put_rounded packs it (put_span_in_range's loops: the tables without dithering,
      // the row's offsets with it); the same pixels.
      // Optimized for size one loop, by the offsets (without dithering those of pack565_nearest,
      // as forward_differenced): no tables.
      constexpr PixelFormat F = DirectRgb565<Writer>::format;
      const uint32_t* const offset =
          writer.dither ? dither_span_offsets(y, x0, p) : (TS_SIZE ? nearest_offsets : nullptr);
      if (offset) {
        const uint32_t k31 = in_register(dither_k31), k63 = in_register(dither_k63);
        rgb565_pixels(p, x1 - x0 + 1, a, b, [&](uint8_t* q, uint32_t r, uint32_t g, uint32_t bl) {
          store565_bytes(q, rgb565_bytes<F>(pack565_dithered(r, g, bl, offset[dither_index(q)], k31, k63)));
        });
      } else {
        if constexpr (!TS_SIZE) {
          const uint16_t* table = rgb565_table<F>.v;
          __asm__("" : "+r"(table));  // the table's address in a register (see put_span_in_range)
          rgb565_pixels(p, x1 - x0 + 1, a, b, [&](uint8_t* q, uint32_t r, uint32_t g, uint32_t bl) {
            store565_bytes(q, pack565_bytes_by_table_biased<F>(r, g + 256, bl, table));
          });
        }
      }
      return;
    }
    if constexpr (Narrow && Writer::takes_rounded) {
      // The weights as eval_narrow takes them, stepped (on 64-bit hosts times 2^32: no shifts a pixel).
      using Weights = ZienkiewiczChannel::Weights;
      Weights w = Weights::of(a, b);
      const Weights dw = Weights::of(steps.dadx, steps.dbdx);
      for (int32_t x = x0; x <= x1; ++x, w.step(dw)) {
        // Rounded and clamped here (as to_u8 of the int32-clamped value, rounding_bias's extra
        // unit included: see ZienkiewiczChannel; the q8 writers below take the value without it
        // and round it themselves); the writer's clamp then folds away, and values are rarely out
        // of range. The channels written out, not a loop (as a loop the values go through the
        // stack).
        int32_t r[Channels];
        auto one = [&](int c) TS_INLINE { r[c] = int32_t(rounded(ch[c].eval_narrow(w))); };
        static_assert(Channels == 1 || Channels == 3, "grey or three channels");
        one(0);
        if constexpr (Channels == 3) {
          one(1);
          one(2);
        }
        writer.put_rounded(p, x, y, r);
        p += bpp;
      }
      return;
    }
    for (int32_t x = x0; x <= x1; ++x) {
      const int32_t wa = int32_t(a), wb = int32_t(b);
      if constexpr (Writer::takes_rounded) {
        int32_t r[Channels];
        for (int c = 0; c < Channels; ++c) {
          int64_t v = ch[c].eval_wide(wa, wb) >> q24_8::frac_bits;  // the bias: rounded to nearest
          if (uint64_t(v) > 255) v = v < 0 ? 0 : 255;
          r[c] = int32_t(v);
        }
        writer.put_rounded(p, x, y, r);
      } else {
        int32_t q8[Channels];
        for (int c = 0; c < Channels; ++c)
          q8[c] = Narrow && !ZienkiewiczChannel::narrow_always
                      ? int32_t(ch[c].eval_narrow(wa, wb) - ZienkiewiczChannel::rounding_bias)
                      : ch[c].eval(wa, wb);
        writer.put(p, x, y, q8);
      }
      p += bpp;
      a += steps.dadx;
      b += steps.dbdx;
    }
  }
  // A q24_8 value plus ZienkiewiczChannel::rounding_bias from eval_narrow rounded and clamped to
  // [0, 255] (as to_u8 of the int32-clamped value plus the bias's extra unit, what put_rounded
  // takes).
  using NarrowValue = ZienkiewiczChannel::NarrowValue;
  TS_INLINE static uint32_t rounded(NarrowValue biased) {
    NarrowValue v = biased >> q24_8::frac_bits;
    if constexpr (tuning::saturates) {
      return uint32_t(v < 0 ? 0 : (v > 255 ? 255 : v));  // one USAT
    } else {
      if (uint64_t(int64_t(v)) > 255) v = v < 0 ? 0 : 255;  // rare: a branch
      return uint32_t(v);
    }
  }
  // Three channels rounded: out(rounded(v0), rounded(v1), rounded(v2)); without a saturating
  // instruction one test for the three (all in range when their bitwise or is below 2^16).
  template <typename Out>
  TS_INLINE static void rounded3(NarrowValue v0, NarrowValue v1, NarrowValue v2, const Out& out) {
    if constexpr (!tuning::saturates) {
      constexpr int f = q24_8::frac_bits;
      if (uint64_t(v0 | v1 | v2) < (uint64_t(256) << f)) {
        out(uint32_t(v0) >> f, uint32_t(v1) >> f, uint32_t(v2) >> f);
        return;
      }
    }
    out(rounded(v0), rounded(v1), rounded(v2));
  }
  // per_pixel's RGB565 loop by eval_narrow: `count` pixels from p (2 bytes each) from the
  // weights a, b, each channel rounded and clamped as put_rounded takes it, then store(pixel, r, g, b).
  template <typename Store>
  TS_INLINE void rgb565_pixels(uint8_t* p, int32_t count, uint32_t a, uint32_t b,
                                                    const Store& store) const {
    using Weights = ZienkiewiczChannel::Weights;
    Weights w = Weights::of(a, b);
    const Weights dw = Weights::of(steps.dadx, steps.dbdx);
    for (uint8_t* const end = p + 2 * count; p != end; p += 2, w.step(dw)) {
      rounded3(ch[0].eval_narrow(w), ch[1].eval_narrow(w), ch[2].eval_narrow(w),
               [&](uint32_t r, uint32_t g, uint32_t bl) { store(p, r, g, bl); });
    }
  }
  // A forward-differenced row, as span and first_long_row draw it: without SSE2 in RGB565 the row
  // loops themselves (tail calls, no forward_differenced call between; optimized for size one
  // loop, by the offsets), else forward_differenced.
  TS_INLINE void forward_differenced_row(int32_t y, int32_t xs, int32_t x0, int32_t x1) {
    if constexpr (DirectRgb565<Writer>::value && !Lanes::active) {
      if (TS_SIZE || writer.dither) {
        rgb565_rows<true>(y, xs, x0, x1);
      } else {
        rgb565_rows<false>(y, xs, x0, x1);
      }
      return;
    }
    forward_differenced(y, xs, x0, x1);
  }
  // Pixels x0..x1 of row y by forward differencing from the weights at xs.
  TS_NOINLINE void forward_differenced(int32_t y, int32_t xs, int32_t x0, int32_t x1) {
    constexpr int vf = ZienkiewiczChannel::value_frac_bits;
    constexpr uint32_t half = uint32_t(1) << (vf - 1);
    uint32_t a, b;
    steps.at(xs, y, &a, &b);
    auto* p = writer.at(x0, y);
    const int step = bpp;  // a local: the pixel stores could alias the member
    const uint32_t da = steps.dadx, db = steps.dbdx;
    if constexpr (Lanes::active) {
      Lanes::row(writer, ch, a, b, da, db, xs, x0, x1, y, p, step);
      return;
    }
    if constexpr (Writer::takes_rounded) {
      // Rounding to nearest folded into the values; clamped here (rarely needed: the writer's
      // clamp then folds away).
      zienkiewicz_row_chunks<Channels>(ch, a, b, da, db, x0 - xs, x1 - xs, half,
                                       [&](int32_t n, int32_t end, CubicSteps* s) {
                                         for (; n <= end; ++n) {
                                           int32_t r[Channels];
                                           for (int c = 0; c < Channels; ++c) {
                                             int32_t v = int32_t(s[c].v) >> vf;
                                             if (uint32_t(v) > 255) v = v < 0 ? 0 : 255;  // rare
                                             r[c] = v;
                                             s[c].step();
                                           }
                                           writer.put_rounded(p, xs + n, y, r);
                                           p += step;
                                         }
                                       });
    } else {
      zienkiewicz_row_chunks<Channels>(ch, a, b, da, db, x0 - xs, x1 - xs, 0,
                                       [&](int32_t n, int32_t end, CubicSteps* s) {
                                         for (; n <= end; ++n) {
                                           int32_t q8[Channels];
                                           for (int c = 0; c < Channels; ++c) {
                                             q8[c] = int32_t(s[c].v) >> (vf - q24_8::frac_bits);
                                             s[c].step();
                                           }
                                           writer.put(p, xs + n, y, q8);
                                           p += step;
                                         }
                                       });
    }
  }
  // forward_differenced's RGB565 rows without SSE2 (rounding to nearest folded into the values):
  // the three channels stepped together a pixel (nine words of differences in registers, the
  // three D3 reloaded), each pixel packed as put_rounded packs it: by the tables, or ByOffsets by
  // the row's Bayer offsets when dithering (optimized for size also without, by nearest_offsets:
  // no tables). One channel at a time into its bit field would cost three calls a chunk. Its own
  // frame, not below forward_differenced's (the deepest
  // zienkiewicz stack stays that of the set-up).
  template <bool ByOffsets>
  TS_NOINLINE void rgb565_rows(int32_t y, int32_t xs, int32_t x0, int32_t x1) {
    constexpr PixelFormat F = DirectRgb565<Writer>::format;
    constexpr int vf = ZienkiewiczChannel::value_frac_bits;
    uint32_t a, b;
    steps.at(xs, y, &a, &b);
    uint8_t* const p = writer.at(x0, y);
    [[maybe_unused]] const uint32_t* offset = nullptr;
    if constexpr (ByOffsets) {
      offset = TS_SIZE && !writer.dither ? nearest_offsets : dither_span_offsets(y, x0, p);
    }
    zienkiewicz_row_chunks<3>(
        ch, a, b, steps.dadx, steps.dbdx, x0 - xs, x1 - xs, uint32_t(1) << (vf - 1),
        [&](int32_t n, int32_t end, CubicSteps* s) {
          uint32_t r = s[0].v, r1 = s[0].d1, r2 = s[0].d2;
          uint32_t g = s[1].v, g1 = s[1].d1, g2 = s[1].d2;
          uint32_t bl = s[2].v, b1 = s[2].d1, b2 = s[2].d2;
          const uint32_t r3 = s[0].d3, g3 = s[1].d3, b3 = s[2].d3;
          auto u8 = [](uint32_t v) {
            const int32_t h = int32_t(v) >> vf;
            return uint32_t(h < 0 ? 0 : (h > 255 ? 255 : h));
          };
          uint8_t* q = p + 2 * (n - (x0 - xs));
          uint8_t* const stop = q + 2 * (end - n + 1);
          if constexpr (ByOffsets) {
            const uint32_t k31 = in_register(dither_k31), k63 = in_register(dither_k63);
            for (; q != stop; q += 2) {
              store565_bytes(
                  q, rgb565_bytes<F>(pack565_dithered(u8(r), u8(g), u8(bl), offset[dither_index(q)], k31, k63)));
              r += r1, r1 += r2, r2 += r3;
              g += g1, g1 += g2, g2 += g3;
              bl += b1, b1 += b2, b2 += b3;
            }
          } else {
            const uint16_t* table = rgb565_table<F>.v;
            __asm__("" : "+r"(table));  // the table's address in a register
            auto pixel = [&](uint8_t * at) TS_INLINE {
              store565_bytes(at, pack565_bytes_by_table_biased<F>(u8(r), u8(g) + 256, u8(bl), table));
              r += r1, r1 += r2, r2 += r3;
              g += g1, g1 += g2, g2 += g3;
              bl += b1, b1 += b2, b2 += b3;
            };
            // Two pixels an iteration, one loop test for both.
            for (; stop - q >= 4; q += 4) {
              pixel(q);
              pixel(q + 2);
            }
            if (q != stop) pixel(q);
          }
        });
  }
};

}  // namespace
}  // namespace tristream::core::detail
