/* SPDX-License-Identifier: MIT */
#pragma once
// The covered columns of a triangle's rows from two exact bounds per row, filled into a table a
// chunk of rows at a time (portable/rasterize.h; test_core_span_stepper checks them against every
// sample point). For every triangle size: the bounds' numerators are taken relative to the
// triangle's first pixel column, so that their set-up divides in 32 bits (in 64 only for
// triangles thousands of pixels across), and a row costs two FloorStepper steps in registers.
//
// With the vertices t, m, b by position y (top, middle, bottom), a row whose sample y is above m
// meets the triangle where it meets the wedge of the two edges from t, and a row below m where it
// meets the wedge of the two edges to b: at such a sample point of the wedge the barycentric weight
// of the vertex opposite the third edge is positive, so that edge's function is a positive integer,
// at least the bias of 1, and the third test always passes. The long edge (t, b) bounds one side
// on every row; the short edge on the other side is the upper one (t, m) above m and the lower one
// (m, b) from the first row past m on. A row exactly through m takes both short edges. A short
// edge with a == 0 is a neutral bound; the rows it excludes are the caller's (restrict_rows).
#include <stdint.h>

#include "arith.h"
#include "edge.h"
#include "triangle_view.h"
#include "tristream/config.h"
#include "tristream/fixed_point.h"
#include "tuning.h"

namespace tristream::core::detail {
namespace {

// The covered columns [xs, xe] of a row (empty when xs > xe).
struct RowSpan {
  int32_t xs, xe;
};

// Rows a chunk: the table's size (8 bytes a row on the stack of the tile function), unless the
// shader declares `static constexpr int32_t rows_a_chunk` (RowChunk).
constexpr int32_t row_chunk = 16;
template <typename Shader, typename = void>
struct RowChunk {
  static constexpr int32_t value = row_chunk;
};
template <typename Shader>
struct RowChunk<Shader, decltype(void(Shader::rows_a_chunk))> {
  static constexpr int32_t value = Shader::rows_a_chunk;
};

class RowBounds {
 public:
  // tv: the vertices (position_fx raw) and boundary-edge flags of a triangle of positive area;
  // left: its first pixel column (the bounds' origin); y0: the row of the first fill.
  void init(const TriangleView& tv, int32_t left, int32_t y0) {
    tv_ = &tv;
    left_ = left;
    int t = 0, b = 0;
    for (int k = 1; k < 3; ++k) {
      if (tv.y[k] < tv.y[t]) t = k;
      if (tv.y[k] > tv.y[b]) b = k;
    }
    if (t == b) b = t == 0 ? 1 : 0;  // a flat triangle (no area: not drawn), kept well-defined
    const int m = 3 - t - b;
    // Edge k joins vertices k and k + 1: the one without m is the long edge, edge m and edge
    // m + 2 the short ones; the one that joins m to b is the lower.
    const int long_edge = m == 2 ? 0 : m + 1, e_prev = m == 0 ? 2 : m - 1;
    const bool m_to_b = (m == 2 ? 0 : m + 1) == b;  // edge m runs from m to b
    lower_ = int8_t(m_to_b ? m : e_prev);
    const int upper = m_to_b ? e_prev : m;
    // The long edge's side: left where its a = -dy 2^S > 0.
    short_side_ = int8_t(edge_dy(long_edge) < 0 ? 1 : 0);
    init_bound(&bound_[1 - short_side_], long_edge, y0);
    const position_fx my = position_fx::from_raw(tv.y[m]);
    split_ = my.ceil_to_int();  // the first row whose sample is not above m
    exact_ = my.is_integer();
    switch_pending_ = y0 < split_ || (y0 == split_ && exact_);
    init_bound(&bound_[short_side_], switch_pending_ ? upper : lower_, y0);
  }

  // Rows y .. y + n - 1 into out[0 .. n - 1] (n >= 1): the next n rows, y being the row the bounds
  // are at (init's y0, then one past the last fill).
  void fill(RowSpan* out, int32_t y, int32_t n) {
    // The rows before the switch to the lower short edge, then (if it falls in these rows) the
    // others: one copy of the row loop.
    int32_t k = switch_pending_ && split_ < y + n ? split_ - y : n;  // >= 0: the switch is never passed
    int32_t upper_q = 0;
    bool through_m = false;
    for (;;) {
      run(out, k);
      if (k == n) break;
      upper_q = bound_[short_side_].q;  // the upper short edge at row split_
      through_m = exact_;
      switch_to_lower();
      out += k;
      n -= k;
      k = n;
    }
    if (through_m) {
      // The row through m (now out[0]): the upper short edge's bound too, on the short edges' side.
      if (short_side_) {
        out->xe = min2(out->xe, upper_q);
      } else {
        out->xs = max2(out->xs, -upper_q);
      }
    }
  }

 private:
  int32_t edge_dx(int k) const { return tv_->x[k == 2 ? 0 : k + 1] - tv_->x[k]; }
  int32_t edge_dy(int k) const { return tv_->y[k == 2 ? 0 : k + 1] - tv_->y[k]; }

  // Edge k's bound from row y: covered when a x + b y + c >= 0 (edge.h: a = -dy 2^S, b = dx 2^S, c
  // with the bias). With x = left + i: a i + num >= 0, num = a left + b y + c = -dy (left 2^S - Px)
  // + dx (y 2^S - Py) - bias, a difference of products bounded by the triangle's box (int32 for
  // boxes below 2^22 pixels). A left bound (a > 0) is x >= left - floor(num / a), a right bound
  // (a < 0) x <= left + floor(num / -a); the stepper keeps q with xs = -q or xe = q.
  // Out of line: inlined into init, it costs more in spills (Cortex-M4) than the calls save.
  TS_NOINLINE void init_bound(FloorStepper* f, int k, int32_t y) const {
    const int32_t dx = edge_dx(k), dy = edge_dy(k);
    if (dy == 0) {
      *f = FloorStepper::constant(INT32_MAX);  // -INT32_MAX as a left bound, INT32_MAX as a right one: never wins
      return;
    }
    constexpr int S = config::subpixel_bits;
    const int32_t px = tv_->x[k], py = tv_->y[k];
    const int32_t bias = inclusive_edge(dx, dy, (tv_->flags & (boundary_edge0 << k)) != 0) ? 0 : 1;
    const int64_t num = int64_t(-dy) * (left_ * (1 << S) - px) + int64_t(dx) * (y * (1 << S) - py) - bias;
    const int32_t den = (dy < 0 ? -dy : dy) * (1 << S);
    // In 32 bits where num fits (every box below 2^22 pixels); for size one form, whose divisions
    // take 32 bits where their operands fit (floor_div).
    if (num == int64_t(int32_t(num))) {
      f->init32(int32_t(num), dx * (1 << S), den);
    } else {
      f->init(num, int64_t(dx) * (1 << S), den);
    }
    f->q += dy < 0 ? -left_ : left_;
  }

  // The lower short edge from row split_ on (at most once a triangle and clip).
  void switch_to_lower() {
    init_bound(&bound_[short_side_], lower_, split_);
    switch_pending_ = false;
  }

  // n rows from the bounds' current row: the steppers in locals (registers on Cortex-M).
  TS_INLINE void run(RowSpan* out, int32_t n) {
    FloorStepper l = bound_[0], r = bound_[1];
    for (RowSpan* const end = out + n; out != end; ++out) {
      out->xs = -l.q;
      out->xe = r.q;
      l.next_row();
      r.next_row();
    }
    bound_[0].q = l.q;
    bound_[0].r = l.r;
    bound_[1].q = r.q;
    bound_[1].r = r.r;
  }

  FloorStepper bound_[2];  // [0] the left bound, [1] the right
  // Set by init (no member initializers: a stepper is set up per triangle).
  const TriangleView* tv_;
  int32_t left_;
  int32_t split_;       // the row where the lower short edge takes over (while switch_pending_)
  int8_t lower_;        // index of the lower short edge
  int8_t short_side_;   // the short edges' side: 0 left, 1 right
  bool exact_;          // row split_ passes through m: both short edges bound it
  bool switch_pending_;
};

}  // namespace
}  // namespace tristream::core::detail
