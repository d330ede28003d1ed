// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/predicates.h"

using tristream::incircle;
using tristream::orient2d;
using tristream::Point;

namespace {

int sign(double v) { return (v > 0) - (v < 0); }
int sign128(__int128 v) { return (v > 0) - (v < 0); }

// Independent exact references for points on the dyadic grid k / 2^20, |k| < 2^28: scaling
// by 2^20 (exact) makes the coordinates integers, and a uniform scale keeps the signs.
constexpr double grid = 0x1p20;
__int128 ik(double v) { return __int128(std::llround(v * grid)); }

int orient_reference(Point a, Point b, Point c) {
  return sign128((ik(b.x) - ik(a.x)) * (ik(c.y) - ik(a.y)) - (ik(b.y) - ik(a.y)) * (ik(c.x) - ik(a.x)));
}

// Coordinates stay below 2^27 grid units: lifts and crosses below 2^57, the determinant
// below 2^116, inside a signed 128-bit integer.
int incircle_reference(Point a, Point b, Point c, Point d) {
  const __int128 adx = ik(a.x) - ik(d.x), ady = ik(a.y) - ik(d.y);
  const __int128 bdx = ik(b.x) - ik(d.x), bdy = ik(b.y) - ik(d.y);
  const __int128 cdx = ik(c.x) - ik(d.x), cdy = ik(c.y) - ik(d.y);
  const __int128 lift[3] = {adx * adx + ady * ady, bdx * bdx + bdy * bdy, cdx * cdx + cdy * cdy};
  const __int128 cross[3] = {bdx * cdy - bdy * cdx, cdx * ady - cdy * adx, adx * bdy - ady * bdx};
  return sign128(lift[0] * cross[0] + lift[1] * cross[1] + lift[2] * cross[2]);
}

}  // namespace

TEST_CASE("orient2d is exact on the near-collinear grid of Kettner et al.", "[predicates]") {
  // p = (0.5 + i ulp, 0.5 + j ulp), q = (12, 12), r = (24, 24): the exact value is
  // 12 (p.y - p.x), whose sign the naive formula gets wrong in large parts of the grid.
  const double ulp = std::nextafter(0.5, 1.0) - 0.5;
  int naive_wrong = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const Point p{0.5 + i * ulp, 0.5 + j * ulp};
      const Point q{12, 12}, r{24, 24};
      const int expected = sign(p.y - p.x);
      REQUIRE(sign(orient2d(p, q, r)) == expected);
      REQUIRE(sign(orient2d(q, r, p)) == expected);
      REQUIRE(sign(orient2d(r, q, p)) == -expected);
      const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
      naive_wrong += sign(naive) != expected;
    }
  CHECK(naive_wrong > 0);  // the test input really is hard
}

TEST_CASE("incircle is exact for cocircular points moved by one ulp", "[predicates]") {
  // Integer points on the circle of radius 65 around a centre far from the origin (beyond the
  // integer fast path), then d moved by one ulp in x: outside iff d.x > centre.x.
  const double cx = 1e9 + 3, cy = -7e8 + 1;
  const int pts[][2] = {{65, 0}, {63, 16}, {60, 25}, {56, 33}, {52, 39}, {39, 52}, {33, 56},
                        {25, 60}, {16, 63}, {0, 65}, {-16, 63}, {-33, -56}, {-63, -16}, {39, -52}};
  const Point a{cx + 65, cy}, b{cx, cy + 65}, c{cx - 65, cy};  // orient2d(a, b, c) > 0
  REQUIRE(orient2d(a, b, c) > 0);
  for (const auto& q : pts) {
    const Point d{cx + q[0], cy + q[1]};
    if (d.x == a.x && d.y == a.y) continue;
    CHECK(incircle(a, b, c, d) == 0);
    for (double direction : {-1.0, 1.0}) {
      const Point moved{std::nextafter(d.x, d.x + direction), d.y};
      if (q[0] == 0) continue;
      const int expected = (q[0] > 0) == (direction > 0) ? -1 : 1;  // outward: negative
      CHECK(sign(incircle(a, b, c, moved)) == expected);
      CHECK(sign(incircle(b, c, a, moved)) == expected);
      CHECK(sign(incircle(a, c, b, moved)) == -expected);
    }
  }
}

TEST_CASE("predicates agree with an integer reference on near-degenerate dyadic input", "[predicates]") {
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t(1) << 25), std::int64_t(1) << 25);
  std::uniform_int_distribution<int> nudge(-2, 2);
  auto random_point = [&] { return Point{double(coord(rng)) / grid, double(coord(rng)) / grid}; };
  auto on_grid = [&](double v) { return std::round(v * grid) / grid; };
  int zero_orient = 0;
  for (int n = 0; n < 20000; ++n) {
    const Point a = random_point(), b = random_point();
    // c near the line ab, d near the circle abc: rounded to the grid, plus a nudge of a few units.
    // Half the time t is an integer, so that c can lie exactly on the line.
    const double t = n % 2 ? double(nudge(rng)) : std::ldexp(double(coord(rng)), -24);
    const Point c{on_grid(a.x + t * (b.x - a.x)) + nudge(rng) / grid,
                  on_grid(a.y + t * (b.y - a.y)) + nudge(rng) / grid};
    const int o = orient_reference(a, b, c);
    REQUIRE(sign(orient2d(a, b, c)) == o);
    REQUIRE(sign(orient2d(b, c, a)) == o);
    zero_orient += o == 0;

    const Point e = random_point();
    if (orient_reference(a, b, e) == 0) continue;
    // d: the reflection of e across the perpendicular bisector of ab lies on circle abe.
    const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
    const double ux = b.x - a.x, uy = b.y - a.y;
    const double s = ((e.x - mx) * ux + (e.y - my) * uy) / (ux * ux + uy * uy);
    const Point d{on_grid(e.x - 2 * s * ux) + nudge(rng) / grid, on_grid(e.y - 2 * s * uy) + nudge(rng) / grid};
    const int expected = incircle_reference(a, b, e, d);
    REQUIRE(sign(incircle(a, b, e, d)) == expected);
    REQUIRE(sign(incircle(b, e, a, d)) == expected);
    REQUIRE(sign(incircle(b, a, e, d)) == -expected);
  }
  CHECK(zero_orient > 0);
}

TEST_CASE("integer input: the fast path and the expansion path agree", "[predicates]") {
  // Translating integer points by 2^40 (exact) leaves every sign unchanged but moves the
  // evaluation off the 2^29 integer path onto the expansion path.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-40, 40);
  const double shift = 0x1p40;
  int zeros = 0;
  for (int n = 0; n < 50000; ++n) {
    Point p[4];
    for (Point& q : p) q = {double(coord(rng)), double(coord(rng))};
    Point s[4];
    for (int i = 0; i < 4; ++i) s[i] = {p[i].x + shift, p[i].y - shift};
    REQUIRE(sign(orient2d(p[0], p[1], p[2])) == sign(orient2d(s[0], s[1], s[2])));
    const int ic = sign(incircle(p[0], p[1], p[2], p[3]));
    REQUIRE(ic == sign(incircle(s[0], s[1], s[2], s[3])));
    zeros += ic == 0;
  }
  CHECK(zeros > 0);
}

TEST_CASE("predicates at the ends of the documented range", "[predicates]") {
  for (double scale : {0x1p-200, 1.0, 0x1p200}) {
    const Point a{0, 0}, b{scale, 0}, c{0, scale};
    CHECK(orient2d(a, b, c) > 0);
    CHECK(orient2d(a, c, b) < 0);
    CHECK(orient2d(a, b, Point{2 * scale, 0}) == 0);
    CHECK(incircle(a, b, c, Point{scale, scale}) == 0);
    CHECK(incircle(a, b, c, Point{scale / 2, scale / 2}) > 0);
    CHECK(incircle(a, b, c, Point{std::nextafter(scale, 2 * scale), scale}) < 0);
    CHECK(incircle(a, b, c, Point{std::nextafter(scale, 0.0), scale}) > 0);
  }
}
