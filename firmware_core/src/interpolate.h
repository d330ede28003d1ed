/* SPDX-License-Identifier: MIT */
#pragma once
// Per-triangle setup and per-pixel stepping of the interpolants. Edge k of a triangle runs from
// vertex k to vertex k+1; E_k / area2 is the barycentric weight of vertex k+2 (indices mod 3).
// Every quantity is an exact function of the pixel position and the triangle, so the output
// never depends on where a tile or span starts.
#include <stddef.h>
#include <stdint.h>

#include "tuning.h"
#include "arith.h"
#include "arm/zienkiewicz_eval.h"
#include "edge.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {

// Bilinear: v(x, y) = v_ref + dvdx (x - xr) + dvdy (y - yr) in q16_16 with gradients rounded once
// per triangle; the error at a pixel is below (1 + |x - xr| + |y - yr|) / 2 units of 2^-16.
struct BilinearChannel {
  // Modulo 2^32: every use (the value at a pixel, the step) is a sum modulo 2^32, exact for a
  // covered pixel.
  uint32_t v_ref = 0;
  uint32_t dvdx = 0;
  uint32_t dvdy = 0;

  // values: q8_8 of vertices 0, 1, 2. a[k], b[k]: edge k's coefficients; e_ref[k]: edge k's exact
  // value at a reference pixel (xr, yr) near the triangle. by_area2: division by the doubled area,
  // rounded to nearest (RoundingDivider, or ShortRoundingDivider where the numerators allow).
  // EdgeValue: int64_t, or int32_t where the edge values fit (the scan path), which makes the
  // products 32 x 32 -> 64 (one multiply-accumulate each on Cortex-M4).
  template <typename Divider, typename EdgeValue>
  void setup(const int32_t* a, const int32_t* b, const EdgeValue* e_ref, const Divider& by_area2,
             const int32_t* values) {
    // E_k / area2 weighs vertex k + 2: written out, no index arithmetic per term.
    const int64_t v2 = values[2], v0 = values[0], v1 = values[1];
    const int64_t nx = v2 * a[0] + v0 * a[1] + v1 * a[2];
    const int64_t ny = v2 * b[0] + v0 * b[1] + v1 * b[2];
    const int64_t nv = v2 * e_ref[0] + v0 * e_ref[1] + v1 * e_ref[2];
    constexpr int shift = q16_16::frac_bits - q8_8::frac_bits;
    dvdx = uint32_t(by_area2(nx * (int64_t(1) << shift)));
    dvdy = uint32_t(by_area2(ny * (int64_t(1) << shift)));
    v_ref = uint32_t(by_area2(nv * (int64_t(1) << shift)));
  }
  // The same quotients from vertex 0's value, for numerators that the caller proves within
  // Mod32RoundingDivider's range (int32): with a = A 2^S and b = B 2^S (per pixel) and (ox, oy) =
  // (xr 2^S - x_0, yr 2^S - y_0) the offset of the reference pixel from vertex 0, E_k(xr, yr) =
  // E_k(P_0) + A_k ox + B_k oy, and sum v_(k+2) E_k(P_0) = v_0 area2 (edges 0 and 2 pass through
  // P_0, E_1(P_0) = area2). So 2^8 sum v e_ref / area2 = 2^8 v_0 + 2^8 t / area2 with t = ox sum v A
  // + oy sum v B, and its rounding is 2^8 v_0 + round(2^8 t / area2): two divisions of an int32
  // numerator instead of three of a 64-bit one, and no edge value at the reference pixel. The
  // coefficients sum to zero (a_2 = -a_0 - a_1), so with u = v_2 - v_1 and w = v_0 - v_1 the sums
  // are u a_0 + w a_1, u b_0 + w b_1 and t = u p + w q (VertexZeroEdges: p, q once per triangle).
  struct VertexZeroEdges {
    int32_t a0, a1, b0, b1;
    int32_t p, q;  // ox A_0 + oy B_0, ox A_1 + oy B_1
    template <int S>
    static VertexZeroEdges of(const int32_t* a, const int32_t* b, int32_t ox, int32_t oy) {
      // a and b are multiples of 2^S: the shifts are exact.
      return VertexZeroEdges{a[0], a[1], b[0], b[1], (a[0] >> S) * ox + (b[0] >> S) * oy,
                             (a[1] >> S) * ox + (b[1] >> S) * oy};
    }
  };
  TS_INLINE void setup_from_vertex0(const VertexZeroEdges& e, const Mod32RoundingDivider& by_area2,
                                                         const int32_t* values) {
    static_assert(q16_16::frac_bits - q8_8::frac_bits == 8, "Mod32RoundingDivider divides m 2^8");
    const int32_t u = values[2] - values[1], w = values[0] - values[1];
    dvdx = by_area2.small(u * e.a0 + w * e.a1);
    dvdy = by_area2.small(u * e.b0 + w * e.b1);
    v_ref = (uint32_t(values[0]) << 8) + by_area2.small(u * e.p + w * e.q);
  }
  // The same for any triangle, with a divider of int64 numerators (PreinvRoundingDivider,
  // RoundingDivider): |a|, |b| < 2^20 (detail/edge.h), so |p|, |q| < 2^21 and every product fits
  // int64; the roundings are those of setup (2^8 v_0 is a whole quotient).
  template <typename Divider>
  TS_INLINE void setup_from_vertex0(const VertexZeroEdges& e, const Divider& by_area2,
                                                         const int32_t* values) {
    constexpr int shift = q16_16::frac_bits - q8_8::frac_bits;
    const int32_t u = values[2] - values[1], w = values[0] - values[1];
    const auto sum = [](int32_t u, int32_t x, int32_t w, int32_t y) TS_INLINE {
      return (mul_s32_wide(u, x) + mul_s32_wide(w, y)) * (int64_t(1) << shift);
    };
    dvdx = uint32_t(by_area2(sum(u, e.a0, w, e.a1)));
    dvdy = uint32_t(by_area2(sum(u, e.b0, w, e.b1)));
    v_ref = (uint32_t(values[0]) << shift) + uint32_t(by_area2(sum(u, e.p, w, e.q)));
  }
  // q16_16 value at (x, y), modulo 2^32 (exact when the pixel is covered).
  uint32_t at(int32_t x, int32_t y, int32_t xr, int32_t yr) const {
    return v_ref + dvdx * uint32_t(x - xr) + dvdy * uint32_t(y - yr);
  }
  // The same at offsets (dx, dy) = (x - xr, y - yr) from the reference pixel.
  uint32_t at_offset(uint32_t dx, uint32_t dy) const { return v_ref + dvdx * dx + dvdy * dy; }
  uint32_t step() const { return dvdx; }
};

// Forward differences of a cubic along a row (ZienkiewiczChannel::setup_rows, steps_at): the
// value and its first three differences in 2^-18 grey, modulo 2^32 (a value read as int32 is
// exact whenever it fits, see ZienkiewiczChannel::max_fd_sum).
struct CubicSteps {
  uint32_t v, d1, d2, d3;  // no initializers: arrays of them are filled by steps_at, not zeroed first

  TS_INLINE void step() {
    v += d1;
    d1 += d2;
    d2 += d3;
  }
  // k steps at once: v(k) = v + k d1 + C(k,2) d2 + C(k,3) d3, and so on; exactly what k calls of
  // step() give (integer identities, modulo 2^32), for k < max_skip (the binomials fit 32 bits:
  // k (k - 1) (k - 2) < 2^30).
  static constexpr uint32_t max_skip = 1024;
  TS_CUBIC_SKIP_ATTRIBUTES void skip(uint32_t k) {
    const uint32_t k2 = k * (k - 1) / 2, k3 = k2 * (k - 2) / 3;  // k (k - 1) (k - 2) / 2 is a multiple of 3
    v += k * d1 + k2 * d2 + k3 * d3;
    d1 += k * d2 + k2 * d3;
    d2 += k * d3;
  }
};

// Whether ZienkiewiczChannel's 32-bit forms (eval32 for eval_narrow, the 32-bit expansion in
// setup: setup_narrow) are used: where a 64-bit product is not one instruction (no 128-bit type:
// Cortex-M). On 64-bit hosts the 64-bit forms are as fast and the checks that choose would only
// cost.
constexpr bool zienkiewicz_narrow_forms = !TS_USE_INT128;

// Zienkiewicz (docs/CONVENTIONS.md) as a cubic polynomial in the barycentric weights (a, b) of vertices
// 0 and 1: f = sum p[i][j] a^i b^j, coefficients in q24_8 from the vertex values and the edge
// derivatives u = edge . gradient, kept scaled by degree: s[i][j] = p[i][j] 4^(i + j), and s00 with
// rounding_bias added (an evaluation is f + 2^7 + 1: whole grey levels, rounded, by a shift).
//
// Two evaluations (docs/FIXED_POINT.md, Zienkiewicz):
// - per pixel: Horner's rule on the scaled coefficients with a and b as q2_30 weights w, each
//   step t' = s + floor(w t / 2^32) (= s + floor(weight t / 4): the scale drops by 4 a degree, so no
//   shifts; one SMMLA on Cortex-M4). eval_narrow: in 32 bits within its budget (eval32), or with
//   a 128-bit product on 64-bit hosts; eval_wide in 64 bits; the same integers (short rows, small
//   triangles, and triangles outside the forward-difference budget; see
//   zienkiewicz_fd_min_length);
// - forward differencing along a row: a and b are linear in x (steps da, db in q2_30), so f is a
//   cubic in x. setup_rows() expands, once per triangle, its forward differences
//   D1(a, b) = P(a + da, b + db) - P(a, b), D2 (the difference of D1) and D3 as polynomials in
//   (a, b) with coefficients in 2^-18 grey levels (each the exact value rounded once); steps_at()
//   evaluates P and them at a restart point in 32 bits, then a pixel costs three 32-bit
//   additions.
struct ZienkiewiczChannel {
  // The ten coefficients p in int64, unscaled (coefficients(), set_coefficients()).
  struct WideCoefficients {
    int64_t p00, p01, p02, p03, p10, p11, p12, p20, p21, p30;
  };
  // The bias in s00, in q24_8: half a grey level, so that a shift rounds to nearest, and one unit,
  // about the mean of the Horner steps' floors (below 3 units, all downward): centred, the rounding
  // meets the exact one more often (on four photographs 0.8 to 1.2 dB PSNR closer to the double
  // reference).
  static constexpr int32_t rounding_bias = (int32_t(1) << (q24_8::frac_bits - 1)) + 1;
  // The ten scaled coefficients s in int64.
  struct ScaledCoefficients {
    int64_t s00, s01, s02, s03, s10, s11, s12, s20, s21, s30;
  };
  // The scaled coefficients: in int64 where a 64-bit product is one instruction (64-bit hosts).
  // Elsewhere (Cortex-M, zienkiewicz_narrow_forms) in int32 when every one fits (40 bytes a
  // channel less of the stack, which holds three channels' for a triangle), else wide(): s30 is
  // wide_mark and all ten are in `w`, in the place of the forward-difference polynomials: such a
  // triangle is outside their budget (setup_rows), so they are never set for it. The mark in place
  // of a flag: 8 bytes a channel less (the flag's padding). An int32 coefficient is never
  // wide_mark (store sends it to `w`).
  using Scaled = wider_if<!zienkiewicz_narrow_forms, int32_t>;
  Scaled s00, s01, s02, s03, s10, s11, s12, s20, s21, s30;
  static constexpr int32_t wide_mark = INT32_MIN;
  bool wide() const { return zienkiewicz_narrow_forms && s30 == wide_mark; }

  // The forward-difference polynomials (set by setup_rows): P itself in 2^-14 grey (e = p 2^6),
  // D1 (quadratic), D2 (linear) and D3 in 2^-18 grey. The coefficients that Horner's rule
  // multiplies first (e03, e12, e21, e30, g20, g11, g02, h10, h01) are stored times 4 (by unsigned
  // shifts: the same bits), as mla_high takes them. 80 bytes, as ScaledCoefficients in the union.
  struct RowCoefficients {
    int32_t e00, e01, e02, e10, e11, e20, e03x4, e12x4, e21x4, e30x4;  // P in 2^-14 grey
    int32_t g00, g01, g10, g02x4, g11x4, g20x4;
    int32_t h00, h01x4, h10x4;
    int32_t d3;
  };
  union {
    RowCoefficients fd;    // when !wide()
    ScaledCoefficients w;  // when wide()
  };

  // The edge derivative u = edge . gradient of a vertex in q24_8 (rounded): edge vectors in
  // position_fx, gradients q19_12 (gradients[2 k], gradients[2 k + 1]: gx, gy of vertex k).
  // Inlined (-Os would call it, and the readers, once per product).
  static constexpr int derivative_shift = config::subpixel_bits + config::gradient_frac_bits - q24_8::frac_bits;
  template <typename Gradients>
  TS_INLINE static int64_t derivative(const int32_t* edge_dx, const int32_t* edge_dy,
                                                           const Gradients& gradients, int edge, int vertex) {
    constexpr int shift = derivative_shift;
    static_assert(shift >= 1, "edge derivative needs at least one bit to round away");
    return (derivative_sum(edge_dx, edge_dy, gradients, edge, vertex) + (int64_t(1) << (shift - 1))) >> shift;
  }
  // derivative before its rounding: edge . gradient in 2^-(shift + 8) grey.
  template <typename Gradients>
  TS_INLINE static int64_t derivative_sum(const int32_t* edge_dx, const int32_t* edge_dy,
                                                               const Gradients& gradients, int edge, int vertex) {
    return mul_s32_wide(edge_dx[edge], gradients[2 * vertex]) +
           mul_s32_wide(edge_dy[edge], gradients[2 * vertex + 1]);
  }

  // dx, dy: domain-space edge vectors AB, BC, CA in position_fx; values q8_8; gradients q19_12
  // (gx, gy per vertex; values[k] and gradients[j] for k < 3, j < 6: arrays, or readers of the
  // blob's bytes). Returns whether eval_narrow evaluates the coefficients: always where it is
  // exact for every triangle (narrow_always), else fits_narrow().
  template <bool Narrow = zienkiewicz_narrow_forms, typename Values, typename Gradients>
  TS_ZIENKIEWICZ_SETUP_INLINE bool setup(const int32_t* edge_dx, const int32_t* edge_dy, const Values& values,
                                         const Gradients& gradients) {
    if constexpr (Narrow) {
      if (setup_narrow(edge_dx, edge_dy, values, gradients)) return true;
    }
    if constexpr (zienkiewicz_narrow_forms) {
      return setup_wide(edge_dx, edge_dy, values, gradients);
    } else {
      return expand_wide(edge_dx, edge_dy, values, gradients);
    }
  }
  // setup's 32-bit expansion alone: true with the coefficients set when every edge derivative is
  // within max_narrow_derivative (narrow_derivatives: the coefficients are then narrow), else false
  // with nothing set (setup_wide then).
  template <typename Values, typename Gradients>
  TS_ZIENKIEWICZ_SETUP_INLINE bool setup_narrow(const int32_t* edge_dx, const int32_t* edge_dy, const Values& values,
                                                const Gradients& gradients) {
    constexpr int shift = derivative_shift;
    if constexpr (shift + 19 >= 32) {
      // (Configurations with many fraction bits.) The derivatives in int64, then tested.
      auto u = [&](int edge, int vertex) TS_INLINE {
        return derivative(edge_dx, edge_dy, gradients, edge, vertex);
      };
      const int64_t u2 = u(0, 0), u3 = u(0, 1), u5 = u(1, 1), u6 = u(1, 2), u8 = u(2, 2), u9 = u(2, 0);
      if (!narrow_derivatives(u2, u3, u5, u6, u8, u9)) return false;
      expand<int32_t>(values[0], int32_t(u2), int32_t(u3), values[1], int32_t(u5), int32_t(u6), values[2], int32_t(u8),
                      int32_t(u9));
      return true;
    }
    // derivative's rounded sum lifted by max 2^shift: u is in [-max, max) exactly when that is in
    // [0, 2 max 2^shift) (its high word 0, its low word below the bound), and u is then the low
    // word shifted, less max: no 64-bit shift or test.
    constexpr int64_t lift = (int64_t(1) << (shift - 1)) + (int64_t(max_narrow_derivative) << shift);
    uint32_t high = 0, low = 0;
    auto u = [&](int edge, int vertex) TS_INLINE {
      const int64_t d = derivative_sum(edge_dx, edge_dy, gradients, edge, vertex) + lift;
      high |= uint32_t(uint64_t(d) >> 32);
      low |= uint32_t(d);
      return int32_t(uint32_t(d) >> shift) - max_narrow_derivative;
    };
    const int32_t u2 = u(0, 0), u3 = u(0, 1);  // AB . gA, AB . gB
    const int32_t u5 = u(1, 1), u6 = u(1, 2);  // BC . gB, BC . gC
    const int32_t u8 = u(2, 2), u9 = u(2, 0);  // CA . gC, CA . gA
    if ((high | (low >> ((shift + 19) & 31))) != 0) return false;
    expand<int32_t>(values[0], u2, u3, values[1], u5, u6, values[2], u8, u9);
    return true;
  }
  // setup's 64-bit expansion out of line where 64-bit arithmetic is several instructions
  // (Cortex-M, where setup takes it only for large derivatives), the derivatives formed again
  // there: inlined into setup it would add its frame to the deepest stack and slow setup's common
  // path; called with the nine int64 inputs it would cost the caller's frame their 64 bytes.
  template <typename Values, typename Gradients>
  TS_NOINLINE bool setup_wide(const int32_t* edge_dx, const int32_t* edge_dy, const Values& values,
                                            const Gradients& gradients) {
    return expand_wide(edge_dx, edge_dy, values, gradients);
  }
  // setup_wide's body, for a caller that has it inline.
  template <typename Values, typename Gradients>
  TS_INLINE bool expand_wide(const int32_t* edge_dx, const int32_t* edge_dy, const Values& values,
                                                  const Gradients& gradients) {
    auto u = [&](int edge, int vertex) TS_INLINE {
      return derivative(edge_dx, edge_dy, gradients, edge, vertex);
    };
    expand<int64_t>(values[0], u(0, 0), u(0, 1), values[1], u(1, 1), u(1, 2), values[2], u(2, 2), u(2, 0));
    return narrow_always || fits_narrow();
  }
  // Whether every edge derivative is in [-max_narrow_derivative, max_narrow_derivative): each
  // u + max in [0, 2 max), so their bitwise or below 2 max.
  TS_INLINE static bool narrow_derivatives(int64_t u2, int64_t u3, int64_t u5, int64_t u6,
                                                                int64_t u8, int64_t u9) {
    constexpr uint64_t lift = uint64_t(max_narrow_derivative);
    auto o = [](int64_t v) { return uint64_t(v) + lift; };
    return (o(u2) | o(u3) | o(u5) | o(u6) | o(u8) | o(u9)) < 2 * lift;
  }
  // Edge derivatives (and values, below 2^16) up to this in magnitude give coefficients of at most
  // 2^23 (every sum of expand is at most 20 max |u|: p21 and p12, t = 6 u7 - k111 with |k111| <= 9
  // max |u|, plus 5 max |u|), so scaled ones within max_narrow_coefficient, formed in 32 bits.
  static constexpr int32_t max_narrow_derivative = int32_t(1) << 18;
  // The coefficients p from the vertex values u1, u4, u7 (q8_8) and the edge derivatives
  // (q24_8) in T: int64_t for any inputs, int32_t (the same integers) within max_narrow_derivative.
  template <typename T>
  TS_ZIENKIEWICZ_SETUP_INLINE void expand(T u1, T u2, T u3, T u4, T u5, T u6, T u7, T u8, T u9) {
    // Homogeneous cubic in (a, b, c) with the control values k300 = u1, k030 = u4, k003 = u7,
    // k210 = 3 u1 + u2, k201 = 3 u1 - u9, k120 = 3 u4 - u3, k021 = 3 u4 + u5, k102 = 3 u7 + u8,
    // k012 = 3 u7 - u6 and k111 below, then c = 1 - a - b, expanded and simplified (exact integer
    // identities: every sum stays far inside int64):
    // p30 = -k003 + k102 - k201 + k300, p21 = -3 k003 + k012 + 2 k102 - k111 - k201 + k210,
    // p20 = 3 k003 - 2 k102 + k201, p12 = -3 k003 + 2 k012 - k021 + k102 - k111 + k120,
    // p11 = 6 k003 - 2 k012 - 2 k102 + k111, p10 = -3 k003 + k102, p03 = -k003 + k012 - k021 + k030,
    // p02 = 3 k003 - 2 k012 + k021, p01 = -3 k003 + k012, p00 = k003.
    const T k111 = 2 * (u1 + u4 + u7) + (u2 - u3 + u5 - u6 + u8 - u9) / 2;
    const T t = 6 * u7 - k111;
    store<T>(u7, -u6, 3 * (u4 - u7) + u5 + 2 * u6, 2 * (u7 - u4) - u5 - u6, u8, 2 * (u6 - u8) - t,
             t - u3 - u5 - 2 * u6 + u8, 3 * (u1 - u7) - 2 * u8 - u9, t + u2 - u6 + 2 * u8 + u9,
             2 * (u7 - u1) + u8 + u9);
  }
  // The scaled coefficients in int64, from either layout.
  ScaledCoefficients scaled() const {
    if (wide()) return w;
    return {s00, s01, s02, s03, s10, s11, s12, s20, s21, s30};
  }
  // All ten coefficients p in int64 (from either layout), and setting them as expand does (tests).
  WideCoefficients coefficients() const {
    const ScaledCoefficients c = scaled();
    WideCoefficients p;
    p.p00 = c.s00 - rounding_bias, p.p01 = c.s01 >> 2, p.p02 = c.s02 >> 4, p.p03 = c.s03 >> 6, p.p10 = c.s10 >> 2;
    p.p11 = c.s11 >> 4, p.p12 = c.s12 >> 6, p.p20 = c.s20 >> 4, p.p21 = c.s21 >> 6, p.p30 = c.s30 >> 6;
    return p;
  }
  void set_coefficients(const WideCoefficients& c) {
    store<int64_t>(c.p00, c.p01, c.p02, c.p03, c.p10, c.p11, c.p12, c.p20, c.p21, c.p30);
  }
  // The coefficients p stored scaled, s = p 4^(i + j) (|p| < 2^52 from any inputs: |u| < 2^47; in
  // int32 within the narrow budget, |p| <= 2^23).
  template <typename T>
  TS_INLINE void store(T q00, T q01, T q02, T q03, T q10, T q11, T q12, T q20, T q21, T q30) {
    if constexpr (zienkiewicz_narrow_forms && sizeof(T) > sizeof(int32_t)) {
      // Whether each scaled coefficient fits int32 (wide_mark itself goes wide: any value that large
      // is outside both 32-bit budgets), tested on p against the int32 bounds over 4^degree: the
      // int64 products only for a wide triangle.
      auto fits = [](T q, int degree) {
        return uint32_t(q > (T(wide_mark) >> (2 * degree)) && q <= (T(INT32_MAX) >> (2 * degree)));
      };
      if (!(fits(q00, 0) & fits(q00 + rounding_bias, 0) & fits(q01, 1) & fits(q02, 2) & fits(q03, 3) & fits(q10, 1) &
            fits(q11, 2) & fits(q12, 3) & fits(q20, 2) & fits(q21, 3) & fits(q30, 3))) {
        w.s00 = q00 + rounding_bias, w.s01 = 4 * q01, w.s02 = 16 * q02, w.s03 = 64 * q03, w.s10 = 4 * q10;
        w.s11 = 16 * q11, w.s12 = 64 * q12, w.s20 = 16 * q20, w.s21 = 64 * q21, w.s30 = 64 * q30;
        s30 = wide_mark;
        return;
      }
      store<int32_t>(int32_t(q00), int32_t(q01), int32_t(q02), int32_t(q03), int32_t(q10), int32_t(q11), int32_t(q12),
                     int32_t(q20), int32_t(q21), int32_t(q30));
    } else {
      static_assert(!zienkiewicz_narrow_forms || max_narrow_coefficient < -int64_t(INT32_MIN),
                    "a narrow coefficient is never wide_mark");
      s30 = 64 * q30, s21 = 64 * q21, s20 = 16 * q20, s12 = 64 * q12, s11 = 16 * q11;
      s10 = 4 * q10, s03 = 64 * q03, s02 = 16 * q02, s01 = 4 * q01, s00 = q00 + rounding_bias;
    }
  }
  // A pixel's barycentric weights as horner and eval_narrow take them (of), stepped by those of the
  // steps (step: modulo 2^32 in the high word): q2_30 in uint32, or where the 128-bit product is
  // used those times 2^32 in uint64 (its high word then the step's value, no shift a pixel).
  struct Weights {
    static constexpr int shift = zienkiewicz_narrow_forms ? 0 : 32;
    using Word = wider_if<!zienkiewicz_narrow_forms, uint32_t>;
    Word a, b;
    TS_INLINE static Weights of(uint32_t a, uint32_t b) { return {Word(a) << shift, Word(b) << shift}; }
    TS_INLINE void step(const Weights& d) { a += d.a, b += d.b; }
  };
  // The q24_8 value at the barycentric weights a, b (q2_30) plus rounding_bias, unclamped (below
  // 2^60 in magnitude: |s| < 2^58).
  int64_t eval_wide(int32_t a, int32_t b) const {
    if (wide()) return horner(w, a, b);
    return horner(*this, a, b);
  }
  // eval_wide of the scaled coefficients c.s00 .. c.s30: each step s + floor(w t / 2^32), exact.
  // With a 128-bit product (64-bit hosts) the weights as W = w 2^32 and floor(w t / 2^32) the high
  // word of W t: one multiply a step, as cheap as a 64-bit product and exact for every t (so every
  // triangle takes it: narrow_always); elsewhere mul_q32.
  template <typename C>
  TS_INLINE static int64_t horner(const C& c, int32_t a, int32_t b) {
    return horner(c, Weights::of(uint32_t(a), uint32_t(b)));
  }
  template <typename C>
  TS_INLINE static int64_t horner(const C& c, Weights w) {
    using W = wider_if<!zienkiewicz_narrow_forms, int32_t>;
    const W wa = W(w.a), wb = W(w.b);
    auto h = [](W v, int64_t t, int64_t s) TS_INLINE {
      if constexpr (zienkiewicz_narrow_forms) {
        return s + mul_q32(t, v);
      } else {
        return s + mulhi_i64(v, t);
      }
    };
    const int64_t pb = h(wb, h(wb, h(wb, c.s03, c.s02), c.s01), c.s00);
    const int64_t pa = h(wa, h(wa, c.s30, h(wb, c.s21, c.s20)), h(wb, h(wb, c.s12, c.s11), c.s10));
    return h(wa, pa, pb);
  }
  // The q24_8 value (without the bias) clamped to int32.
  int32_t eval(int32_t a, int32_t b) const {
    const int64_t f = eval_wide(a, b) - rounding_bias;
    return int32_t(f > INT32_MAX ? INT32_MAX : (f < INT32_MIN ? INT32_MIN : f));
  }

  // eval_wide in 32 bits (eval32), for scaled coefficients in [-S, S), S = max_narrow_coefficient
  // (fits_narrow), and any int32 q2_30 weights (|w| <= 2^31: weights in [-2, 2)): the same steps,
  // so the same value when every partial sum fits int32. With |w| <= 2^31, |floor(w t / 2^32)| <=
  // |t| / 2 + 1, and the partial sums are then at most 13 S / 4 + 5 (narrow_eval_bound; the inner
  // sum of three terms at most 2 S + 2), below 2^31: so each step is p plus the high word of the
  // 32 x 32 -> 64 product w t (one SMMLA on Cortex-M4, against three multiplies a 64-bit product).
  static constexpr int32_t max_narrow_coefficient = int32_t(1) << 29;
  static constexpr int64_t narrow_eval_bound(int64_t s) { return 13 * s / 4 + 5; }
  // Every s in [-S, S): each s + S in [0, 2 S), so their bitwise or below 2 S.
  TS_INLINE bool fits_narrow() const {
    using U = wider_if<!zienkiewicz_narrow_forms, uint32_t>;  // as wide as the fields
    if (wide()) return false;
    auto o = [](auto c) { return U(c) + U(max_narrow_coefficient); };
    return (o(s00) | o(s01) | o(s02) | o(s03) | o(s10) | o(s11) | o(s12) | o(s20) | o(s21) | o(s30)) <
           2 * U(max_narrow_coefficient);
  }
  // Whether eval_narrow is exact for every triangle (the 128-bit form of eval_wide), so that no
  // triangle needs fits_narrow.
  static constexpr bool narrow_always = !zienkiewicz_narrow_forms;
  // The evaluation per pixel of a triangle that setup found narrow: eval_wide where it costs no
  // more (narrow_always), else eval32. The value plus rounding_bias: int32 in eval32's budget.
  using NarrowValue = wider_if<narrow_always, int32_t>;
  TS_INLINE NarrowValue eval_narrow(int32_t a, int32_t b) const {
    if constexpr (narrow_always) {
      return horner(*this, a, b);
    } else {
      return eval32(a, b);
    }
  }
  TS_INLINE NarrowValue eval_narrow(Weights w) const {
    if constexpr (narrow_always) {
      return horner(*this, w);
    } else {
      return eval32(int32_t(w.a), int32_t(w.b));
    }
  }
  TS_INLINE int32_t eval32(int32_t a, int32_t b) const {
#if TS_ARM_SMMLA
    return arm::eval32(&s00, a, b);  // the same steps in assembly (arm/zienkiewicz_eval.h)
#else
    auto h = [](int32_t w, int32_t t, int32_t s) TS_INLINE { return mla_high(w, t, s); };
    const int32_t pb = h(b, h(b, h(b, int32_t(s03), int32_t(s02)), int32_t(s01)), int32_t(s00));
    const int32_t pa = h(a, h(a, int32_t(s30), h(b, int32_t(s21), int32_t(s20))),
                         h(b, h(b, int32_t(s12), int32_t(s11)), int32_t(s10)));
    return h(a, pa, pb);
#endif
  }
  // p + the high word of the 64-bit product w t (modulo 2^32; eval_narrow's sums fit): what one
  // SMMLA computes, the instruction of eval32's and steps_at's assembly on Cortex-M4.
  TS_INLINE static int32_t mla_high(int32_t w, int32_t t, int32_t p) {
    return int32_t(uint32_t(p) + uint32_t(mulhi_s32(w, t)));
  }

  // Forward differencing (docs/FIXED_POINT.md, Zienkiewicz): values and differences in 2^-18 grey,
  // modulo 2^32, for triangles whose coefficients' magnitudes sum to below max_fd_sum (8,176 grey
  // levels: a covered value, at most that sum, is then below 2^13 grey with room for the errors,
  // so its int32 reading is exact), whose steps are those of rows of 5 pixels or more
  // (steps_fit_rows) and whose difference polynomials are within steps_at's budget (setup_rows).
  static constexpr int value_frac_bits = 18;
  static constexpr int32_t max_fd_sum = (int32_t(1) << 21) - (int32_t(1) << 12);
  // Whether the steps are within setup_rows's budget, |da|, |db| <= 2^28 + 2^26 (5/16): every
  // triangle with a row of 5 covered pixels or more (the weights at both ends are in [0, 1] up
  // to a rounding far below 2^-30 times the row's length, so 4 |da| <= 1 + that).
  static bool steps_fit_rows(int32_t da, int32_t db) {
    constexpr uint32_t limit = (uint32_t(1) << 28) + (uint32_t(1) << 26);
    return (uint32_t(da) + limit <= 2 * limit) & (uint32_t(db) + limit <= 2 * limit);
  }
  // The forward-difference polynomials for the steps da, db; false (fd then undefined) outside
  // the budget (the steps', steps_fit_rows, first). The Taylor terms along the row in 2^-38 grey (p
  // in 2^-8 times q2_30): c1 exact, c2 and c3 from floor(x w / 2^30) products (mul_q30; below 2
  // and 3 units of 2^-38 off), then each coefficient rounded once to 2^-18.
  // (The shader tests the steps once for its channels, then calls setup_rows_within.)
  TS_INLINE bool setup_rows(int32_t da, int32_t db) {
    // No row of 5 pixels or more, and the bounds below rest on the steps' budget.
    return steps_fit_rows(da, db) && setup_rows_within(da, db);
  }
  // setup_rows for steps within steps_fit_rows.
  TS_SETUP_ROWS_ATTRIBUTES bool setup_rows_within(int32_t da, int32_t db) {
    if (wide()) return false;
    // The coefficients p (exact shifts of the scaled ones).
    const auto p00 = s00 - rounding_bias, p01 = s01 >> 2, p02 = s02 >> 4, p03 = s03 >> 6, p10 = s10 >> 2,
               p11 = s11 >> 4;
    const auto p12 = s12 >> 6, p20 = s20 >> 4, p21 = s21 >> 6, p30 = s30 >> 6;
    // The sum of magnitudes below max_fd_sum: at once when every p is in [-2^17, 2^17) (ten of
    // them sum to below it; each p + 2^17 in [0, 2^18), so their bitwise or below 2^18), else
    // summed, in 32 bits after each p in [-2^21, 2^21) (implied by the sum's budget): below 2^25.
    using U = wider_if<!zienkiewicz_narrow_forms, uint32_t>;  // as wide as the coefficients
    auto within = [&](int bits) TS_INLINE {
      const U lift = U(1) << bits;
      auto o = [lift](auto c) { return U(c) + lift; };
      return (o(p00) | o(p01) | o(p02) | o(p03) | o(p10) | o(p11) | o(p12) | o(p20) | o(p21) | o(p30)) < 2 * lift;
    };
    static_assert(10 * (int64_t(1) << 17) < max_fd_sum, "ten coefficients below 2^17 sum to below max_fd_sum");
    if (!within(17)) {
      if (!within(21)) return false;
      auto mag = [](auto c) TS_INLINE { return uint32_t(c < 0 ? -c : c); };
      if (mag(p00) + mag(p01) + mag(p02) + mag(p03) + mag(p10) + mag(p11) + mag(p12) + mag(p20) + mag(p21) + mag(p30) >=
          uint32_t(max_fd_sum))
        return false;
    }
    const int32_t q01 = int32_t(p01), q02 = int32_t(p02), q03 = int32_t(p03);
    const int32_t q10 = int32_t(p10), q11 = int32_t(p11), q12 = int32_t(p12), q20 = int32_t(p20), q21 = int32_t(p21);
    const int32_t q30 = int32_t(p30);
    auto mul = [](int32_t x, int32_t y) { return mul_s32_wide(x, y); };
    // P(a + m da, b + m db) = P + c1 m + c2 m^2 + c3 m^3 with c1 = P_a da + P_b db = r00 + r10 a
    // + r01 b + r20 a^2 + r11 a b + r02 b^2 (r00 = p10 da + p01 db, r10 = 2 p20 da + p11 db, ...),
    // c2 = c2_00 + c2_10 a + c2_01 b (c2_00 = p20 da^2 + p11 da db + p02 db^2, ...), c3 = p30 da^3 +
    // p21 da^2 db + p12 da db^2 + p03 db^3; D1 = c1 + c2 + c3, D2 = 2 c2 + 6 c3, D3 = 6 c3.
    // Bounds with the sum of |p| below 2^21 and |da|, |db| below 2^28.33: every sum below 2^51
    // (g20, g02: 3 times the sum times 2^28.33), so each coefficient rounded to 2^-18 is below
    // 2^31 (no int32 wraps before the budget below).
    constexpr int down = q24_8::frac_bits + q2_30::frac_bits - value_frac_bits;
    auto round_down = [](int64_t v) { return int32_t((v + (int64_t(1) << (down - 1))) >> down); };
    // Horner's budget (steps_at): -2^26 <= g < 2^26, -2^28 <= h < 2^28 (256 and 1,024 grey
    // levels), so that every multiplicand times 4 and every partial sum fit int32 with weights a
    // little beyond [0, 1] (at most 3 |g| then 6 |g| in a sum; 3 |h|): each c + 2^k in [0, 2^(k+1)),
    // so their bitwise or below 2^(k+1). With the steps' budget the g budget implies the h budget
    // (D2's terms are the steps times D1's: |h| below 1.6 2^26); its check is kept so that steps_at's
    // bound does not rest on that derivation. Each coefficient stored as soon as it is formed (fd is
    // undefined when the budget fails), those of the cubic terms first, the products that share
    // them in a row (c3 kept for h00, g00): few values live at once (the deepest Cortex-M4 frame
    // is this one).
    constexpr uint32_t g_lift = uint32_t(1) << 26, h_lift = uint32_t(1) << 28;
    uint32_t g_or = 0, h_or = 0;
    auto x4 = [](int32_t v) { return int32_t(uint32_t(v) << 2); };
    RowCoefficients& f = fd;
    auto g = [&](int64_t sum, int32_t * to, bool lifted) TS_INLINE {
      const int32_t v = round_down(sum);
      g_or |= uint32_t(v) + g_lift;
      *to = lifted ? x4(v) : v;
    };
    auto h = [&](int64_t sum, int32_t * to, bool lifted) TS_INLINE {
      const int32_t v = round_down(sum);
      h_or |= uint32_t(v) + h_lift;
      *to = lifted ? x4(v) : v;
    };
    g(mul(3 * q30, da) + mul(q21, db), &f.g20x4, true);
    g(mul(2 * q21, da) + mul(2 * q12, db), &f.g11x4, true);
    g(mul(q12, da) + mul(3 * q03, db), &f.g02x4, true);
    const int64_t c3 =
        mul_q30(mul_q30(mul(q30, da) + mul(q21, db), da), da) + mul_q30(mul_q30(mul(q12, da) + mul(q03, db), db), db);
    f.d3 = round_down(6 * c3);
    {
      const int64_t c2_10 = mul_q30(mul(3 * q30, da) + mul(2 * q21, db), da) + mul_q30(mul(q12, db), db);
      h(2 * c2_10, &f.h10x4, true);
      g(mul(2 * q20, da) + mul(q11, db) + c2_10, &f.g10, false);
    }
    {
      const int64_t c2_01 = mul_q30(mul(q21, da) + mul(2 * q12, db), da) + mul_q30(mul(3 * q03, db), db);
      h(2 * c2_01, &f.h01x4, true);
      g(mul(q11, da) + mul(2 * q02, db) + c2_01, &f.g01, false);
    }
    {
      const int64_t c2_00 = mul_q30(mul(q20, da) + mul(q11, db), da) + mul_q30(mul(q02, db), db);
      h(2 * c2_00 + 6 * c3, &f.h00, false);
      g(mul(q10, da) + mul(q01, db) + c2_00 + c3, &f.g00, false);
    }
    if (g_or >= 2 * g_lift || h_or >= 2 * h_lift) return false;
    // P in 2^-14 grey (e = p 2^6): the ten |e| sum to below 2^27.
    constexpr int up = value_horner_frac_bits - q24_8::frac_bits;
    auto e = [](int32_t q) { return int32_t(uint32_t(q) << up); };
    f.e00 = e(int32_t(p00)), f.e01 = e(q01), f.e02 = e(q02), f.e10 = e(q10), f.e11 = e(q11), f.e20 = e(q20);
    f.e03x4 = x4(e(q03)), f.e12x4 = x4(e(q12)), f.e21x4 = x4(e(q21)), f.e30x4 = x4(e(q30));
    return true;
  }
  // The fraction bits of steps_at's value before it is shifted to value_frac_bits.
  static constexpr int value_horner_frac_bits = 14;
  // The value, D1 and D2 at weights a, b (q2_30, a covered pixel's) in 2^-18 grey by Horner's rule
  // with floor(w t / 2^30) (mla_high): the value's in 2^-14 grey (below 9 units of error from
  // its nine floors), then times 16; D1's and D2's below 5 and 2 units. D3.
  TS_INLINE CubicSteps steps_at(int32_t a, int32_t b) const {
    const RowCoefficients& r = fd;
    CubicSteps s;
    // The value's partial sums: at most the sum of the ten |e| < 2^27 (weights a little beyond
    // [0, 1]), so times 4 within int32.
#if TS_ARM_SMMLA
    // The same steps in assembly (arm/zienkiewicz_eval.h).
    int32_t v, d1, d2;
    arm::steps_at(&r.e00, a, b, &v, &d1, &d2);
    s.d1 = uint32_t(d1);
    s.d2 = uint32_t(d2);
    s.d3 = uint32_t(r.d3);
    s.v = uint32_t(v) << (value_frac_bits - value_horner_frac_bits);
#else
    auto m4 = [](int32_t w, int32_t t4, int32_t p) TS_INLINE { return mla_high(w, t4, p); };
    auto m = [](int32_t w, int32_t t, int32_t p) TS_INLINE {
      return mla_high(w, int32_t(uint32_t(t) << 2), p);
    };
    s.d1 = uint32_t(m(a, m4(a, r.g20x4, m4(b, r.g11x4, r.g10)), m(b, m4(b, r.g02x4, r.g01), r.g00)));
    s.d2 = uint32_t(m4(a, r.h10x4, m4(b, r.h01x4, r.h00)));
    s.d3 = uint32_t(r.d3);
    const int32_t pb = m(b, m(b, m4(b, r.e03x4, r.e02), r.e01), r.e00);
    const int32_t pa = m(a, m4(a, r.e30x4, m4(b, r.e21x4, r.e20)), m(b, m4(b, r.e12x4, r.e11), r.e10));
    s.v = uint32_t(m(a, pa, pb)) << (value_frac_bits - value_horner_frac_bits);
#endif
    return s;
  }
};

// The offsets at which arm/zienkiewicz_eval.h reads the coefficients (the 32-bit layout, checked
// where it is used).
#define TS_OFFSET_IS(type, base, field, bytes) (offsetof(type, field) - offsetof(type, base) == (bytes))
static_assert(!zienkiewicz_narrow_forms ||
                  (TS_OFFSET_IS(ZienkiewiczChannel, s00, s01, 4) && TS_OFFSET_IS(ZienkiewiczChannel, s00, s02, 8) &&
                  TS_OFFSET_IS(ZienkiewiczChannel, s00, s03, 12) && TS_OFFSET_IS(ZienkiewiczChannel, s00, s10, 16) &&
                  TS_OFFSET_IS(ZienkiewiczChannel, s00, s11, 20) && TS_OFFSET_IS(ZienkiewiczChannel, s00, s12, 24) &&
                  TS_OFFSET_IS(ZienkiewiczChannel, s00, s20, 28) && TS_OFFSET_IS(ZienkiewiczChannel, s00, s21, 32) &&
                  TS_OFFSET_IS(ZienkiewiczChannel, s00, s30, 36)),
              "eval32's offsets");
using ZienkiewiczRows = ZienkiewiczChannel::RowCoefficients;
static_assert(TS_OFFSET_IS(ZienkiewiczRows, e00, e01, 4) && TS_OFFSET_IS(ZienkiewiczRows, e00, e02, 8) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, e10, 12) && TS_OFFSET_IS(ZienkiewiczRows, e00, e11, 16) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, e20, 20) && TS_OFFSET_IS(ZienkiewiczRows, e00, e03x4, 24) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, e12x4, 28) && TS_OFFSET_IS(ZienkiewiczRows, e00, e21x4, 32) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, e30x4, 36) && TS_OFFSET_IS(ZienkiewiczRows, e00, g00, 40) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, g01, 44) && TS_OFFSET_IS(ZienkiewiczRows, e00, g10, 48) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, g02x4, 52) && TS_OFFSET_IS(ZienkiewiczRows, e00, g11x4, 56) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, g20x4, 60) && TS_OFFSET_IS(ZienkiewiczRows, e00, h00, 64) &&
                  TS_OFFSET_IS(ZienkiewiczRows, e00, h01x4, 68) && TS_OFFSET_IS(ZienkiewiczRows, e00, h10x4, 72) &&
                  sizeof(ZienkiewiczRows) == 80,
              "steps_at's offsets");
#undef TS_OFFSET_IS
static_assert(ZienkiewiczChannel::narrow_eval_bound(ZienkiewiczChannel::max_narrow_coefficient) <= INT32_MAX,
              "narrow evaluation: every partial sum fits int32");
static_assert(20 * 64 * int64_t(ZienkiewiczChannel::max_narrow_derivative) <=
                      ZienkiewiczChannel::max_narrow_coefficient &&
                  (int64_t(1) << 16) <= ZienkiewiczChannel::max_narrow_derivative,
              "coefficients from narrow derivatives and q8_8 values are narrow");

// Rows at least this long (the row's whole covered length, independent of tiling) of triangles
// of at least this area (pixels) are forward-differenced; other rows are evaluated pixel by pixel
// (ZienkiewiczChannel::eval_narrow, eval_wide): below these sizes the setup costs more than it
// saves.
constexpr int32_t zienkiewicz_fd_min_length = 5;
constexpr int32_t zienkiewicz_fd_min_area = 32;
constexpr int64_t zienkiewicz_fd_min_area2 = int64_t(2 * zienkiewicz_fd_min_area) << (2 * config::subpixel_bits);
// Forward differencing restarts (steps_at from the weights) every this many pixels counted from
// the row's first covered pixel.
constexpr int32_t zienkiewicz_fd_restart = 32;
// The error bound of docs/FIXED_POINT.md at m steps after a restart, in tenths of a unit of
// 2^-18 grey: the differences' errors at the restart (D1 below 6.6 units, D2 below 3.1, D3 below
// 0.6) grown by m, C(m, 2) and C(m, 3) steps, against the restart's value plus the cubic's exact
// change; the restart's value is within zienkiewicz_fd_value_bound_tenths of the cubic (nine
// floors of 2^-14). Their sum at m = R - 1 must stay below 2^-5 grey.
constexpr int64_t zienkiewicz_fd_bound_tenths(int64_t m) {
  return m * 66 + m * (m - 1) / 2 * 31 + m * (m - 1) * (m - 2) / 6 * 6;
}
constexpr int64_t zienkiewicz_fd_value_bound_tenths = 10 * 9 * 16;
static_assert(zienkiewicz_fd_value_bound_tenths + zienkiewicz_fd_bound_tenths(zienkiewicz_fd_restart - 1) <
                  (int64_t(10) << (ZienkiewiczChannel::value_frac_bits - 5)),
              "forward differencing error must stay far below the final rounding");

// One row by forward differencing, a restart chunk at a time: a, b are the weights (q2_30) at the
// row's first covered pixel xs, da, db their steps; calls chunk(n, end, steps) for the pixels
// xs + n, n = n0..n1, chunk by chunk, steps at pixel n (to be stepped with CubicSteps::step from
// there), steps[c].v channel c's value in 2^-18 grey plus `bias`. A pixel's value depends only
// on the triangle, the row and n (the chunk [n - n % R, ...] it lies in restarts from integers),
// never on n0.
template <int Channels, typename Chunk>
TS_INLINE inline void zienkiewicz_row_chunks(const ZienkiewiczChannel* ch, uint32_t a, uint32_t b,
                                                                  uint32_t da, uint32_t db, int32_t n0, int32_t n1,
                                                                  uint32_t bias, Chunk&& chunk) {
  constexpr int32_t R = zienkiewicz_fd_restart;
  static_assert(R > 0 && (R & (R - 1)) == 0 && R <= 1024, "restart interval: a power of two within CubicSteps::skip");
  int32_t n = n0;
  while (n <= n1) {
    const int32_t start = n & ~(R - 1);
    const int32_t end = start + (R - 1) < n1 ? start + (R - 1) : n1;
    const int32_t ac = int32_t(a + da * uint32_t(start)), bc = int32_t(b + db * uint32_t(start));
    CubicSteps s[Channels];
    for (int c = 0; c < Channels; ++c) {
      s[c] = ch[c].steps_at(ac, bc);
      s[c].v += bias;
      if (n > start) s[c].skip(uint32_t(n - start));
    }
    chunk(n, end, s);
    n = end + 1;
  }
}

// Barycentric weights a (vertex 0) and b (vertex 1) in q2_30, modulo 2^32, at a pixel (x, y):
// a = a_ref + dadx (x - xr) + dady (y - yr) with the weights at a reference pixel (xr, yr) and
// the steps each rounded once per triangle (no division per row). The rounding error at a pixel
// is below (1 + |x - xr| + |y - yr|) / 2 units of 2^-30; the exact weights of a covered pixel are
// in [0, 1], so the int32 reading of the modular sum is exact even when a step does not fit.
struct BarycentricStepper {
  uint32_t dadx = 0, dbdx = 0, dady = 0, dbdy = 0;
  uint32_t a_ref = 0, b_ref = 0;
  int32_t xr = 0, yr = 0;

  void setup(const Edge* e, const RoundingDivider& by_area2, int32_t x_ref, int32_t y_ref) {
    const int32_t a[3] = {int32_t(e[0].a), int32_t(e[1].a), int32_t(e[2].a)};
    const int32_t b[3] = {int32_t(e[0].b), int32_t(e[1].b), int32_t(e[2].b)};
    const int64_t e_ref[3] = {e[0].exact_at(x_ref, y_ref), e[1].exact_at(x_ref, y_ref), e[2].exact_at(x_ref, y_ref)};
    setup(a, b, e_ref, by_area2, x_ref, y_ref);
  }
  // The same from edge coefficients a[k], b[k] and exact edge values e_ref[k] at (x_ref, y_ref);
  // by_area2: RoundingDivider, or PreinvRoundingDivider where the doubled area fits it (the same
  // quotients).
  // Inlined (each divider's is called from one place, ZienkiewiczTriangle::begin_steps; out of
  // line on Cortex-M its frame would sit on top of that caller's, in the deepest stack).
  template <typename Divider>
  TS_INLINE void setup(const int32_t* a, const int32_t* b, const int64_t* e_ref,
                                            const Divider& by_area2, int32_t x_ref, int32_t y_ref) {
    constexpr int64_t one = int64_t(1) << q2_30::frac_bits;
    xr = x_ref;
    yr = y_ref;
    if constexpr (TS_SIZE) {
      // A loop: one copy of the divider's quotient (inlined). Each numerator picked in the loop,
      // not staged in an array (which would be in the deepest frame).
      uint32_t q[6];
      for (int i = 0; i < 6; ++i) {
        const int64_t n = i < 2 ? a[i + 1] : (i < 4 ? b[i - 1] : e_ref[i - 3]);
        q[i] = uint32_t(by_area2(n * one));
      }
      dadx = q[0], dbdx = q[1], dady = q[2], dbdy = q[3], a_ref = q[4], b_ref = q[5];
    } else {
      dadx = uint32_t(by_area2(a[1] * one));
      dbdx = uint32_t(by_area2(a[2] * one));
      dady = uint32_t(by_area2(b[1] * one));
      dbdy = uint32_t(by_area2(b[2] * one));
      a_ref = uint32_t(by_area2(e_ref[1] * one));
      b_ref = uint32_t(by_area2(e_ref[2] * one));
    }
  }
  // Weights at pixel (x, y) (the first covered pixel of a row: independent of tiling). Inlined
  // (-Os would call it once a row).
  TS_INLINE void at(int32_t x, int32_t y, uint32_t* a, uint32_t* b) const {
    *a = a_ref + dadx * uint32_t(x - xr) + dady * uint32_t(y - yr);
    *b = b_ref + dbdx * uint32_t(x - xr) + dbdy * uint32_t(y - yr);
  }
};

}  // namespace tristream::core::detail
