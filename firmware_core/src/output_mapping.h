/* SPDX-License-Identifier: MIT */
#pragma once
// The mapping of domain positions to output positions (docs/CONVENTIONS.md, "Fitting"): a scale
// per axis, rounded in position_fx, plus a shift by whole output pixels.
#include <stdint.h>

#include "arith.h"
#include "tristream/config.h"
#include "tuning.h"
#include "tristream/render_params.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

// Domain position_fx -> drawing position_fx: v' = floor((v n + r + 2^S k d) / d) per axis, that is
// the position scaled by n / d and rounded to nearest (r = floor(d / 2); see fit_layout for the one
// exception), plus k >= 0 whole pixels: the picture's offset o in the output plus the frame's shift
// s (FramePlan: the core draws at output positions + s, s >= -o, so that no drawing position is
// negative). Raw positions are at most 65536, n, d below 2^12 (max_dimension) and k below 2^12,
// so the numerator is below 2^29: unsigned 32-bit arithmetic, one hardware division on Cortex-M4
// (64-bit division is a library call there), and the shift costs nothing.
// Where a division is slow (tuning::divides_fast false) each axis's divisor comes with its 32-bit
// reciprocal, floor((2^32 - 1) / d): a quotient of a numerator below 2^31 is then a multiply-high
// and one correction (as Mod32RoundingDivider's). Elsewhere nothing.
template <bool Divides>
struct MappingReciprocals {
  uint32_t x = 0, y = 0;
  void set(uint32_t dx, uint32_t dy) {
    x = 0xFFFFFFFFu / dx;
    y = 0xFFFFFFFFu / dy;
  }
  uint32_t of_x() const { return x; }
  uint32_t of_y() const { return y; }
};
template <>
struct MappingReciprocals<true> {
  void set(uint32_t, uint32_t) {}
  uint32_t of_x() const { return 0; }
  uint32_t of_y() const { return 0; }
};

struct Mapping {
  uint32_t nx = 1, dx = 1, ny = 1, dy = 1;
  uint32_t bx = 0, by = 0;  // r + 2^S k d
  bool identity = true;     // v' = v on both axes (n = d, k = 0)
  [[no_unique_address]] MappingReciprocals<tuning::divides_fast> inv;

  // Always inlined (a few instructions, used per vertex position): -Os would call them.
  TS_INLINE int32_t x(int32_t v) const {
    return identity ? v : int32_t(divide(uint32_t(v) * nx + bx, dx, inv.of_x()));
  }
  TS_INLINE int32_t y(int32_t v) const {
    return identity ? v : int32_t(divide(uint32_t(v) * ny + by, dy, inv.of_y()));
  }
  // The reciprocals where they are kept.
  void set_reciprocals() { inv.set(dx, dy); }
  // floor(num / d) for num below 2^29 (the bound below).
  TS_INLINE static uint32_t divide(uint32_t num, uint32_t d, uint32_t inv) {
    if constexpr (tuning::divides_fast) {
      return num / d;
    } else {
      return divide_slowly(num, d, inv);
    }
  }
  // Out of line: its 16-bit products (ARMv6-M) at every mapped coordinate would crowd the
  // triangle loads of the identity mapping too.
  TS_NOINLINE static uint32_t divide_slowly(uint32_t num, uint32_t d, uint32_t inv) {
    uint32_t unused;
    return divide_by_reciprocal(num, d, inv, &unused);
  }
  // The smallest raw v >= 0 whose mapped y is at least t >= 0: floor((v n + b) / d) >= t exactly
  // when v n >= t d - b (also for the identity: n = d, b < d). t is below 2^18 and d below 2^12.
  int32_t first_y_at_least(int32_t t) const {
    const int32_t need = t * int32_t(dy) - int32_t(by);
    return need <= 0 ? 0 : (need + int32_t(ny) - 1) / int32_t(ny);
  }
};
static_assert(uint64_t(65536) * (config::max_dimension - 1) + config::max_dimension / 2 +
                      (uint64_t(config::max_dimension) << config::subpixel_bits) * (config::max_dimension - 1) <
                  (uint64_t(1) << 32),
              "mapped positions must be computed in 32 bits");

// floor(a / 2) for any sign.
constexpr int32_t floor_half(int32_t a) { return (a - (a < 0)) / 2; }

// Where the picture lies in the output, in integers (docs/CONVENTIONS.md "Fitting"): the scale
// n / d per axis, the output pixel o of the domain point (0, 0) (negative where a fill crops) and
// the rounding constant r, for a w x h domain and an out_w x out_h output (all in [2,
// max_dimension]). Stretch maps each axis corner to corner (o = 0). inside and fill take one scale
// for both axes, that of the axis with the smaller (inside) or larger (fill) ratio (W'-1) / (W-1)
// against (H'-1) / (H-1), x on a tie; along an axis the picture then spans the pixels o .. o + e,
// e = floor((D-1) n / d), o = floor((D'-1 - e) / 2): centred, an odd border's extra pixel on the
// right or at the bottom, an odd crop's on the left or at the top. r = min(floor(d / 2), g - 1) with
// g = 2^S ((e + 1) d - (D-1) n) >= 2^S: rounding to nearest, unless that would carry the domain's far
// edge (D-1) 2^S onto the centre of pixel o + e + 1, which its exact position (D-1) n / d does not
// reach; then r is lowered just enough. The picture's pixels are then exactly those whose sample
// points lie in the domain's rectangle. The stretch's far edge is exact (e = n): r = floor(d / 2).
struct FitLayout {
  uint32_t nx, dx, ny, dy;
  int32_t ox, oy;
  uint32_t rx, ry;
};

// The rounding constant of an axis whose domain side is D = side + 1 pixels.
inline uint32_t far_edge_rounding(uint32_t side, uint32_t n, uint32_t d) {
  const uint32_t e = side * n / d;  // below 2^24
  const uint32_t gap = ((e + 1) * d - side * n) << config::subpixel_bits;
  return d / 2 < gap - 1 ? d / 2 : gap - 1;
}

inline FitLayout fit_layout(int32_t w, int32_t h, int32_t out_w, int32_t out_h, Fit fit) {
  const uint32_t nx = uint32_t(out_w - 1), dx = uint32_t(w - 1), ny = uint32_t(out_h - 1), dy = uint32_t(h - 1);
  if (fit == Fit::stretch) return FitLayout{nx, dx, ny, dy, 0, 0, dx / 2, dy / 2};
  const bool by_x = fit == Fit::inside ? nx * dy <= ny * dx : nx * dy >= ny * dx;  // below 2^24
  const uint32_t n = by_x ? nx : ny, d = by_x ? dx : dy;
  const int32_t ex = int32_t(dx * n / d), ey = int32_t(dy * n / d);
  return FitLayout{n, d, n, d, floor_half(int32_t(nx) - ex), floor_half(int32_t(ny) - ey),
                   far_edge_rounding(dx, n, d), far_edge_rounding(dy, n, d)};
}

// The mapping of a layout drawn at output positions + (sx, sy) (sx >= -ox, sy >= -oy).
inline Mapping drawing_mapping(const FitLayout& f, int32_t sx, int32_t sy) {
  constexpr uint32_t one = 1u << config::subpixel_bits;
  const uint32_t kx = uint32_t(f.ox + sx), ky = uint32_t(f.oy + sy);
  Mapping m{f.nx, f.dx, f.ny, f.dy, f.rx + one * kx * f.dx, f.ry + one * ky * f.dy,
            f.nx == f.dx && f.ny == f.dy && kx == 0 && ky == 0, {}};
  m.set_reciprocals();
  return m;
}

}  // namespace
}  // namespace tristream::core::detail
