/* SPDX-License-Identifier: MIT */
#pragma once
// BilinearShader's lanes (bilinear_shader.h; the interface: portable/bilinear_shader.h) with SSE2:
// RGB to a writer that takes rounded values, the three channels' values, steps per column and per
// row in the writer's lanes (PixelLanes), a pixel one vector addition.
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../interpolate.h"
#include "pixel_writers.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail::sse2 {
namespace {

// Lane by lane, the low 32 bits of v * k (SSE2 has no 32-bit lane product: two 32 x 32 -> 64
// products of the even and the odd lanes).
inline __m128i mullo_lanes(__m128i v, uint32_t k) {
  const __m128i kk = _mm_set1_epi32(int32_t(k));
  const __m128i even = _mm_mul_epu32(v, kk), odd = _mm_mul_epu32(_mm_srli_epi64(v, 32), kk);
  return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)),
                            _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
}

template <int Channels, typename Writer, bool = Channels == 3 && Writer::takes_rounded>
struct BilinearLanes {
  static constexpr bool active = false;
  void set(const BilinearChannel*) {}
  void span(const Writer&, int32_t, int32_t, int32_t, int32_t, int32_t) const {}
};

template <int Channels, typename Writer>
struct BilinearLanes<Channels, Writer, true> {
  static constexpr bool active = true;
  using Lanes = PixelLanes<Writer::format>;
  __m128i lane_ref{}, lane_dx{}, lane_dy{};

  void set(const BilinearChannel* ch) {
    // (int32(v) >> 8 + 128) >> 8 == int32(v + 2^15) >> 16: the rounding of to_u8 folded in.
    constexpr uint32_t half = 1u << (q16_16::frac_bits - 1);
    lane_ref = Lanes::lanes(ch[0].v_ref + half, ch[1].v_ref + half, ch[2].v_ref + half, true);
    lane_dx = Lanes::lanes(ch[0].dvdx, ch[1].dvdx, ch[2].dvdx, false);
    lane_dy = Lanes::lanes(ch[0].dvdy, ch[1].dvdy, ch[2].dvdy, false);
  }
  TS_INLINE void span(const Writer& writer, int32_t y, int32_t x0, int32_t x1, int32_t xr, int32_t yr) const {
    // BilinearChannel::at in lanes: the same sums modulo 2^32.
    const __m128i v = _mm_add_epi32(lane_ref, _mm_add_epi32(mullo_lanes(lane_dx, uint32_t(x0 - xr)),
                                                            mullo_lanes(lane_dy, uint32_t(y - yr))));
    Lanes::put_span_lanes(writer.at(x0, y), x0, x1, y, writer.dither, v, lane_dx);
  }
};

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
