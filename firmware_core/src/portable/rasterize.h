/* SPDX-License-Identifier: MIT */
#pragma once
// A clipped triangle's rows in plain C++ (rasterize.h has the interface), the form of every target
// without SSE2. Small triangles without explicit corners take the scan path (scan_path.h: a row's
// columns by testing the box's columns, drawn row by row). For the others the covered columns of
// up to a chunk of rows (row_bounds.h: RowChunk) go into a table, from two exact bounds a row (row_bounds.h), the rows the
// horizontal edges exclude emptied and the explicit corners applied (corners.h); then the shader
// draws the table's rows, with its own state in registers for the whole table.
#include <stdint.h>

#include "../arith.h"
#include "../corners.h"
#include "../edge.h"
#include "../pixel_box.h"
#include "../row_bounds.h"
#include "../scan_path.h"
#include "../shader.h"
#include "../triangle_view.h"
#include "../tuning.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#include "tristream/fixed_point.h"
#include "tristream/tile.h"

namespace tristream::core::detail::portable {
namespace {

// Edge values in a box below 64 pixels each way fit int32 (e_ref32 of small boxes): |E| < 2 (64 2^S)^2.
static_assert(scan_max_extent <= 62 &&
                  2 * (int64_t(64) << config::subpixel_bits) * (int64_t(64) << config::subpixel_bits) < (int64_t(1) << 31),
              "the edge values of small boxes must fit int32");

// The shader's set-up of a triangle (shader.h): edge coefficients, the reference pixel and, where
// the shader reads them, the exact edge values there (in int64: for boxes below scan_max_extent
// pixels they fit int32, scan_path.h's bound).
template <typename Shader>
inline void row_setup(const TriangleView& tv, int64_t area2, bool small_box, TriangleSetup* s) {
  constexpr int S = config::subpixel_bits;
  const int32_t xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  const int32_t yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  s->xr = xr;
  s->yr = yr;
  s->area2 = area2;
  s->small_box = small_box;
  const unsigned reads =
      small_box ? ERefsRead<Shader>::value : (LargeERefRead<Shader>::of(area2) ? scan_e_ref64 : 0u);
  TS_UNROLL_FAST
  for (int k = 0; k < 3; ++k) {
    const int n = k == 2 ? 0 : k + 1;
    const int32_t dx = tv.x[n] - tv.x[k], dy = tv.y[n] - tv.y[k];
    s->a[k] = -dy * (1 << S);
    s->b[k] = dx * (1 << S);
    if (reads != 0) {
      const int64_t e = int64_t(-dy) * (xr * (1 << S) - tv.x[k]) + int64_t(dx) * (yr * (1 << S) - tv.y[k]);
      if (reads & scan_e_ref32) s->e_ref32[k] = int32_t(e);
      if (reads & scan_e_ref64) s->e_ref[k] = e;
    }
  }
}

// The rows [first, last] of a horizontal edge's side: an edge with dy == 0 at y = Py (raw) covers
// 2^S y - Py >= bias (dx > 0, rows below it) or <= -bias (dx < 0, rows above), E = dx (2^S y - Py).
inline void restrict_to_horizontal_edges(const TriangleView& tv, int32_t* first, int32_t* last) {
  TS_UNROLL_FAST
  for (int k = 0; k < 3; ++k) {
    const int n = k == 2 ? 0 : k + 1;
    if (tv.y[n] != tv.y[k]) continue;
    const int32_t dx = tv.x[n] - tv.x[k];
    const int32_t bias = inclusive_edge(dx, int32_t(0), (tv.flags & (boundary_edge0 << k)) != 0) ? 0 : 1;
    if (dx > 0) {
      const int32_t lo = position_fx::from_raw(tv.y[k] + bias).ceil_to_int();
      *first = lo > *first ? lo : *first;
    } else {
      const int32_t hi = position_fx::from_raw(tv.y[k] - bias).floor_to_int();
      *last = hi < *last ? hi : *last;
    }
  }
}

// The rows of the table rows[0 .. n - 1] (rows y .. y + n - 1) with pixels in columns [cx0, cx1]:
// by the shader's rows where it has one (DrawsRows), else by span a row.
template <typename Shader>
TS_INLINE inline void draw_rows(Shader& shader, const RowSpan* rows, int32_t y, int32_t n, int32_t cx0, int32_t cx1) {
  if constexpr (DrawsRows<Shader>::value) {
    shader.rows(rows, y, n, cx0, cx1);
  } else {
    for (int32_t j = 0; j < n; ++j) {
      const int32_t cs = max2(rows[j].xs, cx0), ce = min2(rows[j].xe, cx1);
      if (cs <= ce) shader.span(y + j, rows[j].xs, rows[j].xe, cs, ce);
    }
  }
}

// The scan path's boxes: below this many pixels each way. Its column walk costs per tested column
// and row, the row bounds' set-up (two or three divided bounds) per triangle: on the Cortex-M4
// bench the walk costs less only below about 8 pixels (kodim23 and the 40,000-triangle grid).
constexpr int32_t scan_path_extent = 8;
static_assert(scan_path_extent <= scan_max_extent, "scan-path boxes are small boxes (shader.h)");

template <typename Shader>
void rasterize_clipped(const TriangleView& tv, const Rect& clip, const PixelBox& box, Shader& shader) {
  // The scan path: small boxes without explicit corners, in int32.
  constexpr uint16_t any_corner = corner_explicit0 | corner_explicit0 << 1 | corner_explicit0 << 2;
  if (!(tv.flags & any_corner) && box.right - box.left < scan_path_extent && box.bottom - box.top < scan_path_extent) {
    const int32_t area2 = (tv.x[1] - tv.x[0]) * (tv.y[2] - tv.y[0]) - (tv.y[1] - tv.y[0]) * (tv.x[2] - tv.x[0]);
    if (area2 <= 0) return;  // collapsed by down-scaling
    scan_small(tv, area2, box.left, box.right, box.y0, box.y1, clip.x0, clip.x1 - 1, shader);
    return;
  }
  const int64_t area2 = (int64_t(tv.x[1]) - tv.x[0]) * (int64_t(tv.y[2]) - tv.y[0]) -
                        (int64_t(tv.y[1]) - tv.y[0]) * (int64_t(tv.x[2]) - tv.x[0]);
  if (area2 <= 0) return;  // collapsed by down-scaling
  // Rows [r0, r1] pass the horizontal edges; an owned corner on an excluded row adds that row.
  int32_t r0 = box.y0, r1 = box.y1;
  restrict_to_horizontal_edges(tv, &r0, &r1);
  Corners corners;
  int32_t first = r0, last = r1;
  corners.collect(tv, box.y0, box.y1, &first, &last);
  if (first > last) return;
  RowBounds bounds;
  bounds.init(tv, box.left, first);
  const int32_t cx0 = clip.x0, cx1 = clip.x1 - 1;
  bool started = false;
  constexpr int32_t chunk = RowChunk<Shader>::value;
  RowSpan rows[chunk];
  for (int32_t y = first; y <= last; y += chunk) {
    const int32_t n = last - y + 1 < chunk ? last - y + 1 : chunk;
    bounds.fill(rows, y, n);
    // Rows outside [r0, r1] keep only their owned corners.
    for (int32_t j = 0; j < n && y + j < r0; ++j) rows[j] = RowSpan{1, 0};
    for (int32_t j = n - 1; j >= 0 && y + j > r1; --j) rows[j] = RowSpan{1, 0};
    for (int k = 0; k < corners.count; ++k) {
      const int32_t j = corners.c[k].y - y;
      if (j >= 0 && j < n) Corners::apply_corner(corners.c[k], &rows[j].xs, &rows[j].xe);
    }
    int32_t j = 0;
    if (!started) {
      // The set-up on the first row with a pixel in the clip.
      while (j < n && max2(rows[j].xs, cx0) > min2(rows[j].xe, cx1)) ++j;
      if (j == n) continue;
      TriangleSetup s;
      row_setup<Shader>(tv, area2, box.right - box.left < scan_max_extent && box.bottom - box.top < scan_max_extent,
                        &s);
      shader.begin(tv, s);
      started = true;
    }
    draw_rows(shader, rows + j, y + j, n - j, cx0, cx1);
  }
}

}  // namespace
}  // namespace tristream::core::detail::portable
