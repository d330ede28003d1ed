// find_mesh_defect against a brute-force check of every pair, on valid and damaged meshes.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "geometry/delaunay.h"
#include "geometry/mesh_check.h"
#include "geometry/predicates.h"

using namespace tristream;

namespace {

// Interiors of two positive triangles overlap iff no edge line of either separates them.
bool interiors_overlap(const std::vector<Point>& p, const Triangle& a, const Triangle& b) {
  auto separated = [&](const Triangle& s, const Triangle& t) {
    for (int e = 0; e < 3; ++e) {
      const Point& u = p[s.v[e]];
      const Point& w = p[s.v[(e + 1) % 3]];
      if (orient2d(u, w, p[t.v[0]]) <= 0 && orient2d(u, w, p[t.v[1]]) <= 0 && orient2d(u, w, p[t.v[2]]) <= 0)
        return true;
    }
    return false;
  };
  return !separated(a, b) && !separated(b, a);
}

bool strictly_inside_segment(const Point& a, const Point& b, const Point& q) {
  if (orient2d(a, b, q) != 0) return false;
  const bool x_between = (a.x < q.x && q.x < b.x) || (b.x < q.x && q.x < a.x);
  const bool y_between = (a.y < q.y && q.y < b.y) || (b.y < q.y && q.y < a.y);
  return a.x == b.x ? (q.x == a.x && y_between) : x_between;
}

// Every pair of triangles, and every used vertex against every edge.
bool brute_force_defect(const std::vector<Point>& p, const std::vector<Triangle>& t) {
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 1; j < t.size(); ++j)
      if (interiors_overlap(p, t[i], t[j])) return true;
  std::vector<char> used(p.size(), 0);
  for (const Triangle& tri : t)
    for (auto v : tri.v) used[v] = 1;
  for (const Triangle& tri : t)
    for (int e = 0; e < 3; ++e)
      for (std::uint32_t v = 0; v < p.size(); ++v)
        if (used[v] && strictly_inside_segment(p[tri.v[e]], p[tri.v[(e + 1) % 3]], p[v])) return true;
  return false;
}

// Drops degenerate triangles and makes the others positive.
std::vector<Triangle> positive(const std::vector<Point>& p, std::vector<Triangle> t) {
  std::vector<Triangle> out;
  for (Triangle tri : t) {
    const double o = orient2d(p[tri.v[0]], p[tri.v[1]], p[tri.v[2]]);
    if (o == 0) continue;
    if (o < 0) std::swap(tri.v[1], tri.v[2]);
    out.push_back(tri);
  }
  return out;
}

}  // namespace

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
