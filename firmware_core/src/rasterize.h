/* SPDX-License-Identifier: MIT */
#pragma once
// Rasterization of one triangle inside a clip rectangle: its pixel box and the rows the clip
// leaves, then the platform's rows (backend::rasterize_clipped: portable/rasterize.h,
// sse2/rasterize.h), which call the shader's begin once before the first covered pixel of the
// clip and then draw the covered columns of each row (shader.h).
#include <stdint.h>

#include "arith.h"
#include "backend.h"
#include "pixel_box.h"
#include "portable/rasterize.h"
#include "sse2/rasterize.h"
#include "triangle_view.h"
#include "tristream/fixed_point.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

// Rasterizes one triangle inside `clip` and returns whether the triangle is done with the band: no
// pixel column right of the clip, no pixel row below it.
template <typename Shader>
bool rasterize(const TriangleView& tv, const Rect& clip, Shader& shader) {
  PixelBox box;
  box.top = position_fx::from_raw(min3(tv.y[0], tv.y[1], tv.y[2])).ceil_to_int();
  box.bottom = position_fx::from_raw(max3(tv.y[0], tv.y[1], tv.y[2])).floor_to_int();
  box.left = position_fx::from_raw(min3(tv.x[0], tv.x[1], tv.x[2])).ceil_to_int();
  box.right = position_fx::from_raw(max3(tv.x[0], tv.x[1], tv.x[2])).floor_to_int();
  const bool done = (box.right < clip.x1) & (box.bottom < clip.y1);
  box.y0 = box.top > clip.y0 ? box.top : clip.y0;
  box.y1 = box.bottom < clip.y1 - 1 ? box.bottom : clip.y1 - 1;
  if (box.y0 > box.y1) return done;
  if (box.right < clip.x0 || box.left >= clip.x1) return done;
  backend::rasterize_clipped(tv, clip, box, shader);
  return done;
}

}  // namespace
}  // namespace tristream::core::detail
