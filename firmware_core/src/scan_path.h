/* SPDX-License-Identifier: MIT */
#pragma once
// The scan path: small triangles (pixel box below scan_max_extent each way, no explicit corner) take
// int32 edge values and find each row's covered columns by edge tests over the box (RowMasks), instead
// of the span steppers and their divisions. Both paths test the same exact predicate.
#include <stdint.h>

#include "shader.h"
#include "triangle_view.h"
#include "tristream/config.h"
#include "backend.h"
#include "portable/scan_path.h"
#include "sse2/scan_path.h"
#include "tristream/blob.h"
#include "edge.h"
#include "tuning.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

static_assert(scan_max_extent <= 62, "the scan path's int32 edge values need boxes below 64 pixels");

// Edge values on the pixel box of a triangle whose box is below 64 x 64 pixels: for a pixel x of
// the box, |x 2^S - Px| < 64 * 2^S and |dy| < 64 * 2^S, so |E| < 2 * (64 * 2^S)^2 = 2^21 for
// S = 4 (and below 2^31 for every S up to 8), plus the bias; int32 suffices.
static_assert(2 * (int64_t(64) << config::subpixel_bits) * (int64_t(64) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path edge values must fit int32");

// The platform's part (portable/scan_path.h, sse2/scan_path.h), in namespace backend:
//   SmallEdges            a scan-path triangle's edges (below) and doubled area;
//   small_edges(tv, area2, left, y0, &e)   sets them up for the rows from (left, y0);
//   small_setup<Reads>(tv, e, &s)          the shader's TriangleSetup (e_ref32 and e_ref may be
//                         left unset where ERefsRead says the shader does not read them);
//   RowMasks<Groups>      the covered columns of a box row, from the three edge values at the
//                         row's first column and their steps per column (a) and per row (b):
//                         RowMasks(e.row, e.a, e.b, box) with the box's columns as a mask,
//                         bool columns(box, &first, &last) the current row's covered columns
//                         (offsets from the box's first column; false for none), void next_row();
//   scan_rows_by_width    whether scan_rows takes a copy per width in groups of four columns.

// The edges of a scan-path triangle (backend::SmallEdges; edge k from vertex k to vertex k + 1) in
// int32, with its doubled area. Its vertices span fewer than scan_max_extent + 2 pixels each way, so every coordinate
// difference, and the offset of every vertex from a pixel of the box or from vertex 0 floored, is
// below 19 * 2^S: int16 (S <= 8), and the area is below 2 * (19 * 2^S)^2. Edge values
// E_k(x, y) = -dy_k (x 2^S - x_k) + dx_k (y 2^S - y_k): the same integer as A x + B y + C of
// detail/edge.h.
static_assert((int32_t(19) << config::subpixel_bits) < 32768, "scan-path differences must fit int16");
static_assert(2 * (int64_t(19) << config::subpixel_bits) * (int64_t(19) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path areas must fit int32");

template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const backend::SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader);

// Rows y0..y1 (already clipped) of a triangle whose pixel box has columns left..right: each row
// is scanned over the whole box, so xs is the row's first covered pixel even when the clip
// (columns cx0..cx1) cuts the span.
template <typename Shader>
void scan_small(const TriangleView& tv, int32_t area2, int32_t left, int32_t right, int32_t y0, int32_t y1,
                int32_t cx0, int32_t cx1, Shader& shader) {
  if (right < left) return;  // no pixel column between the vertices
  backend::SmallEdges e;
  backend::small_edges(tv, area2, left, y0, &e);
  const uint32_t box = (2u << (right - left)) - 1;  // covered columns at most; right - left < 16
  static_assert(scan_max_extent <= 16, "scan rows are at most four groups of four columns");
  if constexpr (backend::scan_rows_by_width) {
    switch ((right - left) / 4) {
      case 0: return scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);
      case 1: return scan_rows<2>(tv, e, left, box, y0, y1, cx0, cx1, shader);
      case 2: return scan_rows<3>(tv, e, left, box, y0, y1, cx0, cx1, shader);
      default: return scan_rows<4>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    }
  } else {
    scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);  // one copy: Groups unused
  }
}

// The rows of scan_small with masks of Groups * 4 columns (the box's width at most).
template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const backend::SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader) {
  backend::RowMasks<Groups> masks(e.row, e.a, e.b, box);
  bool started = false;
  for (int32_t y = y0; y <= y1; ++y, masks.next_row()) {
    int32_t first, last;
    if (!masks.columns(box, &first, &last)) continue;
    const int32_t xs = left + first, xe = left + last;
    const int32_t cs = xs > cx0 ? xs : cx0;
    const int32_t ce = xe < cx1 ? xe : cx1;
    if (cs > ce) continue;
    if (!started) {
      TriangleSetup s;
      backend::small_setup<ERefsRead<Shader>::value>(tv, e, &s);
      shader.begin(tv, s);
      started = true;
    }
    shader.span(y, xs, xe, cs, ce);
  }
}

}  // namespace
}  // namespace tristream::core::detail
