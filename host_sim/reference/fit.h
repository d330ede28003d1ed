/* SPDX-License-Identifier: MIT */
#pragma once
// Where the picture lies in an output of another shape (docs/CONVENTIONS.md, "Fitting"), in
// integers: the same layout as the core's (firmware_core/src/output_mapping.h, fit_mapping).
#include <cstdint>

namespace tristream {

enum class Fit { stretch, inside, fill };

struct FitLayout {
  // One scale for both axes: n / d output pixels per domain unit (stretch: 0, each axis corner to corner).
  std::int64_t n = 0, d = 0;
  // Output pixel of the domain point (0, 0) (negative where a fill crops) and the picture's pixel
  // box from there: the pixels whose sample points lie in [0, W-1] x [0, H-1].
  std::int64_t x0 = 0, y0 = 0, width = 0, height = 0;
};

// For a w x h domain and an out_w x out_h output (sides at least 2). inside and fill scale by the
// smaller resp. larger of (W'-1) / (W-1) and (H'-1) / (H-1) (x on a tie); along each axis the picture
// has e + 1 pixels, e = floor((D-1) n / d), and starts at floor((D'-1 - e) / 2).
inline FitLayout fit_layout(std::int64_t w, std::int64_t h, std::int64_t out_w, std::int64_t out_h, Fit fit) {
  FitLayout f;
  if (fit == Fit::stretch) {
    f.width = out_w;
    f.height = out_h;
    return f;
  }
  const std::int64_t nx = out_w - 1, dx = w - 1, ny = out_h - 1, dy = h - 1;
  const bool by_x = fit == Fit::inside ? nx * dy <= ny * dx : nx * dy >= ny * dx;
  f.n = by_x ? nx : ny;
  f.d = by_x ? dx : dy;
  const std::int64_t ex = dx * f.n / f.d, ey = dy * f.n / f.d;
  auto floor_half = [](std::int64_t a) { return a >= 0 ? a / 2 : -((1 - a) / 2); };
  f.x0 = floor_half(nx - ex);
  f.y0 = floor_half(ny - ey);
  f.width = ex + 1;
  f.height = ey + 1;
  return f;
}

}  // namespace tristream
