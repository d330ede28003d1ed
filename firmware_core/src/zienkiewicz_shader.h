/* SPDX-License-Identifier: MIT */
#pragma once
// The Zienkiewicz (cubic) shader: values from integer barycentrics per pixel, or forward
// differenced along long rows of large triangles.
#include <stddef.h>
#include <stdint.h>

#include "shader.h"
#include "triangle_view.h"
#include "tristream/config.h"
#if TS_USE_SSE2
#include <emmintrin.h>
#endif
#include "tristream/detail/arith.h"
#include "tristream/detail/bytes.h"
#include "tristream/detail/interpolate.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

// A channel's q8_8 value of vertex k (at offset 2 c from the vertex's first) and its q19_12
// gradient component j (gx, gy of vertex j / 2; offset 8 c), read in place for
// ZienkiewiczChannel::setup. One type for every shader: one setup in the code.
struct VertexValues {
  const uint8_t* const* vertex;
  int offset;
  __attribute__((always_inline)) int32_t operator[](int k) const { return load_u16(vertex[k] + offset); }
};
struct VertexGradients {
  const uint8_t* const* vertex;
  int offset;
  __attribute__((always_inline)) int32_t operator[](int j) const {
    return load_i32(vertex[j >> 1] + offset + 4 * (j & 1));
  }
};

// The writer-independent part of ZienkiewiczShader: a triangle's stepper and coefficients, and
// their set-up (begin), so that the writers of one channel count share one copy of begin in the
// code (-2.7 KB of Cortex-M4 flash at -O2, -0.3 KB at -Os).
template <int Channels>
struct ZienkiewiczTriangle {
  const BlobLayer* layer;
  int per_vertex;
  int first_channel;
  ZienkiewiczChannel ch[Channels];
  BarycentricStepper steps;
  int fd_state = 0;  // forward differencing of this triangle: 0 not set up yet, 1 ready, -1 out of budget
  bool narrow = false;  // every channel fits ZienkiewiczChannel::eval_narrow (zienkiewicz_narrow_forms)

  void begin(const TriangleView& tv, const TriangleSetup& s) {
    const int64_t a2 = s.area2;
    // Where a 64 x 64 product is several instructions (Cortex-M) the division by a 32-bit
    // reciprocal, as the bilinear setup: one 32 x 32 -> 64 product a quotient against a four-multiply
    // high product and a 64-bit product (RoundingDivider for doubled areas of 2^31 or more).
    if (zienkiewicz_narrow_forms && PreinvRoundingDivider::fits(a2)) {
      steps.setup(s.a, s.b, s.e_ref, PreinvRoundingDivider(a2), s.xr, s.yr);
    } else {
      steps.setup(s.a, s.b, s.e_ref, RoundingDivider(a2), s.xr, s.yr);
    }
    int32_t dx[3], dy[3];
    const uint8_t* values[3];
    const uint8_t* gradients[3];
    for (int k = 0; k < 3; ++k) {
      const uint8_t* pk = layer->positions + 4 * size_t(tv.v[k]);
      const uint8_t* pn = layer->positions + 4 * size_t(tv.v[k == 2 ? 0 : k + 1]);
      dx[k] = int32_t(load_u16(pn)) - int32_t(load_u16(pk));
      dy[k] = int32_t(load_u16(pn + 2)) - int32_t(load_u16(pk + 2));
      const size_t first = size_t(tv.v[k]) * per_vertex + first_channel;
      values[k] = layer->values + 2 * first;
      gradients[k] = layer->gradients + 8 * first;
    }
    fd_state = a2 >= zienkiewicz_fd_min_area2 ? 0 : -1;
    // Each channel's values and gradients read from the blob where its setup uses them (no
    // staging arrays).
    bool fits = true;
    for (int c = 0; c < Channels; ++c) {
      const VertexValues v3{values, 2 * c};
      const VertexGradients g6{gradients, 8 * c};
      fits &= ch[c].setup(dx, dy, v3, g6);
    }
    narrow = fits;
  }
};

template <int Channels, typename Writer>
struct ZienkiewiczShader : ZienkiewiczTriangle<Channels> {
  Writer writer;
  int bpp;
  using ZienkiewiczTriangle<Channels>::ch;
  using ZienkiewiczTriangle<Channels>::steps;
  using ZienkiewiczTriangle<Channels>::fd_state;
  using ZienkiewiczTriangle<Channels>::narrow;

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
    if (xe - xs + 1 >= zienkiewicz_fd_min_length && rows_ready()) {
      forward_differenced(y, xs, x0, x1);
      return;
    }
    uint32_t a, b;
    // The weights at x0 directly: the same sums modulo 2^32 as at xs plus (x0 - xs) steps.
    steps.at(x0, y, &a, &b);
    if (zienkiewicz_narrow_forms && narrow) {
      per_pixel<zienkiewicz_narrow_forms>(y, x0, x1, a, b);
    } else {
      per_pixel<false>(y, x0, x1, a, b);
    }
  }
  // Pixels x0..x1 of row y evaluated one by one from the weights a, b at x0; Narrow: every
  // channel's coefficients fit ZienkiewiczChannel::eval_narrow (the same values in 32 bits).
  template <bool Narrow>
  void per_pixel(int32_t y, int32_t x0, int32_t x1, uint32_t a, uint32_t b) {
    constexpr int down = q2_30::frac_bits - q17_15::frac_bits;
    constexpr int32_t half = 1 << (q24_8::frac_bits - 1);
    auto* p = writer.at(x0, y);
    for (int32_t x = x0; x <= x1; ++x) {
      const int32_t a15 = int32_t(a) >> down, b15 = int32_t(b) >> down;
      if constexpr (Writer::takes_rounded) {
        // Rounded and clamped here (as to_u8 of the int32-clamped value); the writer's clamp then
        // folds away, and values are rarely out of range.
        int32_t r[Channels];
        if constexpr (Narrow) {
          // The channels written out, not a loop (as a loop the values go through the stack):
          // -2 % to -3 % modelled Cortex-M4 cycles at -O2, -4 % to -7 % at -Os.
          auto one = [&](int c) __attribute__((always_inline)) {
            const int32_t v = (ch[c].eval_narrow(a15, b15) + half) >> q24_8::frac_bits;
            r[c] = v < 0 ? 0 : (v > 255 ? 255 : v);
          };
          static_assert(Channels == 1 || Channels == 3, "grey or three channels");
          one(0);
          if constexpr (Channels == 3) {
            one(1);
            one(2);
          }
        } else {
          for (int c = 0; c < Channels; ++c) {
            int64_t v = (ch[c].eval_wide(a15, b15) + half) >> q24_8::frac_bits;
            if (uint64_t(v) > 255) v = v < 0 ? 0 : 255;
            r[c] = int32_t(v);
          }
        }
        writer.put_rounded(p, x, y, r);
      } else {
        int32_t q8[Channels];
        for (int c = 0; c < Channels; ++c) q8[c] = Narrow ? ch[c].eval_narrow(a15, b15) : ch[c].eval(a15, b15);
        writer.put(p, x, y, q8);
      }
      p += bpp;
      a += steps.dadx;
      b += steps.dbdx;
    }
  }
  // Pixels x0..x1 of row y by forward differencing from the weights at xs.
  __attribute__((noinline)) void forward_differenced(int32_t y, int32_t xs, int32_t x0, int32_t x1) {
    constexpr int vf = ZienkiewiczChannel::value_frac_bits;
    uint32_t a, b;
    steps.at(xs, y, &a, &b);
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
                                    const __m128i q =
                                        _mm_unpacklo_epi64(_mm_shuffle_epi32(v01, _MM_SHUFFLE(3, 1, 3, 1)),
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
    if constexpr (Writer::takes_rounded && Channels == 3) {
      // Rounding to nearest folded into the values (exact: the differences are unchanged). Each
      // channel's rounded bytes of up to `piece` pixels in a loop of its own (CubicSteps::high_bytes),
      // then the pixels by the writer's put_rounded_bytes (its step is bpp, as the shader's): the
      // same values as stepping the three channels together.
      constexpr int32_t piece = 32;
      zienkiewicz_row_chunks<3>(ch, a, b, steps.dadx, steps.dbdx, x0 - xs, x1 - xs, uint64_t(1) << (vf - 1),
                                [&](int32_t n, int32_t end, CubicSteps* s) {
                                  uint8_t bytes[3][piece];
                                  while (n <= end) {
                                    const int32_t count = end - n + 1 < piece ? end - n + 1 : piece;
                                    for (int c = 0; c < 3; ++c) s[c].high_bytes(bytes[c], count);
                                    writer.put_rounded_bytes(p, xs + n, y, bytes[0], bytes[1], bytes[2], count);
                                    p += count * step;
                                    n += count;
                                  }
                                });
    } else if constexpr (Writer::takes_rounded) {
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

}  // namespace
}  // namespace tristream::core::detail
