// SPDX-License-Identifier: MIT
// find_mesh_defect against a brute-force check of every pair, on valid and damaged meshes.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "geometry/delaunay.h"
#include "geometry/mesh_check.h"
#include "geometry/predicates.h"
#include "../support/mesh_brute_force.h"

using namespace tristream;
using namespace tristream::testing;

TEST_CASE("Delaunay triangulations, lattices included, have no defect") {
  std::mt19937 rng(7);
  for (int round = 0; round < 200; ++round) {
    std::vector<Point> pts;
    const int n = 3 + int(rng() % 60);
    const bool lattice = round % 2 == 0;
    std::uniform_int_distribution<int> coord(0, lattice ? 6 : 1000);
    for (int i = 0; i < n; ++i) {
      const Point q{double(coord(rng)), double(coord(rng))};
      bool dup = false;
      for (const Point& o : pts) dup = dup || (o.x == q.x && o.y == q.y);
      if (!dup) pts.push_back(q);
    }
    const auto tris = delaunay_triangulation(pts);
    if (tris.empty()) continue;
    INFO("round " << round);
    CHECK_FALSE(find_mesh_defect(pts, tris).has_value());
  }
}

TEST_CASE("damaged meshes: the sweep finds a defect exactly when the brute force does") {
  std::mt19937 rng(11);
  int defects = 0, valid = 0;
  for (int round = 0; round < 3000; ++round) {
    std::vector<Point> pts;
    const int n = 4 + int(rng() % 25);
    std::uniform_int_distribution<int> coord(0, round % 3 == 0 ? 5 : 40);  // small grids: many collinear cases
    for (int i = 0; i < n; ++i) {
      const Point q{double(coord(rng)), double(coord(rng))};
      bool dup = false;
      for (const Point& o : pts) dup = dup || (o.x == q.x && o.y == q.y);
      if (!dup) pts.push_back(q);
    }
    std::vector<Triangle> tris = delaunay_triangulation(pts);
    if (tris.empty()) continue;
    switch (round % 4) {
      case 0: {  // move one vertex somewhere else
        const std::size_t v = rng() % pts.size();
        const Point q{double(coord(rng)), double(coord(rng))};
        bool dup = false;
        for (const Point& o : pts) dup = dup || (o.x == q.x && o.y == q.y);
        if (!dup) pts[v] = q;
        break;
      }
      case 1:  // drop some triangles (holes, T-junctions of unused vertices do not count)
        for (std::size_t k = 0; k < 1 + rng() % 3 && tris.size() > 1; ++k)
          tris.erase(tris.begin() + long(rng() % tris.size()));
        break;
      case 2: {  // add a random triangle
        Triangle t;
        for (auto& v : t.v) v = std::uint32_t(rng() % pts.size());
        if (t.v[0] != t.v[1] && t.v[1] != t.v[2] && t.v[0] != t.v[2]) tris.push_back(t);
        break;
      }
      default: {  // replace a triangle by a random one
        Triangle t;
        for (auto& v : t.v) v = std::uint32_t(rng() % pts.size());
        if (t.v[0] != t.v[1] && t.v[1] != t.v[2] && t.v[0] != t.v[2]) tris[rng() % tris.size()] = t;
        break;
      }
    }
    tris = positive(pts, tris);
    if (tris.empty()) continue;
    const bool expected = brute_force_defect(pts, tris);
    INFO("round " << round);
    REQUIRE(find_mesh_defect(pts, tris).has_value() == expected);
    (expected ? defects : valid) += 1;
  }
  CHECK(defects > 500);
  CHECK(valid > 500);
}

TEST_CASE("defects are classified") {
  // The T-junction of issue 17: (10,10) lies inside the edge (0,0)-(20,20) of the first triangle.
  const std::vector<Point> p{{0, 0}, {20, 0}, {0, 20}, {20, 20}, {10, 10}};
  const auto t = positive(p, {{{0, 1, 3}}, {{0, 4, 2}}, {{4, 3, 2}}});
  const auto d = find_mesh_defect(p, t);
  REQUIRE(d);
  CHECK(d->kind == MeshDefect::Kind::t_junction);
  CHECK(d->vertex == 4);
  CHECK(d->a == 0);
  // A triangle inside another, no edges crossing.
  const std::vector<Point> q{{0, 0}, {30, 0}, {0, 30}, {5, 5}, {8, 5}, {5, 8}};
  const auto nested = find_mesh_defect(q, positive(q, {{{0, 1, 2}}, {{3, 4, 5}}}));
  REQUIRE(nested);
  CHECK(nested->kind == MeshDefect::Kind::overlap);
  // The same triangle twice.
  const auto twice = find_mesh_defect(q, positive(q, {{{0, 1, 2}}, {{2, 1, 0}}}));
  REQUIRE(twice);
  CHECK(twice->kind == MeshDefect::Kind::overlap);
}
