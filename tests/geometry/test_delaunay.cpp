// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "geometry/delaunay.h"
#include "geometry/predicates.h"

using namespace tristream;

namespace {

// Number of input points on the boundary of the convex hull (vertices and points on edges).
std::size_t hull_boundary_count(const std::vector<Point>& pts) {
  std::vector<Point> s = pts;
  std::sort(s.begin(), s.end(), [](const Point& a, const Point& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  std::vector<Point> hull;  // strict convex hull, Andrew's monotone chain
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point& p : s) {
      while (hull.size() >= base + 2 && orient2d(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(s.begin(), s.end());
  }
  std::size_t count = 0;
  for (const Point& p : pts)
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Point& a = hull[i];
      const Point& b = hull[(i + 1) % hull.size()];
      if (orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
          std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y)) {
        ++count;
        break;
      }
    }
  return count;
}

double hull_doubled_area(const std::vector<Point>& pts) {
  std::vector<Point> s = pts;
  std::sort(s.begin(), s.end(), [](const Point& a, const Point& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  std::vector<Point> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point& p : s) {
      while (hull.size() >= base + 2 && orient2d(hull[hull.size() - 2], hull.back(), p) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
    std::reverse(s.begin(), s.end());
  }
  double area = 0;
  for (std::size_t i = 0; i < hull.size(); ++i)
    area += hull[i].x * hull[(i + 1) % hull.size()].y - hull[(i + 1) % hull.size()].x * hull[i].y;
  return std::fabs(area);
}

// Checks everything a Delaunay triangulation of distinct, not all collinear points must
// satisfy. `exact_area`: coordinates are small integers, so areas sum exactly in double.
void check_delaunay(const std::vector<Point>& pts, const std::vector<Triangle>& tris, bool exact_area) {
  const std::size_t n = pts.size();
  const std::size_t h = hull_boundary_count(pts);
  // Every point is a vertex and Euler's formula holds: T = 2n - h - 2.
  REQUIRE(tris.size() == 2 * n - h - 2);
  std::vector<int> used(n, 0);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  double area = 0;
  for (const Triangle& t : tris) {
    for (int e = 0; e < 3; ++e) {
      REQUIRE(t.v[e] < n);
      used[t.v[e]] = 1;
      // Each directed edge at most once: no overlap, consistent winding.
      REQUIRE(directed.emplace(std::make_pair(t.v[e], t.v[(e + 1) % 3]), 1).second);
    }
    const Point &a = pts[t.v[0]], &b = pts[t.v[1]], &c = pts[t.v[2]];
    REQUIRE(orient2d(a, b, c) > 0);
    area += (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  }
  REQUIRE(std::count(used.begin(), used.end(), 1) == std::ptrdiff_t(n));
  // An edge without its twin lies on the hull boundary; there are exactly h of them.
  std::size_t unpaired = 0;
  for (const auto& [edge, one] : directed)
    if (!directed.count({edge.second, edge.first})) {
      ++unpaired;
      for (const Point& p : pts) REQUIRE(orient2d(pts[edge.first], pts[edge.second], p) >= 0);
    }
  REQUIRE(unpaired == h);
  if (exact_area) REQUIRE(area == hull_doubled_area(pts));
  else REQUIRE(area == Approx(hull_doubled_area(pts)).epsilon(1e-12));
  // Empty circumcircles, exact: no point strictly inside any triangle's circle.
  for (const Triangle& t : tris)
    for (const Point& p : pts) REQUIRE(incircle(pts[t.v[0]], pts[t.v[1]], pts[t.v[2]], p) <= 0);
}

// Neighbour links of every live slot are mutual and edges match in reverse.
void check_structure(const DelaunayBuilder& d) {
  std::size_t solid = 0;
  for (std::uint32_t t = 0; t < d.slot_count(); ++t) {
    if (!d.is_live(t)) continue;
    if (!d.is_ghost(t)) {
      ++solid;
      REQUIRE(orient2d(d.point(d.vertices(t)[0]), d.point(d.vertices(t)[1]), d.point(d.vertices(t)[2])) > 0);
    }
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = d.neighbour(t, e);
      REQUIRE(u < d.slot_count());
      REQUIRE(d.is_live(u));
      const auto a = d.vertices(t)[e], b = d.vertices(t)[(e + 1) % 3];
      int found = 0;
      for (int f = 0; f < 3; ++f)
        if (d.neighbour(u, f) == t && d.vertices(u)[f] == b && d.vertices(u)[(f + 1) % 3] == a) ++found;
      REQUIRE(found == 1);
    }
  }
  REQUIRE(solid == d.solid_count());
}

std::vector<Point> random_points(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point> pts(n);
  for (Point& p : pts) p = {u(rng), u(rng)};
  return pts;
}

}  // namespace

TEST_CASE("Delaunay of random points", "[delaunay]") {
  const auto pts = random_points(1500, 1);
  check_delaunay(pts, delaunay_triangulation(pts), false);
}

TEST_CASE("Delaunay of random integer points with many collinear and cocircular subsets", "[delaunay]") {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> c(0, 30);
  std::set<std::pair<int, int>> s;
  while (s.size() < 400) s.insert({c(rng), c(rng)});
  std::vector<Point> pts;
  for (auto [x, y] : s) pts.push_back({double(x), double(y)});
  std::shuffle(pts.begin(), pts.end(), rng);
  check_delaunay(pts, delaunay_triangulation(pts), true);
}

TEST_CASE("Delaunay of cocircular lattices", "[delaunay]") {
  for (int side : {2, 3, 7, 20}) {
    std::vector<Point> pts;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) pts.push_back({double(x), double(y)});
    const auto tris = delaunay_triangulation(pts);
    REQUIRE(tris.size() == std::size_t(2 * (side - 1) * (side - 1)));
    check_delaunay(pts, tris, true);
  }
  SECTION("a non-square, shifted, scaled lattice") {
    std::vector<Point> pts;
    for (int y = 0; y < 9; ++y)
      for (int x = 0; x < 13; ++x) pts.push_back({0.25 + x * 0.125, -3.0 + y * 0.375});
    check_delaunay(pts, delaunay_triangulation(pts), true);
  }
}

TEST_CASE("Delaunay of points on one circle", "[delaunay]") {
  // The 36 integer points at distance 65 from the origin (65^2 = 4225 = 16^2 + 63^2 = ...).
  std::vector<Point> pts;
  for (int x = -65; x <= 65; ++x)
    for (int y = -65; y <= 65; ++y)
      if (x * x + y * y == 65 * 65) pts.push_back({double(x), double(y)});
  REQUIRE(pts.size() == 36);
  const auto tris = delaunay_triangulation(pts);
  REQUIRE(tris.size() == 34);
  check_delaunay(pts, tris, true);
  pts.push_back({0, 0});
  check_delaunay(pts, delaunay_triangulation(pts), true);
}

TEST_CASE("Delaunay of collinear rows", "[delaunay]") {
  std::vector<Point> pts;
  for (int row = 0; row < 4; ++row)
    for (int i = 0; i < 30; ++i) pts.push_back({double(i * (row + 1)), double(row * 5)});
  check_delaunay(pts, delaunay_triangulation(pts), true);
  SECTION("a single row and one point off it") {
    std::vector<Point> row;
    for (int i = 0; i < 50; ++i) row.push_back({double(i), 2.0 * i});
    CHECK(delaunay_triangulation(row).empty());
    row.push_back({10, 0});
    const auto tris = delaunay_triangulation(row);
    CHECK(tris.size() == 49);
    check_delaunay(row, tris, true);
  }
}

// Work (walk steps and conflict tests, DelaunayBuilder::work) for n points and for 4n: an
// O(n log n) triangulation grows about 4.3 times, a quadratic one 16 times.
template <class Make>
double work_growth(Make make, int n) {
  std::uint64_t small = 0, large = 0;
  const std::vector<Point> a = make(n), b = make(4 * n);
  const auto ta = delaunay_triangulation(a, &small);
  const auto tb = delaunay_triangulation(b, &large);
  CHECK(!ta.empty());
  CHECK(!tb.empty());
  return double(large) / double(small);
}

TEST_CASE("Delaunay of points on a few lines grows in O(n log n) work", "[delaunay]") {
  auto rows = [](int lines) {
    return [lines](int n) {
      std::vector<Point> pts;
      for (int i = 0; i < n; ++i) pts.push_back({double(i / lines), double(i % lines)});
      return pts;
    };
  };
  auto random = [](int n) {
    std::vector<Point> pts;
    std::uint64_t s = 12345;
    for (int i = 0; i < n; ++i) {
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      pts.push_back({double((s >> 33) % 65536), double((s >> 17) % 65536)});
    }
    return pts;
  };
  auto fan = [](int n) {  // one row and a point above its middle: every triangle shares it
    std::vector<Point> pts;
    for (int i = 0; i < n - 1; ++i) pts.push_back({double(i), 0});
    pts.push_back({double(n / 2), 1e6});
    return pts;
  };
  const int n = 4000;
  CHECK(work_growth(rows(2), n) < 5.0);
  CHECK(work_growth(rows(3), n) < 5.0);
  CHECK(work_growth(rows(7), n) < 5.0);
  CHECK(work_growth(random, n) < 5.0);
  CHECK(work_growth(fan, n) < 5.0);
  // The two-row lattice is still triangulated right.
  const std::vector<Point> two = rows(2)(2000);
  check_delaunay(two, delaunay_triangulation(two), true);
}

TEST_CASE("Delaunay of tiny sets", "[delaunay]") {
  CHECK(delaunay_triangulation(std::vector<Point>{}).empty());
  CHECK(delaunay_triangulation(std::vector<Point>{{0, 0}, {1, 1}}).empty());
  CHECK(delaunay_triangulation(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}).empty());
  const std::vector<Point> tri = {{0, 0}, {0, 1}, {1, 0}};
  const auto one = delaunay_triangulation(tri);
  REQUIRE(one.size() == 1);
  check_delaunay(tri, one, true);
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  check_delaunay(square, delaunay_triangulation(square), true);
  const std::vector<Point> collinear_first = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1.5, 1}};
  check_delaunay(collinear_first, delaunay_triangulation(collinear_first), false);
}

TEST_CASE("Delaunay output is deterministic", "[delaunay]") {
  const auto pts = random_points(3000, 9);
  const auto a = delaunay_triangulation(pts);
  const auto b = delaunay_triangulation(pts);
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) REQUIRE(a[i].v == b[i].v);
}

TEST_CASE("DelaunayBuilder reports destroyed and created slots", "[delaunay]") {
  // The encoder's use: start from two corners and one more, insert pixel positions in an
  // arbitrary order (boundary points included), following the reported changes.
  DelaunayBuilder d({0, 0}, {63, 0}, {0, 47});
  d.insert({63, 47});
  std::mt19937 rng(5);
  std::set<std::pair<int, int>> seen = {{0, 0}, {63, 0}, {0, 47}, {63, 47}};
  std::vector<char> alive(d.slot_count(), 1);
  for (int n = 0; n < 600; ++n) {
    const int x = std::uniform_int_distribution<int>(0, 63)(rng);
    const int y = n % 10 == 0 ? 0 : std::uniform_int_distribution<int>(0, 47)(rng);
    if (!seen.insert({x, y}).second) {
      const std::uint32_t before = std::uint32_t(d.vertex_count());
      REQUIRE(d.insert({double(x), double(y)}) < before);
      REQUIRE(d.created().empty());
      continue;
    }
    const std::uint32_t v = d.insert({double(x), double(y)});
    REQUIRE(v == d.vertex_count() - 1);
    for (std::uint32_t t : d.destroyed()) {
      REQUIRE(alive[t]);
      alive[t] = 0;
    }
    alive.resize(d.slot_count(), 0);
    for (std::uint32_t t : d.created()) {
      REQUIRE(!alive[t]);
      alive[t] = 1;
      const auto& tv = d.vertices(t);
      REQUIRE(std::find(tv.begin(), tv.end(), v) != tv.end());
    }
    for (std::uint32_t t = 0; t < d.slot_count(); ++t) REQUIRE(bool(alive[t]) == d.is_live(t));
    if (n % 50 == 0) check_structure(d);
  }
  check_structure(d);
  check_delaunay(d.points(), d.triangles(), true);
  // Every pixel position of the rectangle is located in a solid triangle, never outside.
  for (int y = 0; y < 48; y += 5)
    for (int x = 0; x < 64; x += 5) {
      const std::uint32_t t = d.locate({double(x), double(y)});
      REQUIRE(!d.is_ghost(t));
    }
}

TEST_CASE("DelaunayBuilder grows the hull for points outside it", "[delaunay]") {
  DelaunayBuilder d({0, 0}, {1, 0}, {0, 1});
  const std::vector<Point> extra = {{2, 0}, {3, 0}, {-1, -1}, {5, 5}, {0, 2}, {-1, 1}, {0.5, 0.5}, {4, 0}, {-2, -2}};
  for (const Point& p : extra) {
    d.insert(p);
    check_structure(d);
  }
  check_delaunay(d.points(), d.triangles(), false);
  REQUIRE_THROWS_AS(DelaunayBuilder({0, 0}, {1, 1}, {2, 2}), std::invalid_argument);
}
