/* SPDX-License-Identifier: MIT */
#pragma once
// Rasterization of one triangle inside a clip rectangle: the scan path for small triangles
// (scan_path.h), span bounds stepped row by row for the others, explicit corners of boundary
// vertices, and the shader's begin and spans.
#include <stdint.h>

#include "scan_path.h"
#include "shader.h"
#include "triangle_view.h"
#include "tristream/blob.h"
#include "arith.h"
#include "backend.h"
#include "edge.h"
#include "portable/edges.h"
#include "sse2/edges.h"
#include "tuning.h"
#include "tristream/fixed_point.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

// An explicit corner (blob.h: a boundary vertex at a pixel's sample point): its pixel joins the
// row's span when owned, leaves it otherwise.
struct Corner {
  int32_t x, y;
  bool owned;
};

// The setup of a span-path triangle for the shader, from its edges.
inline void edge_setup(const TriangleView& tv, const Edge* e, int64_t area2, TriangleSetup* s) {
  s->xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  s->yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  TS_UNROLL_FAST
  for (int k = 0; k < 3; ++k) {
    s->a[k] = int32_t(e[k].a);
    s->b[k] = int32_t(e[k].b);
    s->e_ref[k] = e[k].exact_at(s->xr, s->yr);
  }
  s->area2 = area2;
  s->scan_path = false;
}

// Rasterizes one triangle inside `clip`, calling shader.begin once before the first span, and
// returns whether the triangle is done with the band: no pixel column right of the clip, no
// pixel row below it.
template <typename Shader>
bool rasterize(const TriangleView& tv, const Rect& clip, Shader& shader) {
  const int32_t top = position_fx::from_raw(min3(tv.y[0], tv.y[1], tv.y[2])).ceil_to_int();
  const int32_t bottom = position_fx::from_raw(max3(tv.y[0], tv.y[1], tv.y[2])).floor_to_int();
  const int32_t left = position_fx::from_raw(min3(tv.x[0], tv.x[1], tv.x[2])).ceil_to_int();
  const int32_t right = position_fx::from_raw(max3(tv.x[0], tv.x[1], tv.x[2])).floor_to_int();
  const bool done = (right < clip.x1) & (bottom < clip.y1);
  int32_t y0 = top, y1 = bottom;
  if (y0 < clip.y0) y0 = clip.y0;
  if (y1 > clip.y1 - 1) y1 = clip.y1 - 1;
  if (y0 > y1) return done;
  if (right < clip.x0 || left >= clip.x1) return done;
  // The scan path: small boxes without explicit corners, in int32.
  constexpr uint16_t any_corner = corner_explicit0 | corner_explicit0 << 1 | corner_explicit0 << 2;
  if (!(tv.flags & any_corner) && right - left < scan_max_extent && bottom - top < scan_max_extent) {
    const int32_t area2 = (tv.x[1] - tv.x[0]) * (tv.y[2] - tv.y[0]) - (tv.y[1] - tv.y[0]) * (tv.x[2] - tv.x[0]);
    if (area2 <= 0) return done;  // collapsed by down-scaling
    scan_small(tv, area2, left, right, y0, y1, clip.x0, clip.x1 - 1, shader);
    return done;
  }
  const int64_t area2 = (int64_t(tv.x[1]) - tv.x[0]) * (int64_t(tv.y[2]) - tv.y[0]) -
                        (int64_t(tv.y[1]) - tv.y[0]) * (int64_t(tv.x[2]) - tv.x[0]);
  if (area2 <= 0) return done;  // collapsed by down-scaling
  Edge edges[3];
  TS_UNROLL_FAST
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    edges[k] = make_edge(tv.x[k], tv.y[k], tv.x[n], tv.y[n], (tv.flags & (boundary_edge0 << k)) != 0);
  }
  // Rows [r0, r1] pass the horizontal edges; an owned corner on an excluded row adds that row.
  int32_t r0 = y0, r1 = y1;
  restrict_rows(edges, &r0, &r1);
  Corner corners[3];
  int corner_count = 0;
  int32_t first = r0, last = r1;
  TS_UNROLL_FAST
  for (int k = 0; k < 3; ++k) {
    if (!(tv.flags & (corner_explicit0 << k))) continue;
    const position_fx cx = position_fx::from_raw(tv.x[k]), cy = position_fx::from_raw(tv.y[k]);
    if (!cx.is_integer() || !cy.is_integer()) continue;
    const Corner c{cx.floor_to_int(), cy.floor_to_int(), (tv.flags & (corner_owned0 << k)) != 0};
    corners[corner_count++] = c;
    if (c.owned && c.y >= y0 && c.y <= y1) {
      first = c.y < first ? c.y : first;
      last = c.y > last ? c.y : last;
    }
  }
  if (first > last) return done;
  backend::RowSpans spans;  // portable/edges.h, sse2/edges.h
  spans.init(edges, tv.y, first);
  bool started = false;
  for (int32_t y = first; y <= last; ++y, spans.next_row()) {
    int32_t xs = 1, xe = 0;
    spans.begin_row(y);
    if (y >= r0 && y <= r1) spans.span(y, &xs, &xe);
    for (int k = 0; k < corner_count; ++k) {
      const Corner& c = corners[k];
      if (c.y != y) continue;
      if (c.owned) {
        if (xs > xe) {
          xs = xe = c.x;
        } else {
          xs = c.x < xs ? c.x : xs;
          xe = c.x > xe ? c.x : xe;
        }
      } else if (xs == c.x) {
        ++xs;
      } else if (xe == c.x) {
        --xe;
      }
    }
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
  return done;
}

}  // namespace
}  // namespace tristream::core::detail
