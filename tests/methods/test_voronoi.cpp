// SPDX-License-Identifier: MIT
// Piecewise linear interpolation on the Voronoi diagram: the diagram against brute force, the
// polygon coordinates, and the renderer against an independent recomputation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "geometry/predicates.h"
#include "model/topology.h"
#include "reference/gradients.h"
#include "reference/methods/voronoi.h"
#include "reference/methods/zienkiewicz.h"
#include "reference/render.h"
#include "../support/random_mesh.h"
#include "methods_support.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

double dist(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The Voronoi cell of all[v] among `all` by half-plane clipping of a big box.
Polygon brute_force_cell(const std::vector<Point>& all, std::size_t v) {
  const double big = 1e7;
  Polygon cell = {{-big, -big}, {big, -big}, {big, big}, {-big, big}};
  for (std::size_t j = 0; j < all.size(); ++j)
    if (j != v) cell = clip_closer_to(cell, all[v], all[j]);
  // Drop vertices closer than 1e-9 to their predecessor (several cocircular bisectors).
  Polygon out;
  for (const Point& q : cell)
    if (out.empty() || dist(out.back(), q) > 1e-9) out.push_back(q);
  while (out.size() > 1 && dist(out.front(), out.back()) <= 1e-9) out.pop_back();
  return out;
}

void check_cells(const std::vector<Point>& sites) {
  const VoronoiDiagram voronoi(sites);
  REQUIRE(voronoi.site_count() == sites.size());
  std::vector<Point> all(voronoi.delaunay().points.begin(), voronoi.delaunay().points.end());
  REQUIRE(all.size() == sites.size() + 3);
  for (std::size_t v = 0; v < sites.size(); ++v) {
    INFO("site " << v << " (" << sites[v].x << ", " << sites[v].y << ")");
    const auto cell = voronoi.cell(std::uint32_t(v));
    const Polygon expected = brute_force_cell(all, v);
    REQUIRE(cell.size() == expected.size());
    CHECK(area(cell) == Approx(area(expected)).epsilon(1e-9));
    for (const Point& q : cell) {
      double best = std::numeric_limits<double>::infinity();
      for (const Point& e : expected) best = std::min(best, dist(q, e));
      CHECK(best < 1e-6);
    }
    for (std::size_t i = 0; i < cell.size(); ++i) CHECK(dist(cell[i], cell[(i + 1) % cell.size()]) > 1e-9);
  }
}

}  // namespace

TEST_CASE("voronoi: cells match brute-force half-plane intersection") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 60);
  std::vector<Point> sites = {{0, 0}, {60, 0}, {0, 40}, {60, 40}};
  for (int i = 0; i < 50; ++i) sites.push_back({u(rng), u(rng) * 40 / 60});
  check_cells(sites);
}

TEST_CASE("voronoi: cocircular lattice sites give cells without repeated vertices") {
  std::vector<Point> sites;
  for (int y = 0; y <= 12; y += 3)
    for (int x = 0; x <= 15; x += 3) sites.push_back({double(x), double(y)});
  sites.push_back({7, 7});
  check_cells(sites);
}

TEST_CASE("voronoi: nearest_site finds the nearest site") {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 100);
  std::vector<Point> sites;
  for (int i = 0; i < 300; ++i) sites.push_back({u(rng), u(rng)});
  const VoronoiDiagram voronoi(sites);
  for (int k = 0; k < 500; ++k) {
    const Point p{u(rng), u(rng)};
    double best = std::numeric_limits<double>::infinity();
    for (const Point& s : sites) best = std::min(best, dist(s, p));
    const std::uint32_t got = voronoi.nearest_site(p, std::uint32_t(k % sites.size()));
    CHECK(dist(sites[got], p) == best);
  }
}

TEST_CASE("voronoi: Meyer coordinates are barycentric with linear precision") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> w;
  for (int trial = 0; trial < 200; ++trial) {
    // A random convex polygon: sorted angles on an ellipse.
    const int n = 3 + trial % 7;
    std::vector<double> angle;
    for (int i = 0; i < n; ++i) angle.push_back(6.283185307179586 * u(rng));
    std::sort(angle.begin(), angle.end());
    Polygon poly;
    for (double a : angle) poly.push_back({10 + 7 * std::cos(a), 5 + 3 * std::sin(a)});
    if (area(poly) < 1) continue;
    // A point inside: a random convex combination.
    Point p{0, 0};
    double s = 0;
    std::vector<double> c(n);
    for (auto& x : c) s += x = u(rng) + 0.01;
    for (int i = 0; i < n; ++i) p.x += c[i] / s * poly[i].x, p.y += c[i] / s * poly[i].y;
    meyer_coordinates(poly, p, w);
    REQUIRE(w.size() == std::size_t(n));
    double sum = 0, x = 0, y = 0;
    for (int i = 0; i < n; ++i) {
      CHECK(w[i] > 0);
      sum += w[i], x += w[i] * poly[i].x, y += w[i] * poly[i].y;
    }
    CHECK(std::abs(sum - 1) < 1e-12);
    CHECK(std::abs(x - p.x) < 1e-9);
    CHECK(std::abs(y - p.y) < 1e-9);
    // Eq. 3.12 as the thesis writes it (cotangents at Q_j over |P - Q_j|^2), normalised.
    std::vector<double> cot(n);
    double cot_sum = 0;
    for (int j = 0; j < n; ++j) {
      const Point& q = poly[j];
      const Point& qp = poly[(j + n - 1) % n];
      const Point& qn = poly[(j + 1) % n];
      const double ax = p.x - q.x, ay = p.y - q.y;
      auto cotangent = [&](const Point& r) {
        const double rx = r.x - q.x, ry = r.y - q.y;
        return (ax * rx + ay * ry) / std::abs(ax * ry - ay * rx);
      };
      cot[j] = (cotangent(qp) + cotangent(qn)) / (ax * ax + ay * ay);
      cot_sum += cot[j];
    }
    for (int j = 0; j < n; ++j) CHECK(std::abs(w[j] - cot[j] / cot_sum) < 1e-9);
    // Next to an edge (within rounding of it): linear interpolation along the edge.
    const int e = trial % n;
    const Point& a = poly[e];
    const Point& b = poly[(e + 1) % n];
    const double t = 0.1 + 0.8 * u(rng);
    const Point on_edge{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    meyer_coordinates(poly, on_edge, w);
    CHECK(std::abs(w[e] - (1 - t)) < 1e-6);
    CHECK(std::abs(w[(e + 1) % n] - t) < 1e-6);
  }
  // On an edge: the thesis's fallback, linear along the edge; at a vertex: that vertex.
  const Polygon square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  meyer_coordinates(square, {1, 0}, w);
  CHECK(w == std::vector<double>{0.75, 0.25, 0, 0});
  meyer_coordinates(square, {4, 4}, w);
  CHECK(w == std::vector<double>{0, 0, 1, 0});
  meyer_coordinates(square, {2, 2}, w);
  for (double x : w) CHECK(x == Approx(0.25));
}

TEST_CASE("voronoi: the renderer equals an independent recomputation of the thesis's method") {
  const int W = 48, H = 36;
  const Mesh mesh = tristream::testing::random_lattice_mesh(W, H, 90, 21, 30, 1);
  Field out(W, H, 1);
  render_voronoi(mesh, W, H, {}, out);
  Field bilinear(W, H, 1);
  find_reference_method("bilinear")->render(mesh, W, H, {}, bilinear);

  const VoronoiDiagram voronoi(mesh.points);
  const Topology topo = build_topology(mesh);
  const std::vector<Gradient> grad = vertex_gradients(mesh, topo, 0);
  // Zienkiewicz at q by brute-force point location.
  auto zienkiewicz_at = [&](const Point& q) {
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& v = mesh.triangles[t].v;
      const Point &a = mesh.points[v[0]], &b = mesh.points[v[1]], &c = mesh.points[v[2]];
      if (orient2d(a, b, q) < 0 || orient2d(b, c, q) < 0 || orient2d(c, a, q) < 0) continue;
      const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      const double la = ((b.x - q.x) * (c.y - q.y) - (b.y - q.y) * (c.x - q.x)) / d;
      const double lb = ((c.x - q.x) * (a.y - q.y) - (c.y - q.y) * (a.x - q.x)) / d;
      const auto k = zienkiewicz_coefficients(a, b, c, mesh.value(v[0], 0), mesh.value(v[1], 0), mesh.value(v[2], 0),
                                              grad[v[0]], grad[v[1]], grad[v[2]]);
      return zienkiewicz_value(k, la, lb, 1 - la - lb);
    }
    return std::numeric_limits<double>::quiet_NaN();
  };

  int interpolated = 0, prefilled = 0;
  std::vector<double> w;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      INFO("pixel " << i << ", " << j);
      const Point p{double(i), double(j)};
      REQUIRE_FALSE(std::isnan(out.at(i, j, 0)));
      // The nearest site by brute force; on a tie the renderer may use either cell, and
      // both give the same value on their shared edge unless one of them is pre-filled.
      std::uint32_t site = 0;
      for (std::uint32_t v = 1; v < mesh.points.size(); ++v)
        if (dist(mesh.points[v], p) < dist(mesh.points[site], p)) site = v;
      const auto cell = voronoi.cell(site);
      bool unclipped = true;
      for (const Point& q : cell) unclipped = unclipped && q.x > 0 && q.x < W - 1 && q.y > 0 && q.y < H - 1;
      bool corner = false;
      for (const Point& c : {Point{0, 0}, Point{W - 1.0, 0}, Point{0, H - 1.0}, Point{W - 1.0, H - 1.0}}) {
        std::uint32_t nearest = 0;
        for (std::uint32_t v = 1; v < mesh.points.size(); ++v)
          if (dist(mesh.points[v], c) < dist(mesh.points[nearest], c)) nearest = v;
        corner = corner || nearest == site;
      }
      if (corner) {
        CHECK(out.at(i, j, 0) == Approx(bilinear.at(i, j, 0)).margin(1e-9));
        ++prefilled;
      } else if (unclipped) {
        meyer_coordinates(cell, p, w);
        double expected = 0;
        for (std::size_t k = 0; k < cell.size(); ++k) expected += w[k] * zienkiewicz_at(cell[k]);
        CHECK(out.at(i, j, 0) == Approx(expected).margin(1e-6));
        ++interpolated;
      }
    }
  CHECK(interpolated > W * H / 3);
  CHECK(prefilled >= 4);
}

TEST_CASE("voronoi: linear data is reproduced in every cell whose vertices are all inside") {
  const int W = 64, H = 48;
  Mesh mesh = tristream::testing::random_lattice_mesh(W, H, 200, 4, 0, 1);
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    mesh.values[v] = 20 + 2 * mesh.points[v].x + 1.5 * mesh.points[v].y;
  Field out(W, H, 1);
  render_voronoi(mesh, W, H, {}, out);
  const VoronoiDiagram voronoi(mesh.points);
  int checked = 0;
  double worst_border = 0;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const Point p{double(i), double(j)};
      const double truth = 20 + 2 * i + 1.5 * j;
      std::uint32_t site = 0;
      for (std::uint32_t v = 1; v < mesh.points.size(); ++v)
        if (dist(mesh.points[v], p) < dist(mesh.points[site], p)) site = v;
      bool unclipped = true;
      for (const Point& q : voronoi.cell(site))
        unclipped = unclipped && q.x > 0 && q.x < W - 1 && q.y > 0 && q.y < H - 1;
      if (unclipped) {
        CHECK(std::abs(out.at(i, j, 0) - truth) < 1e-9);
        ++checked;
      } else {
        worst_border = std::max(worst_border, std::abs(out.at(i, j, 0) - truth));
      }
    }
  CHECK(checked > W * H / 2);
  // The thesis's clip-vertex rule is not linear: border cells are visibly off.
  CHECK(worst_border > 0.5);
}

TEST_CASE("voronoi: only pixels of the mesh's domain are written") {
  Mesh mesh;
  mesh.points = {{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}, {2, 2}, {7, 2}};
  mesh.values = {0, 10, 20, 30, 40, 50, 60, 70};
  mesh.triangles = {{{0, 1, 7}}, {{1, 2, 7}}, {{7, 2, 3}}, {{0, 7, 6}},
                    {{6, 7, 3}}, {{0, 6, 5}}, {{6, 3, 5}}, {{3, 4, 5}}};
  mesh.normalize_winding();
  Field out(11, 11, 1);
  render_voronoi(mesh, 11, 11, {}, out);
  for (int j = 0; j <= 10; ++j)
    for (int i = 0; i <= 10; ++i) {
      INFO("pixel " << i << ", " << j);
      CHECK(std::isnan(out.at(i, j, 0)) == (i > 5 && j > 5));
    }
}

TEST_CASE("voronoi: scaled output, a single triangle and a mesh short of the image still render") {
  const Mesh mesh = tristream::testing::random_lattice_mesh(40, 30, 50, 9, 10, 3);
  Field out(79, 59, 3);
  render_voronoi(mesh, 40, 30, {}, out);
  for (double v : out.v) CHECK_FALSE(std::isnan(v));
  Mesh one;
  one.points = {{0, 0}, {9, 0}, {0, 6}};
  one.values = {0, 90, 60};
  one.triangles = {{{0, 1, 2}}};
  one.normalize_winding();
  Field small(10, 7, 1);
  render_voronoi(one, 10, 7, {}, small);
  for (int j = 0; j < 7; ++j)
    for (int i = 0; i < 10; ++i) {
      INFO("pixel " << i << ", " << j);
      // Three cells, each holding a corner of the image: all bilinear pre-fill.
      const bool inside = 6 * i + 9 * j <= 54;
      CHECK(std::isnan(small.at(i, j, 0)) == !inside);
      if (inside) CHECK(small.at(i, j, 0) == Approx(10.0 * i + 10.0 * j).margin(1e-9));
    }
}
