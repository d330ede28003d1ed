/* SPDX-License-Identifier: MIT */
#pragma once
// A clipped triangle's rows with SSE2 (rasterize.h has the interface): small triangles by the
// scan path (scan_path.h: a row's columns as a mask of edge tests in lanes), the others by the
// span bounds of their three edges in lanes (edges.h), explicit corners (corners.h) on both.
#include <stdint.h>

#include "../tuning.h"
#if TS_USE_SSE2
#include "../arith.h"
#include "../corners.h"
#include "../edge.h"
#include "../scan_path.h"
#include "../shader.h"
#include "../triangle_view.h"
#include "edges.h"
#include "tristream/blob.h"
#include "tristream/fixed_point.h"
#include "tristream/tile.h"

namespace tristream::core::detail::sse2 {
namespace {

// The setup of a span-path triangle for the shader, from its edges.
inline void edge_setup(const TriangleView& tv, const Edge* e, int64_t area2, TriangleSetup* s) {
  s->xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  s->yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  for (int k = 0; k < 3; ++k) {
    s->a[k] = int32_t(e[k].a);
    s->b[k] = int32_t(e[k].b);
    s->e_ref[k] = e[k].exact_at(s->xr, s->yr);
  }
  s->area2 = area2;
  s->small_box = false;
}

// Always inlined into rasterize: as a call, its pixel box goes through memory (x86-64 bilinear at
// 20,000 triangles: 2 % more instructions).
template <typename Shader>
TS_INLINE inline void rasterize_clipped(const TriangleView& tv, const Rect& clip, const PixelBox& box, Shader& shader) {
  const int32_t y0 = box.y0, y1 = box.y1;
  // The scan path: small boxes without explicit corners, in int32.
  constexpr uint16_t any_corner = corner_explicit0 | corner_explicit0 << 1 | corner_explicit0 << 2;
  if (!(tv.flags & any_corner) && box.right - box.left < scan_max_extent && box.bottom - box.top < scan_max_extent) {
    const int32_t area2 = (tv.x[1] - tv.x[0]) * (tv.y[2] - tv.y[0]) - (tv.y[1] - tv.y[0]) * (tv.x[2] - tv.x[0]);
    if (area2 <= 0) return;  // collapsed by down-scaling
    scan_small(tv, area2, box.left, box.right, y0, y1, clip.x0, clip.x1 - 1, shader);
    return;
  }
  const int64_t area2 = (int64_t(tv.x[1]) - tv.x[0]) * (int64_t(tv.y[2]) - tv.y[0]) -
                        (int64_t(tv.y[1]) - tv.y[0]) * (int64_t(tv.x[2]) - tv.x[0]);
  if (area2 <= 0) return;  // collapsed by down-scaling
  Edge edges[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    edges[k] = make_edge(tv.x[k], tv.y[k], tv.x[n], tv.y[n], (tv.flags & (boundary_edge0 << k)) != 0);
  }
  // Rows [r0, r1] pass the horizontal edges; an owned corner on an excluded row adds that row.
  int32_t r0 = y0, r1 = y1;
  restrict_rows(edges, &r0, &r1);
  Corners corners;
  int32_t first = r0, last = r1;
  corners.collect(tv, y0, y1, &first, &last);
  if (first > last) return;
  RowSpans spans;
  spans.init(edges, tv.y, first);
  bool started = false;
  for (int32_t y = first; y <= last; ++y, spans.next_row()) {
    int32_t xs = 1, xe = 0;
    spans.begin_row(y);
    if (y >= r0 && y <= r1) spans.span(y, &xs, &xe);
    corners.apply(y, &xs, &xe);
    if (xs > xe) continue;
    const int32_t cs = xs > clip.x0 ? xs : clip.x0;
    const int32_t ce = xe < clip.x1 - 1 ? xe : clip.x1 - 1;
    if (cs > ce) continue;
    if (!started) {
      TriangleSetup s;
      edge_setup(tv, edges, area2, &s);
      shader.begin(tv, s);
      started = true;
    }
    shader.span(y, xs, xe, cs, ce);
  }
}

}  // namespace
}  // namespace tristream::core::detail::sse2
#endif
