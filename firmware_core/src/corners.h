/* SPDX-License-Identifier: MIT */
#pragma once
// Explicit corners (blob.h: a boundary vertex at a pixel's sample point): its pixel joins the row's
// span when the triangle owns it, leaves it otherwise. Every raster path applies them the same way.
#include <stdint.h>

#include "triangle_view.h"
#include "tristream/blob.h"
#include "tristream/fixed_point.h"
#include "tuning.h"

namespace tristream::core::detail {
namespace {

struct Corners {
  struct Corner {
    int32_t x, y;
    bool owned;
  };
  Corner c[3];
  int count = 0;

  // tv's explicit corners on sample points; [*first, *last] (rows) widened to the owned ones
  // within rows [y0, y1].
  void collect(const TriangleView& tv, int32_t y0, int32_t y1, int32_t* first, int32_t* last) {
    TS_UNROLL_FAST
    for (int k = 0; k < 3; ++k) {
      if (!(tv.flags & (corner_explicit0 << k))) continue;
      const position_fx cx = position_fx::from_raw(tv.x[k]), cy = position_fx::from_raw(tv.y[k]);
      if (!cx.is_integer() || !cy.is_integer()) continue;
      const Corner n{cx.floor_to_int(), cy.floor_to_int(), (tv.flags & (corner_owned0 << k)) != 0};
      c[count++] = n;
      if (n.owned && n.y >= y0 && n.y <= y1) {
        *first = n.y < *first ? n.y : *first;
        *last = n.y > *last ? n.y : *last;
      }
    }
  }
  // Row y's covered columns [*xs, *xe] (empty when *xs > *xe) with the corners on that row.
  void apply(int32_t y, int32_t* xs, int32_t* xe) const {
    for (int k = 0; k < count; ++k)
      if (c[k].y == y) apply_corner(c[k], xs, xe);
  }
  // The same with corner n (on the row of [*xs, *xe]).
  static void apply_corner(const Corner& n, int32_t* xs, int32_t* xe) {
    if (n.owned) {
      if (*xs > *xe) {
        *xs = *xe = n.x;
      } else {
        *xs = n.x < *xs ? n.x : *xs;
        *xe = n.x > *xe ? n.x : *xe;
      }
    } else if (*xs == n.x) {
      ++*xs;
    } else if (*xe == n.x) {
      --*xe;
    }
  }
};

}  // namespace
}  // namespace tristream::core::detail
