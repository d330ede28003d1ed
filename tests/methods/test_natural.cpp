// SPDX-License-Identifier: MIT
// Natural-neighbour (Sibson) coordinates against an independent brute-force area computation,
// and the properties of the interpolant (partition of unity, linear precision, vertex values).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "reference/domain.h"
#include "reference/methods/natural.h"
#include "reference/render.h"
#include "../support/random_mesh.h"
#include "methods_support.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

// Sibson coordinates by definition: p's Voronoi cell among sites + p, intersected with each
// site's old Voronoi cell, O(n^2) half-plane clips. `box` must contain p's cell.
std::map<std::uint32_t, double> brute_force_sibson(const std::vector<Point>& sites, const Point& p, double box) {
  Polygon cell = {{p.x - box, p.y - box}, {p.x + box, p.y - box}, {p.x + box, p.y + box}, {p.x - box, p.y + box}};
  for (const Point& s : sites) cell = clip_closer_to(cell, p, s);
  for (const Point& q : cell) REQUIRE(std::max(std::abs(q.x - p.x), std::abs(q.y - p.y)) < box * 0.99);
  std::map<std::uint32_t, double> w;
  double total = 0;
  for (std::uint32_t i = 0; i < sites.size(); ++i) {
    Polygon piece = cell;
    for (std::uint32_t j = 0; j < sites.size() && !piece.empty(); ++j)
      if (j != i) piece = clip_closer_to(piece, sites[i], sites[j]);
    const double a = piece.size() >= 3 ? area(piece) : 0.0;
    if (a > 0) w[i] = a, total += a;
  }
  for (auto& [v, a] : w) a /= total;
  return w;
}

void check_against_brute_force(const std::vector<Point>& sites, const std::vector<Point>& queries) {
  SibsonCoordinates sibson(sites);
  std::vector<NeighbourWeight> w;
  for (const Point& p : queries) {
    INFO("query (" << p.x << ", " << p.y << ")");
    REQUIRE(sibson.compute(p, w));
    const auto expected = brute_force_sibson(sites, p, 1e5);
    std::map<std::uint32_t, double> got;
    double sum = 0;
    for (const auto& nw : w) {
      CHECK(nw.weight >= 0);
      got[nw.vertex] += nw.weight;
      sum += nw.weight;
    }
    CHECK(std::abs(sum - 1) < 1e-12);
    for (const auto& [v, e] : expected) CHECK(std::abs(got[v] - e) < 1e-9);
    for (const auto& [v, g] : got) CHECK(std::abs(g - (expected.count(v) ? expected.at(v) : 0.0)) < 1e-9);
  }
}

}  // namespace

TEST_CASE("natural: Sibson coordinates match a brute-force area computation (random points)") {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(0, 100);
  std::vector<Point> sites = {{0, 0}, {100, 0}, {0, 100}, {100, 100}};
  for (int i = 0; i < 40; ++i) sites.push_back({u(rng), u(rng)});
  std::vector<Point> queries;
  std::uniform_real_distribution<double> q(0.5, 99.5);
  for (int i = 0; i < 150; ++i) queries.push_back({q(rng), q(rng)});
  check_against_brute_force(sites, queries);
}

TEST_CASE("natural: Sibson coordinates match brute force on a lattice (cocircular points)") {
  // Lattice vertices and pixel-centre queries: queries on Delaunay edges, on circumcircles
  // and at circumcentres shared by several triangles.
  std::vector<Point> sites;
  std::mt19937 rng(99);
  for (int y = 0; y <= 12; y += 2)
    for (int x = 0; x <= 16; x += 2)
      if ((x == 0 || x == 16 || y == 0 || y == 12) || rng() % 3 != 0) sites.push_back({double(x), double(y)});
  std::vector<Point> queries;
  for (int y = 1; y < 12; ++y)
    for (int x = 1; x < 16; ++x)
      if ((x + y) % 3 == 0 || (x % 2 == 1 && y % 2 == 1)) queries.push_back({double(x), double(y)});
  check_against_brute_force(sites, queries);
}

TEST_CASE("natural: vertices, hull edges and the outside") {
  const std::vector<Point> sites = {{0, 0}, {10, 0}, {10, 8}, {0, 8}, {3, 4}, {7, 3}};
  SibsonCoordinates sibson(sites);
  std::vector<NeighbourWeight> w;
  for (std::uint32_t v = 0; v < sites.size(); ++v) {
    REQUIRE(sibson.compute(sites[v], w));
    REQUIRE(w.size() == 1);
    CHECK(w[0].vertex == v);
    CHECK(w[0].weight == 1.0);
  }
  // On a hull edge: linear interpolation of its two ends.
  REQUIRE(sibson.compute({4, 0}, w));
  std::map<std::uint32_t, double> m;
  for (const auto& nw : w) m[nw.vertex] += nw.weight;
  CHECK(m.size() == 2);
  CHECK(m[0] == Approx(0.6));
  CHECK(m[1] == Approx(0.4));
  // Just inside the hull the coordinates approach the edge's linear interpolation.
  REQUIRE(sibson.compute({4, 1e-5}, w));
  m.clear();
  for (const auto& nw : w) m[nw.vertex] += nw.weight;
  CHECK(m[0] == Approx(0.6).margin(1e-4));
  CHECK(m[1] == Approx(0.4).margin(1e-4));
  CHECK_FALSE(sibson.compute({-0.5, 3}, w));
  CHECK(w.empty());
  CHECK_FALSE(sibson.compute({5, 8.001}, w));
}

TEST_CASE("natural: linear precision of the coordinates") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 50);
  std::vector<Point> sites = {{0, 0}, {50, 0}, {0, 40}, {50, 40}};
  for (int i = 0; i < 200; ++i) sites.push_back({u(rng), 0.8 * u(rng)});
  SibsonCoordinates sibson(sites);
  std::vector<NeighbourWeight> w;
  for (int y = 0; y <= 40; ++y)
    for (int x = 0; x <= 50; ++x) {
      REQUIRE(sibson.compute({double(x), double(y)}, w));
      double sx = 0, sy = 0, sum = 0;
      for (const auto& nw : w) {
        REQUIRE(nw.weight >= 0);
        sx += nw.weight * sites[nw.vertex].x;
        sy += nw.weight * sites[nw.vertex].y;
        sum += nw.weight;
      }
      CHECK(std::abs(sum - 1) < 1e-12);
      CHECK(std::abs(sx - x) < 1e-9);
      CHECK(std::abs(sy - y) < 1e-9);
    }
}

TEST_CASE("natural: the renderer reproduces linear data and vertex values, covering every pixel") {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    // Flipped (non-Delaunay) file triangles only decide the domain; weights use Delaunay.
    Mesh mesh = tristream::testing::random_lattice_mesh(61, 47, 150, seed, 100, 2);
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
      mesh.values[2 * v] = 40 + 1.5 * mesh.points[v].x - 0.75 * mesh.points[v].y + 30;  // linear
    }
    Field out(61, 47, 2);
    render_natural(mesh, 61, 47, {}, out);
    for (int j = 0; j < 47; ++j)
      for (int i = 0; i < 61; ++i) {
        INFO("pixel " << i << ", " << j);
        REQUIRE_FALSE(std::isnan(out.at(i, j, 0)));
        CHECK(std::abs(out.at(i, j, 0) - (70 + 1.5 * i - 0.75 * j)) < 1e-9);
      }
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
      CHECK(out.at(int(mesh.points[v].x), int(mesh.points[v].y), 1) == mesh.value(v, 1));
  }
}

TEST_CASE("natural: pixels outside a non-convex domain stay uncovered") {
  // An L-shaped domain: the hull covers the notch, the mesh does not.
  Mesh mesh;
  mesh.points = {{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}};
  mesh.values = {0, 10, 20, 30, 40, 50};
  mesh.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 5}}, {{3, 4, 5}}};
  mesh.normalize_winding();
  Field out(11, 11, 1);
  render_natural(mesh, 11, 11, {}, out);
  CHECK(std::isnan(out.at(8, 8, 0)));
  CHECK_FALSE(std::isnan(out.at(5, 5, 0)));
  CHECK(out.at(5, 5, 0) == 30.0);
  CHECK_FALSE(std::isnan(out.at(2, 8, 0)));
}

TEST_CASE("natural: the in-hull search equals the located one, hull boundary included") {
  // Lattice sites with many collinear vertices on the hull's sides.
  std::vector<Point> sites;
  std::mt19937 rng(17);
  for (int y = 0; y <= 30; y += 3)
    for (int x = 0; x <= 40; x += 4)
      if (x == 0 || y == 0 || x == 40 || y == 30 || rng() % 2) sites.push_back({double(x), double(y)});
  SibsonCoordinates located(sites), walking(sites);
  std::vector<NeighbourWeight> a, b;
  for (int y = 0; y <= 30; ++y)
    for (int x = 0; x <= 40; ++x) {
      INFO("point " << x << ", " << y);
      const Point p{double(x), double(y)};
      REQUIRE(located.compute(p, a));
      REQUIRE(walking.compute_in_hull(p, b));
      std::map<std::uint32_t, double> ma, mb;
      for (const auto& nw : a) ma[nw.vertex] += nw.weight;
      for (const auto& nw : b) mb[nw.vertex] += nw.weight;
      for (const auto& [v, w] : ma) CHECK(std::abs(w - mb[v]) < 1e-12);
      for (const auto& [v, w] : mb) CHECK(std::abs(w - ma[v]) < 1e-12);
    }
}

TEST_CASE("natural: a Delaunay mesh is used as is, with the same result as a rebuilt triangulation") {
  const Mesh delaunay = tristream::testing::random_lattice_mesh(50, 40, 120, 31, 0, 1);
  const Mesh flipped = tristream::testing::random_lattice_mesh(50, 40, 120, 31, 60, 1);
  REQUIRE(is_locally_delaunay(delaunay, build_topology(delaunay)));
  REQUIRE_FALSE(is_locally_delaunay(flipped, build_topology(flipped)));
  Field a(50, 40, 1), b(50, 40, 1);
  render_natural(delaunay, 50, 40, {}, a);  // reuses the mesh's triangles
  render_natural(flipped, 50, 40, {}, b);   // builds the Delaunay triangulation
  for (std::size_t k = 0; k < a.v.size(); ++k) CHECK(std::abs(a.v[k] - b.v[k]) < 1e-9);
}

TEST_CASE("natural: scaled output and a single-triangle mesh") {
  // 61x47 domain rendered at 121x93 (corner to corner): linear data still exact.
  Mesh mesh = tristream::testing::random_lattice_mesh(61, 47, 80, 5, 0, 1);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    mesh.values[v] = 10 + 0.5 * mesh.points[v].x + 2 * mesh.points[v].y;
  Field out(121, 93, 1);
  render_natural(mesh, 61, 47, {}, out);
  const PixelMapping map(61, 47, 121, 93);
  for (int j = 0; j < 93; ++j)
    for (int i = 0; i < 121; ++i) {
      const Point p = map.sample(i, j);
      INFO("pixel " << i << ", " << j);
      REQUIRE_FALSE(std::isnan(out.at(i, j, 0)));
      CHECK(std::abs(out.at(i, j, 0) - (10 + 0.5 * p.x + 2 * p.y)) < 1e-9);
    }
  // One triangle: natural-neighbour coordinates inside it are its barycentric coordinates.
  Mesh one;
  one.points = {{0, 0}, {9, 0}, {0, 6}};
  one.values = {0, 90, 60};
  one.triangles = {{{0, 1, 2}}};
  one.normalize_winding();
  Field small(10, 7, 1);
  render_natural(one, 10, 7, {}, small);
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 10; ++i) {
      const bool inside = 6 * i + 9 * j <= 54;
      INFO("pixel " << i << ", " << j);
      CHECK(std::isnan(small.at(i, j, 0)) == !inside);
      if (inside) CHECK(small.at(i, j, 0) == Approx(10.0 * i + 10.0 * j).margin(1e-9));
    }
}

TEST_CASE("natural: the row sweep gives every pixel the coordinates of a per-point computation") {
  for (auto [w, h] : {std::pair{45, 33}, std::pair{89, 65}, std::pair{30, 20}}) {
    const Mesh mesh = tristream::testing::random_lattice_mesh(45, 33, 110, 77, 0, 1);
    SibsonCoordinates swept(mesh.points), single(mesh.points);
    const PixelMapping map(45, 33, w, h);
    std::vector<int> visits(std::size_t(w) * h, 0);
    std::vector<NeighbourWeight> expected;
    swept.for_each_sample(map, 44, 32, [&](int i, int j, const std::vector<NeighbourWeight>& got) {
      INFO("output " << w << "x" << h << ", pixel " << i << ", " << j);
      ++visits[std::size_t(j) * w + i];
      REQUIRE(single.compute(map.sample(i, j), expected));
      std::map<std::uint32_t, double> a, b;
      for (const auto& nw : got) a[nw.vertex] += nw.weight;
      for (const auto& nw : expected) b[nw.vertex] += nw.weight;
      for (const auto& [v, x] : a) CHECK(std::abs(x - b[v]) < 1e-12);
      for (const auto& [v, x] : b) CHECK(std::abs(x - a[v]) < 1e-12);
    });
    CHECK(std::count(visits.begin(), visits.end(), 1) == w * h);
  }
}
