// SPDX-License-Identifier: MIT
// The span bounds of the span path: SplitSpanStepper (two bounds per row, the Cortex-M form),
// SpanStepper (three) and, with SSE2, sse2::RowSpans (three in lanes, the x86-64 form) must give, on every row of a triangle and from any first row (a band's
// clip), exactly the covered columns that testing every sample point against the three edges
// gives. Triangles: random, with vertices on whole pixels (every encoder mesh), flat tops and
// bottoms, the middle vertex on a row and off it, boundary edges, slivers.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>

#include "tristream/config.h"
#include "edge.h"
#include "sse2/edges.h"

using namespace tristream::core;
using namespace tristream::core::detail;

namespace {

constexpr int S = config::subpixel_bits;

struct Covered {
  int32_t x0, x1;  // empty: x0 > x1
};

// Brute force over the columns [-2, 2 extent]: a sample point is covered when a x + b y + c >= 0
// on all three edges (c carries the bias).
Covered brute(const Edge* e, int32_t y, int32_t max_x) {
  Covered c{1, 0};
  for (int32_t x = -2; x <= max_x; ++x) {
    bool in = true;
    for (int k = 0; k < 3; ++k) in = in && e[k].a * x + e[k].b * y + e[k].c >= 0;
    if (!in) continue;
    if (c.x0 > c.x1) c.x0 = x;
    c.x1 = x;
  }
  return c;
}

void check_triangle(const int32_t* xs, const int32_t* ys, int flags, int32_t max_x) {
  Edge e[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    e[k] = make_edge(xs[k], ys[k], xs[n], ys[n], (flags >> k & 1) != 0);
  }
  const int32_t top = (std::min({ys[0], ys[1], ys[2]}) + (1 << S) - 1) >> S;
  const int32_t bottom = std::max({ys[0], ys[1], ys[2]}) >> S;
  int32_t r0 = top, r1 = bottom;
  restrict_rows(e, &r0, &r1);
  for (int32_t first = top; first <= bottom; ++first) {
    SpanStepper three;
    three.init(e, first);
    SplitSpanStepper two;
    two.init(e, ys, first);
#if TS_USE_SSE2
    sse2::RowSpans lanes;
    lanes.init(e, ys, first);
#endif
    for (int32_t y = first; y <= bottom; ++y, three.next_row(), two.next_row()) {
      two.begin_row(y);
#if TS_USE_SSE2
      lanes.begin_row(y);
      if (y > first) lanes.next_row();
#endif
      if (y < r0 || y > r1) continue;
      const Covered want = brute(e, y, max_x);
      Covered got3{}, got2{};
      three.span(&got3.x0, &got3.x1);
      two.span(y, &got2.x0, &got2.x1);
#if TS_USE_SSE2
      Covered got_lanes{};
      lanes.span(y, &got_lanes.x0, &got_lanes.x1);
      CHECK(((got_lanes.x0 > got_lanes.x1 && got3.x0 > got3.x1) ||
             (got_lanes.x0 == got3.x0 && got_lanes.x1 == got3.x1)));
#endif
      INFO("triangle (" << xs[0] << "," << ys[0] << ") (" << xs[1] << "," << ys[1] << ") (" << xs[2] << ","
                        << ys[2] << ") flags " << flags << ", first row " << first << ", row " << y);
      if (want.x0 > want.x1) {
        CHECK(got3.x0 > got3.x1);
        CHECK(got2.x0 > got2.x1);
      } else {
        CHECK(got3.x0 == want.x0);
        CHECK(got3.x1 == want.x1);
        CHECK(got2.x0 == want.x0);
        CHECK(got2.x1 == want.x1);
      }
    }
  }
}

// Positive orientation (the core's triangles after loading), or false for no area.
bool orient(int32_t* xs, int32_t* ys) {
  const int64_t a = int64_t(xs[1] - xs[0]) * (ys[2] - ys[0]) - int64_t(ys[1] - ys[0]) * (xs[2] - xs[0]);
  if (a == 0) return false;
  if (a < 0) {
    std::swap(xs[1], xs[2]);
    std::swap(ys[1], ys[2]);
  }
  return true;
}

}  // namespace

TEST_CASE("two span bounds per row give the covered columns of three") {
  std::mt19937 rng(16);
  int checked = 0;
  for (int i = 0; i < 6000; ++i) {
    const int mode = i % 4;
    const int32_t extent = i % 3 == 0 ? 6 : (i % 3 == 1 ? 24 : 60);
    std::uniform_int_distribution<int32_t> pixel(0, extent), fine(0, extent << S);
    int32_t xs[3], ys[3];
    for (int k = 0; k < 3; ++k) {
      // 0, 1: whole pixels (the middle vertex often on a row); 2: sub-pixel positions; 3: whole
      // pixels with two vertices on one row (flat tops and bottoms).
      xs[k] = mode == 2 ? fine(rng) : pixel(rng) << S;
      ys[k] = mode == 2 ? fine(rng) : pixel(rng) << S;
    }
    if (mode == 3) ys[1] = ys[(i / 4) % 2 == 0 ? 0 : 2];
    if (!orient(xs, ys)) continue;
    check_triangle(xs, ys, int(rng() % 8), (extent + 2));
    ++checked;
  }
  CHECK(checked > 4000);
}
