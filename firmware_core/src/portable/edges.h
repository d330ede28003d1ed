/* SPDX-License-Identifier: MIT */
#pragma once
// The span path's row bounds (rasterize.h) in plain C++: SplitSpanStepper (edge.h), two bounds per
// row, which stay in registers on Cortex-M where three do not.
#include "../edge.h"

namespace tristream::core::detail::portable {

// RowSpans, the span path's stepper of a row's covered columns:
//   void init(const Edge* edges, const int32_t* ys, int32_t y0)  the edges, the vertices' y
//                                       (position_fx raw, vertex k the start of edge k), row y0;
//   void begin_row(int32_t y)          on every row y (the row the stepper is at), first;
//   void span(int32_t y, int32_t* x0, int32_t* x1)  columns [*x0, *x1] of row y (empty: *x0 > *x1);
//   void next_row()                    to row y + 1.
using RowSpans = SplitSpanStepper;

}  // namespace tristream::core::detail::portable
