// SPDX-License-Identifier: MIT
// The span bounds of the rasterizer: RowBounds (two bounds per row filled into a table a chunk of
// rows at a time, the form without SSE2), SpanStepper (three) and, with SSE2, sse2::RowSpans (three
// in lanes, the x86-64 form) must give, on every row of a triangle and from any first row (a band's
// clip), exactly the covered columns that testing every sample point against the three edges
// gives, whatever the chunks. Triangles: random, with vertices on whole pixels (every encoder mesh), flat tops and
// bottoms, the middle vertex on a row and off it, boundary edges, slivers.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "tristream/config.h"
#include "edge.h"
#include "row_bounds.h"
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

// Every first row from the top (first_step 1), or every first_step-th, each checked over at most
// row_limit rows.
void check_triangle(const int32_t* xs, const int32_t* ys, int flags, int32_t max_x, int32_t first_step = 1,
                    int32_t row_limit = INT32_MAX) {
  Edge e[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    e[k] = make_edge(xs[k], ys[k], xs[n], ys[n], (flags >> k & 1) != 0);
  }
  const int32_t top = (std::min({ys[0], ys[1], ys[2]}) + (1 << S) - 1) >> S;
  const int32_t bottom = std::max({ys[0], ys[1], ys[2]}) >> S;
  int32_t r0 = top, r1 = bottom;
  restrict_rows(e, &r0, &r1);
  for (int32_t first = top; first <= bottom; first += first_step) {
    const int32_t last = bottom - first < row_limit ? bottom : first + row_limit - 1;
    SpanStepper three;
    three.init(e, first);
    // RowBounds from the same first row, its rows filled in chunks of 1 .. row_chunk rows.
    TriangleView tv{};
    for (int k = 0; k < 3; ++k) tv.x[k] = xs[k], tv.y[k] = ys[k];
    tv.flags = uint16_t(flags);  // boundary_edge0 << k: bit k
    const int32_t left = (std::min({xs[0], xs[1], xs[2]}) + (1 << S) - 1) >> S;
    RowBounds two;
    two.init(tv, left, first);
    std::vector<RowSpan> table(size_t(last - first + 1));
    for (int32_t y = first, n = 1; y <= last; y += n, n = n % row_chunk + 1) {
      n = std::min(n, last - y + 1);
      two.fill(table.data() + (y - first), y, n);
    }
#if TS_USE_SSE2
    sse2::RowSpans lanes;
    lanes.init(e, ys, first);
#endif
    for (int32_t y = first; y <= last; ++y, three.next_row()) {
#if TS_USE_SSE2
      lanes.begin_row(y);
      if (y > first) lanes.next_row();
#endif
      if (y < r0 || y > r1) continue;
      const Covered want = brute(e, y, max_x);
      Covered got3{}, got2{};
      three.span(&got3.x0, &got3.x1);
      got2 = Covered{table[size_t(y - first)].xs, table[size_t(y - first)].xe};
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

TEST_CASE("row bounds of triangles thousands of pixels across (64-bit numerators)") {
  std::mt19937 rng(39);
  std::uniform_int_distribution<int32_t> fine(0, (4096 << S) - 1);
  int checked = 0;
  for (int i = 0; i < 24; ++i) {
    int32_t xs[3], ys[3];
    for (int k = 0; k < 3; ++k) xs[k] = fine(rng), ys[k] = fine(rng);
    if (i % 2 == 0) ys[1] = ys[0];  // a horizontal edge
    if (!orient(xs, ys)) continue;
    // Boxes over 2^22 pixels: their bounds' numerators need 64 bits.
    check_triangle(xs, ys, int(rng() % 8), 4098, 397, 24);
    ++checked;
  }
  CHECK(checked > 20);
}
