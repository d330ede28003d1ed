/* SPDX-License-Identifier: MIT */
#pragma once
// The bilinear (linear per triangle) shader: values stepped by their exact per-pixel gradients.
#include <stdint.h>

#include "shader.h"
#include "triangle_view.h"
#include "tristream/config.h"
#include "arith.h"
#include "backend.h"
#include "interpolate.h"
#include "portable/bilinear_shader.h"
#include "row_bounds.h"
#include "sse2/bilinear_shader.h"
#include "tuning.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

// The bit budget of the bilinear setup of scan-path triangles (boxes below scan_max_extent = m
// pixels each way): with e = m + 1 their extents (and |dx|, |dy| of their edges) are below e 2^S,
// the offsets of their vertices from the reference pixel below (e + 1) 2^S, the doubled area d
// below (e 2^S)^2 (at most the box), and |e_ref| < 2 e (e + 1) 2^(2S). With values below 2^16 the
// largest numerator, 2^8 sum v e_ref (dv/dx and dv/dy have |A|, |B| < e 2^(2S) instead), is below
// 2^24 * 3 * 2 e (e + 1) 2^(2S). m = 16, S = 4: |2n + d| < 2^43.9 and 2d < 2^17.2; m = 15:
// |2n + d| < 2^43.7 and 2d < 2^17.
constexpr uint64_t scan_area2_bound(int m, int s) { return uint64_t(m + 1) * (m + 1) << (2 * s); }
constexpr uint64_t scan_numerator_bound(int m, int s) {
  return (uint64_t(3 * 2 * (m + 1) * (m + 2)) << (25 + 2 * s)) + scan_area2_bound(m, s);
}
// Whether ShortRoundingDivider is exact for them: |2n + d| 2d < 2^64.
constexpr bool short_division_fits(int m, int s) {
  return scan_numerator_bound(m, s) < ~uint64_t(0) / (2 * scan_area2_bound(m, s));
}
// Whether Mod32RoundingDivider is exact for them (BilinearChannel::setup_from_vertex0): 2d within
// its divisor range and its numerators in int32, with value differences |u|, |w| < 2^16: u a_0 +
// w a_1 and u b_0 + w b_1 (a = A 2^S, |A| < e 2^S: below 2 * 65535 * e 2^(2S)), and every product
// and the sum of t = u p + w q (p = ox A_0 + oy B_0 with |ox|, |oy| < 2^S: below twice that).
constexpr bool mod32_division_fits(int m, int s) {
  return 2 * scan_area2_bound(m, s) <= Mod32RoundingDivider::max_divisor &&
         (uint64_t(4) * 65535 * (uint64_t(m + 1) << (2 * s))) < (uint64_t(1) << 31);
}
// Where the high multiply is one instruction (a 128-bit type) the short division for the scan
// path and RoundingDivider for the span path. Else (Cortex-M) Mod32RoundingDivider for the scan
// path where the budget allows (two or three hardware divides of small quotients per numerator and
// no 64-bit arithmetic: fewer cycles than a reciprocal per triangle), and PreinvRoundingDivider
// for the span path (RoundingDivider for
// doubled areas of 2^31 or more, none in the default configuration).
constexpr bool bilinear_short_division =
    TS_USE_INT128 && short_division_fits(scan_max_extent, config::subpixel_bits);
constexpr bool bilinear_mod32_division =
    !TS_USE_INT128 && mod32_division_fits(scan_max_extent, config::subpixel_bits);
constexpr bool bilinear_preinv_division = !TS_USE_INT128;
static_assert(short_division_fits(16, 4), "the default configuration divides scan-path numerators without correction");
static_assert(mod32_division_fits(15, 4), "the default configuration divides scan-path numerators in 32 bits");

template <int Channels, typename Writer>
struct BilinearShader {
  using Lanes = backend::BilinearLanes<Channels, Writer>;
  const BlobLayer* layer;
  int per_vertex;
  int first_channel;
  Writer writer;
  int bpp;
  BilinearChannel ch[Channels];
  int32_t xr = 0, yr = 0;
  // Without a 128-bit type (Cortex-M) triangles are set up from vertex 0's value
  // (BilinearChannel::setup_from_vertex0: no edge value at the reference pixel and fewer 64-bit
  // products), but for those of RoundingDivider (doubled areas of 2^31 or more, which read the
  // span path's e_ref). The scan path's edge values that begin reads: none then; e_ref32 for the
  // short division without SSE2; else e_ref.
  static constexpr bool from_vertex0 = !TS_USE_INT128;
  static constexpr unsigned e_refs = TS_USE_SSE2                 ? scan_e_ref64
                                     : from_vertex0              ? 0u
                                     : bilinear_short_division   ? scan_e_ref32
                                                                 : scan_e_ref64;
  // The RGB spans in vector lanes where the platform has them (portable/bilinear_shader.h,
  // sse2/bilinear_shader.h); no storage where it has none.
  [[no_unique_address]] Lanes lanes;
  static constexpr bool in_lanes = Lanes::active;
  // A writer that takes rounded values, without lanes: span's scalar path (begin moves v_ref).
  static constexpr bool rounded_scalar = Writer::takes_rounded && !in_lanes;

  // Whether begin reads e_ref on a triangle whose box is not small (shader.h: LargeERefRead).
  static constexpr bool large_reads_e_ref(int64_t area2) {
    return !(from_vertex0 && bilinear_preinv_division && PreinvRoundingDivider::fits(area2));
  }
  // rows (shader.h: DrawsRows) where span's scalar path takes rounded values; not when optimizing
  // for size, where span's pixel loops are then one copy, inlined into span.
  static constexpr bool draws_rows = rounded_scalar && !TS_SIZE;

  TS_BILINEAR_BEGIN void begin(const TriangleView& tv, const TriangleSetup& s) {
    xr = s.xr;
    yr = s.yr;
    int32_t vals[3][Channels];
    TS_UNROLL
    for (int k = 0; k < 3; ++k) vertex_values(*layer, per_vertex, first_channel, Channels, tv.v[k], vals[k]);
    auto setup = [&](const auto& by_area2, const auto* e_ref) {
      TS_UNROLL_FAST
      for (int c = 0; c < Channels; ++c) {
        const int32_t v3[3] = {vals[0][c], vals[1][c], vals[2][c]};
        ch[c].setup(s.a, s.b, e_ref, by_area2, v3);
      }
    };
    const auto setup_from_vertex0 = [&](const auto& by_area2) {
      constexpr int S = config::subpixel_bits;
      const auto edges = BilinearChannel::VertexZeroEdges::of<S>(s.a, s.b, s.xr * (1 << S) - tv.x[0],
                                                                 s.yr * (1 << S) - tv.y[0]);
      TS_UNROLL_FAST
      for (int c = 0; c < Channels; ++c) {
        const int32_t v3[3] = {vals[0][c], vals[1][c], vals[2][c]};
        ch[c].setup_from_vertex0(edges, by_area2, v3);
      }
    };
    // The scan path's numerators are small enough for the division without correction, and its
    // edge values fit int32 (e_ref32, set without SSE2).
    if (bilinear_short_division && s.small_box) {
      if constexpr (TS_USE_SSE2) {
        setup(ShortRoundingDivider(s.area2), s.e_ref);
      } else {
        setup(ShortRoundingDivider(s.area2), s.e_ref32);
      }
    } else if (bilinear_mod32_division && s.small_box) {
      setup_from_vertex0(Mod32RoundingDivider(int32_t(s.area2)));
    } else if (bilinear_preinv_division && PreinvRoundingDivider::fits(s.area2)) {
      if constexpr (from_vertex0) {
        setup_from_vertex0(PreinvRoundingDivider(s.area2));
      } else {
        setup(PreinvRoundingDivider(s.area2), s.e_ref);
      }
    } else {
      setup(RoundingDivider(s.area2), s.e_ref);
    }
    if constexpr (in_lanes) lanes.set(ch);
    if constexpr (rounded_scalar) {
      // v_ref becomes the value at pixel (0, 0) with the rounding offset (modulo 2^32, as every
      // use): a row's first value is then v_ref + dvdx x + dvdy y, without xr and yr.
      constexpr uint32_t half = 1u << (q16_16::frac_bits - 1);
      TS_UNROLL_FAST
      for (int c = 0; c < Channels; ++c)
        ch[c].v_ref = ch[c].v_ref + half - ch[c].dvdx * uint32_t(xr) - ch[c].dvdy * uint32_t(yr);
    }
  }
  // Rows y .. y + n - 1, the covered columns table[j] of each within [cx0, cx1]: span's scalar
  // path, with the dithering tested once for the table.
  TS_SPAN_INLINE void rows(const RowSpan* table, int32_t y, int32_t n, int32_t cx0, int32_t cx1) {
    static_assert(rounded_scalar, "rows takes span's scalar path of rounded values");
    if (!writer.dither) {
      rows_with<false>(table, y, n, cx0, cx1);
    } else {
      rows_with<true>(table, y, n, cx0, cx1);
    }
  }
  template <bool Dither>
  TS_INLINE void rows_with(const RowSpan* table, int32_t y, int32_t n, int32_t cx0, int32_t cx1) {
    for (const RowSpan* const end = table + n; table != end; ++table, ++y) {
      const int32_t cs = max2(table->xs, cx0), ce = min2(table->xe, cx1);
      if (cs > ce) continue;
      const RoundedStart s = rounded_start(cs, y);
      writer.template put_span<Dither>(writer.at(cs, y), cs, ce, y, s.v0, s.v1, s.v2, s.d0, s.d1, s.d2);
    }
  }
  // The values of pixel (x, y) and their steps along the row, for the writers that take rounded
  // values (v_ref is at pixel (0, 0), the rounding offset included: begin); channels 1 and 2 are 0
  // for grey.
  struct RoundedStart {
    uint32_t v0, v1, v2, d0, d1, d2;
  };
  TS_INLINE RoundedStart rounded_start(int32_t x, int32_t y) const {
    const uint32_t dx = uint32_t(x), dy = uint32_t(y);
    const BilinearChannel &c0 = ch[0], &c1 = ch[Channels > 1 ? 1 : 0], &c2 = ch[Channels - 1];
    return RoundedStart{c0.at_offset(dx, dy),
                        Channels == 3 ? c1.at_offset(dx, dy) : 0,
                        Channels == 3 ? c2.at_offset(dx, dy) : 0,
                        c0.step(),
                        Channels == 3 ? c1.step() : 0,
                        Channels == 3 ? c2.step() : 0};
  }
  TS_SPAN_INLINE void span(int32_t y, int32_t, int32_t, int32_t x0, int32_t x1) {
    if constexpr (in_lanes) {
      lanes.span(writer, y, x0, x1, xr, yr);
      return;
    }
    auto* p = writer.at(x0, y);
    if constexpr (Writer::takes_rounded) {
      // (int32(v) >> 8 + 128) >> 8 == int32(v + 2^15) >> 16: the rounding of to_u8 folded into
      // the start value. No clamping is needed: a covered pixel is in the closed triangle, so its
      // exact value is a convex combination of vertex values in [0, 255 * 2^8] (open_blob checks
      // them), i.e. in [0, 255 * 2^16] in q16_16, and the stepped value is within (1 + |x - xr| +
      // |y - yr|) / 2 < 2^12 units of it (docs/FIXED_POINT.md, max_dimension <= 4096): v + 2^15
      // stays in [0, 2^24), so (v + 2^15) >> 16 is in [0, 255].
      static_assert(config::max_dimension <= 4096, "the stepped values' error bound needs boxes below 4096 pixels");
      const RoundedStart s = rounded_start(x0, y);
      writer.put_span_in_range(p, x0, x1, y, s.v0, s.v1, s.v2, s.d0, s.d1, s.d2);
      return;
    }
    uint32_t v[Channels], dv[Channels];
    for (int c = 0; c < Channels; ++c) {
      v[c] = ch[c].at(x0, y, xr, yr);
      dv[c] = ch[c].step();
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

}  // namespace
}  // namespace tristream::core::detail
