#pragma once
// Per-triangle setup and per-pixel stepping of the interpolants. Edge k of a triangle runs from
// vertex k to vertex k+1; E_k / area2 is the barycentric weight of vertex k+2 (indices mod 3).
// Every quantity is an exact function of the pixel position and the triangle, so the output
// never depends on where a tile or span starts.
#include <stdint.h>

#include "tristream/fixed_point.h"
#include "tristream/detail/arith.h"
#include "tristream/detail/edge.h"

namespace tristream::core::detail {

// Bilinear: v(x, y) = v_ref + dvdx (x - xr) + dvdy (y - yr) in q16_16 with gradients rounded once
// per triangle; the error at a pixel is below (1 + |x - xr| + |y - yr|) / 2 units of 2^-16.
struct BilinearChannel {
  int64_t v_ref = 0;
  int64_t dvdx = 0;
  int64_t dvdy = 0;

  // values: q8_8 of vertices 0, 1, 2. e_ref[k]: edge k's exact value at a reference pixel
  // (xr, yr) near the triangle. by_area2: division by the doubled area, rounded to nearest.
  void setup(const Edge* e, const int64_t* e_ref, const RoundingDivider& by_area2, const int32_t* values) {
    int64_t nx = 0, ny = 0, nv = 0;
    for (int k = 0; k < 3; ++k) {
      const int64_t v = values[(k + 2) % 3];
      nx += v * e[k].a;
      ny += v * e[k].b;
      nv += v * e_ref[k];
    }
    constexpr int shift = q16_16::frac_bits - q8_8::frac_bits;
    dvdx = by_area2(nx * (int64_t(1) << shift));
    dvdy = by_area2(ny * (int64_t(1) << shift));
    v_ref = by_area2(nv * (int64_t(1) << shift));
  }
  // q16_16 value at (x, y), modulo 2^32 (exact when the pixel is covered).
  uint32_t at(int32_t x, int32_t y, int32_t xr, int32_t yr) const {
    return uint32_t(v_ref) + uint32_t(dvdx) * uint32_t(x - xr) + uint32_t(dvdy) * uint32_t(y - yr);
  }
  uint32_t step() const { return uint32_t(dvdx); }
};

// Zienkiewicz (NOTES.md 3.2) as a cubic polynomial in the barycentric weights (a, b) of vertices
// 0 and 1: f = sum p[i][j] a^i b^j, coefficients in q24_8 from the vertex values and the edge
// derivatives u = edge . gradient, evaluated by Horner's rule with a, b in q17_15.
struct ZienkiewiczChannel {
  int64_t p00, p01, p02, p03, p10, p11, p12, p20, p21, p30;

  // dx, dy: domain-space edge vectors AB, BC, CA in position_fx; values q8_8; gradients q19_12
  // (gx, gy per vertex).
  void setup(const int32_t* edge_dx, const int32_t* edge_dy, const int32_t* values, const int32_t* gradients) {
    constexpr int shift = config::subpixel_bits + config::gradient_frac_bits - q24_8::frac_bits;
    static_assert(shift >= 1, "edge derivative needs at least one bit to round away");
    auto dot = [&](int edge, int vertex) {
      const int64_t d = int64_t(edge_dx[edge]) * gradients[2 * vertex] + int64_t(edge_dy[edge]) * gradients[2 * vertex + 1];
      return (d + (int64_t(1) << (shift - 1))) >> shift;
    };
    const int64_t u1 = values[0], u4 = values[1], u7 = values[2];
    const int64_t u2 = dot(0, 0), u3 = dot(0, 1);  // AB . gA, AB . gB
    const int64_t u5 = dot(1, 1), u6 = dot(1, 2);  // BC . gB, BC . gC
    const int64_t u8 = dot(2, 2), u9 = dot(2, 0);  // CA . gC, CA . gA
    // Homogeneous cubic in (a, b, c), then c = 1 - a - b.
    const int64_t k300 = u1, k030 = u4, k003 = u7;
    const int64_t k210 = 3 * u1 + u2, k201 = 3 * u1 - u9;
    const int64_t k120 = 3 * u4 - u3, k021 = 3 * u4 + u5;
    const int64_t k102 = 3 * u7 + u8, k012 = 3 * u7 - u6;
    const int64_t k111 = 2 * (u1 + u4 + u7) + (u2 - u3 + u5 - u6 + u8 - u9) / 2;
    p30 = -k003 + k102 - k201 + k300;
    p21 = -3 * k003 + k012 + 2 * k102 - k111 - k201 + k210;
    p20 = 3 * k003 - 2 * k102 + k201;
    p12 = -3 * k003 + 2 * k012 - k021 + k102 - k111 + k120;
    p11 = 6 * k003 - 2 * k012 - 2 * k102 + k111;
    p10 = -3 * k003 + k102;
    p03 = -k003 + k012 - k021 + k030;
    p02 = 3 * k003 - 2 * k012 + k021;
    p01 = -3 * k003 + k012;
    p00 = k003;
  }
  // q24_8 value at barycentric weights a, b (q17_15).
  int32_t eval(int64_t a, int64_t b) const {
    constexpr int s = q17_15::frac_bits;
    const int64_t pb = p00 + ((b * (p01 + ((b * (p02 + ((b * p03) >> s))) >> s))) >> s);
    const int64_t pa = p10 + ((b * (p11 + ((b * p12) >> s))) >> s) +
                       ((a * (p20 + ((b * p21) >> s) + ((a * p30) >> s))) >> s);
    const int64_t f = pb + ((a * pa) >> s);
    return int32_t(f > INT32_MAX ? INT32_MAX : (f < INT32_MIN ? INT32_MIN : f));
  }
};

// Barycentric weights a (vertex 0) and b (vertex 1) in q2_30 along a row, modulo 2^32.
struct BarycentricStepper {
  uint32_t dadx = 0, dbdx = 0;  // per triangle

  void setup(const Edge* e, const RoundingDivider& by_area2) {
    constexpr int64_t one = int64_t(1) << q2_30::frac_bits;
    dadx = uint32_t(by_area2(e[1].a * one));
    dbdx = uint32_t(by_area2(e[2].a * one));
  }
  // Weights at pixel (x, y), the first covered pixel of its row (so independent of tiling).
  static void at(const Edge* e, const RoundingDivider& by_area2, int32_t x, int32_t y, uint32_t* a, uint32_t* b) {
    constexpr int64_t one = int64_t(1) << q2_30::frac_bits;
    *a = uint32_t(by_area2(e[1].exact_at(x, y) * one));
    *b = uint32_t(by_area2(e[2].exact_at(x, y) * one));
  }
};

}  // namespace tristream::core::detail
