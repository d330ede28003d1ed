/* SPDX-License-Identifier: MIT */
#pragma once
// ZienkiewiczShader's lanes (zienkiewicz_shader.h; the interface: portable/zienkiewicz_shader.h)
// with SSE2: a forward-differenced RGB row to a writer that takes rounded values, the three
// channels in 32-bit lanes: three additions a pixel, the rounded values the lanes shifted down.
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include <emmintrin.h>

#include "../interpolate.h"
#include "pixel_writers.h"

namespace tristream::core::detail::sse2 {
namespace {

template <int Channels, typename Writer, bool = Channels == 3 && Writer::takes_rounded>
struct ZienkiewiczLanes {
  static constexpr bool active = false;
  static void row(const Writer&, const ZienkiewiczChannel*, uint32_t, uint32_t, uint32_t, uint32_t, int32_t, int32_t,
                  int32_t, int32_t, uint8_t*, int) {}
};

template <int Channels, typename Writer>
struct ZienkiewiczLanes<Channels, Writer, true> {
  static constexpr bool active = true;
  using Px = PixelLanes<Writer::format>;
  TS_INLINE static void row(const Writer& writer, const ZienkiewiczChannel* ch, uint32_t a, uint32_t b, uint32_t da,
                            uint32_t db, int32_t xs, int32_t x0, int32_t x1, int32_t y, uint8_t* p, int step) {
    constexpr int vf = ZienkiewiczChannel::value_frac_bits;
    constexpr uint32_t half = uint32_t(1) << (vf - 1);
    // Rounding to nearest folded into the values. The three channels in 32-bit lanes: three
    // additions a pixel, the rounded values the lanes shifted down.
    const int32_t last = x1 - xs;
    zienkiewicz_row_chunks<3>(ch, a, b, da, db, x0 - xs, last, half, [&](int32_t n, int32_t end, CubicSteps* s) {
      // The three channels' (v, d1, d2, d3) transposed into a vector of each.
      static_assert(sizeof(CubicSteps) == 16, "four words a channel");
      auto row = [&](int c) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(&s[c])); };
      const __m128i r0 = row(0), r1 = row(1), r2 = row(2), zero = _mm_setzero_si128();
      const __m128i t0 = _mm_unpacklo_epi32(r0, r1), t1 = _mm_unpacklo_epi32(r2, zero);
      const __m128i t2 = _mm_unpackhi_epi32(r0, r1), t3 = _mm_unpackhi_epi32(r2, zero);
      __m128i v = _mm_unpacklo_epi64(t0, t1), d1 = _mm_unpackhi_epi64(t0, t1), d2 = _mm_unpacklo_epi64(t2, t3);
      const __m128i d3 = _mm_unpackhi_epi64(t2, t3);
      for (; n <= end; ++n) {
        Px::put_lanes(p, Px::ordered(_mm_srai_epi32(v, vf)), xs + n, y, writer.dither, n != last);
        p += step;
        v = _mm_add_epi32(v, d1), d1 = _mm_add_epi32(d1, d2), d2 = _mm_add_epi32(d2, d3);
      }
    });
  }
};

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
