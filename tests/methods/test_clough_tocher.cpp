// SPDX-License-Identifier: MIT
// Clough-Tocher: interpolation, polynomial precision and C1 continuity.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>

#include "../support/random_mesh.h"
#include "model/topology.h"
#include "reference/gradients.h"
#include "reference/methods/clough_tocher.h"
#include "reference/methods/zienkiewicz.h"
#include "reference/render.h"

using namespace tristream;

namespace {

Triangulation single_mesh(int w, int h, Mesh mesh) {
  Triangulation tri;
  tri.width = w;
  tri.height = h;
  tri.layers.push_back(std::move(mesh));
  return tri;
}

Field render(const Triangulation& tri) {
  const MethodInfo* m = find_reference_method("clough-tocher");
  REQUIRE(m != nullptr);
  return render_reference_field(tri, *m, {});
}

// Barycentric coordinates of p in triangle (a, b, c).
std::array<double, 3> barycentric(const Point& a, const Point& b, const Point& c, const Point& p) {
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double l0 = ((b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x)) / area;
  const double l1 = ((c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x)) / area;
  return {l0, l1, 1 - l0 - l1};
}

// Derivative at p along unit direction d from f at p + s d, s = 0, h, 2h, 3h: the four-point
// one-sided formula is exact for cubics, so on one cubic piece only rounding remains (about
// 20 * 1e-16 * |f| / h).
template <class F>
double one_sided_derivative(F&& f, const Point& p, const Point& d, double h) {
  auto at = [&](double s) { return f(Point{p.x + s * d.x, p.y + s * d.y}); };
  return (-11 * at(0) + 18 * at(h) - 9 * at(2 * h) + 2 * at(3 * h)) / (6 * h);
}

// One piecewise function per triangle of a mesh, evaluated at any point of the plane.
struct PerTriangle {
  const Mesh& mesh;
  std::vector<CloughTocherTriangle> ct;
  std::vector<ZienkiewiczCoefficients> zk;

  PerTriangle(const Mesh& m, const std::vector<Gradient>& g) : mesh(m) {
    for (const Triangle& t : m.triangles) {
      const auto& v = t.v;
      ct.push_back(clough_tocher_triangle({m.points[v[0]], m.points[v[1]], m.points[v[2]]},
                                          {m.value(v[0], 0), m.value(v[1], 0), m.value(v[2], 0)},
                                          {g[v[0]], g[v[1]], g[v[2]]}));
      zk.push_back(zienkiewicz_coefficients(m.points[v[0]], m.points[v[1]], m.points[v[2]], m.value(v[0], 0),
                                            m.value(v[1], 0), m.value(v[2], 0), g[v[0]], g[v[1]], g[v[2]]));
    }
  }
  double value(std::size_t t, const Point& p, bool zienkiewicz = false) const {
    const auto& v = mesh.triangles[t].v;
    const auto l = barycentric(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], p);
    return zienkiewicz ? zienkiewicz_value(zk[t], l[0], l[1], l[2]) : clough_tocher_value(ct[t], l[0], l[1], l[2]);
  }
  double one_sided(std::size_t t, const Point& p, const Point& d, double h, bool zienkiewicz = false) const {
    return one_sided_derivative([&](const Point& r) { return value(t, r, zienkiewicz); }, p, d, h);
  }
};

struct EdgeMismatch {
  double value = 0;       // largest |f_left - f_right| on shared edges
  double derivative = 0;  // largest difference of the derivatives normal to the edge
};

// Compares the two triangles of every interior edge at points along it.
EdgeMismatch edge_mismatch(const Mesh& mesh, const PerTriangle& f, bool zienkiewicz) {
  const Topology topo = build_topology(mesh);
  EdgeMismatch worst;
  // Points within 3h of an edge, 10% of its length away from its ends, lie in the piece of
  // that edge unless the triangle is thinner than about 30h.
  const double h = 1e-3;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = topo.neighbour[3 * t + e];
      if (u == no_neighbour || u < t) continue;
      const Point& a = mesh.points[mesh.triangles[t].v[e]];
      const Point& b = mesh.points[mesh.triangles[t].v[(e + 1) % 3]];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      // Unit normal pointing into t (the left of a->b in orient2d terms, Mesh winding).
      const Point n{-(b.y - a.y) / len, (b.x - a.x) / len};
      for (double s = 0.1; s < 0.95; s += 0.1) {
        const Point p{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
        worst.value = std::max(worst.value, std::fabs(f.value(t, p, zienkiewicz) - f.value(u, p, zienkiewicz)));
        const double into_t = f.one_sided(t, p, n, h, zienkiewicz);
        const double into_u = f.one_sided(u, p, {-n.x, -n.y}, h, zienkiewicz);
        worst.derivative = std::max(worst.derivative, std::fabs(into_t + into_u));
      }
    }
  return worst;
}

}  // namespace

TEST_CASE("clough-tocher interpolates the vertex values", "[clough-tocher]") {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    const Mesh mesh = testing::random_lattice_mesh(48, 36, 80, seed, 20);
    const Triangulation tri = single_mesh(48, 36, mesh);
    const Field f = render(tri);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      const int x = int(mesh.points[v].x), y = int(mesh.points[v].y);
      REQUIRE(f.at(x, y, 0) == Approx(mesh.value(v, 0)).margin(1e-9));
    }
  }
}

TEST_CASE("clough-tocher reproduces linear data exactly", "[clough-tocher]") {
  Mesh mesh = testing::random_lattice_mesh(48, 36, 80, 7, 20, 3);
  auto linear = [](const Point& p, int c) { return 20.0 + (c + 1) * 1.1 * p.x - 0.9 * p.y + 40 * c; };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c) mesh.values[v * 3 + c] = linear(mesh.points[v], c);
  Triangulation tri = single_mesh(48, 36, mesh);
  tri.space = ColorSpace::rgb;
  const Field f = render(tri);
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 48; ++x)
      for (int c = 0; c < 3; ++c) REQUIRE(f.at(x, y, c) == Approx(linear({double(x), double(y)}, c)).margin(1e-9));
}

TEST_CASE("clough-tocher reproduces quadratics when the gradients are exact", "[clough-tocher]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(-20, 20), coef(-2, 2), bary(-0.2, 1.2);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<Point, 3> p{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    if (std::fabs(area) < 20) continue;
    const double k[6] = {coef(rng) * 50, coef(rng), coef(rng), coef(rng) / 4, coef(rng) / 4, coef(rng) / 4};
    auto q = [&](const Point& r) {
      return k[0] + k[1] * r.x + k[2] * r.y + k[3] * r.x * r.x + k[4] * r.x * r.y + k[5] * r.y * r.y;
    };
    auto grad = [&](const Point& r) {
      return Gradient{k[1] + 2 * k[3] * r.x + k[4] * r.y, k[2] + k[4] * r.x + 2 * k[5] * r.y};
    };
    const auto ct = clough_tocher_triangle(p, {q(p[0]), q(p[1]), q(p[2])}, {grad(p[0]), grad(p[1]), grad(p[2])});
    for (int s = 0; s < 20; ++s) {
      const double l0 = bary(rng), l1 = bary(rng), l2 = 1 - l0 - l1;
      const Point r{l0 * p[0].x + l1 * p[1].x + l2 * p[2].x, l0 * p[0].y + l1 * p[1].y + l2 * p[2].y};
      REQUIRE(clough_tocher_value(ct, l0, l1, l2) == Approx(q(r)).margin(1e-9));
    }
  }
}

TEST_CASE("clough-tocher does not reproduce cubics (the space is only C1 cubic splines)", "[clough-tocher]") {
  const std::array<Point, 3> p{Point{0, 0}, Point{10, 0}, Point{3, 8}};
  auto cubic = [](const Point& r) { return r.x * r.x * r.x / 100; };
  auto grad = [](const Point& r) { return Gradient{3 * r.x * r.x / 100, 0}; };
  const auto ct =
      clough_tocher_triangle(p, {cubic(p[0]), cubic(p[1]), cubic(p[2])}, {grad(p[0]), grad(p[1]), grad(p[2])});
  const Point centroid{13.0 / 3, 8.0 / 3};
  CHECK(std::fabs(clough_tocher_value(ct, 1.0 / 3, 1.0 / 3, 1.0 / 3) - cubic(centroid)) > 1e-3);
}

TEST_CASE("clough-tocher is C0 and C1 across the edges of a mesh", "[clough-tocher]") {
  for (std::uint32_t seed : {4u, 5u}) {
    const Mesh mesh = testing::random_lattice_mesh(40, 30, 60, seed, 0);
    const Topology topo = build_topology(mesh);
    const PerTriangle f(mesh, vertex_gradients(mesh, topo, 0));
    const EdgeMismatch ct = edge_mismatch(mesh, f, false);
    CHECK(ct.value < 1e-9);
    CHECK(ct.derivative < 1e-6);
    // The same check sees the kinks of zienkiewicz, which is only C0.
    const EdgeMismatch zk = edge_mismatch(mesh, f, true);
    CHECK(zk.value < 1e-9);
    CHECK(zk.derivative > 1.0);
  }
}

TEST_CASE("clough-tocher is C1 across the inner edges of the split", "[clough-tocher]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0, 30), val(0, 255), g(-20, 20);
  for (int trial = 0; trial < 50; ++trial) {
    const std::array<Point, 3> p{Point{coord(rng), coord(rng)}, Point{coord(rng), coord(rng)},
                                 Point{coord(rng), coord(rng)}};
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    if (std::fabs(area) < 40) continue;
    const auto ct =
        clough_tocher_triangle(p, {val(rng), val(rng), val(rng)},
                               {Gradient{g(rng), g(rng)}, Gradient{g(rng), g(rng)}, Gradient{g(rng), g(rng)}});
    auto f = [&](const Point& r) {
      const auto l = barycentric(p[0], p[1], p[2], r);
      return clough_tocher_value(ct, l[0], l[1], l[2]);
    };
    const Point s{(p[0].x + p[1].x + p[2].x) / 3, (p[0].y + p[1].y + p[2].y) / 3};
    const double h = 1e-3;
    for (int i = 0; i < 3; ++i) {
      const double len = std::hypot(s.x - p[i].x, s.y - p[i].y);
      const Point n{-(s.y - p[i].y) / len, (s.x - p[i].x) / len};
      for (double t = 0.1; t < 0.95; t += 0.1) {
        const Point q{p[i].x + t * (s.x - p[i].x), p[i].y + t * (s.y - p[i].y)};
        const double plus = one_sided_derivative(f, q, n, h);
        const double minus = one_sided_derivative(f, q, {-n.x, -n.y}, h);
        CHECK(std::fabs(plus + minus) < 1e-6);
      }
    }
  }
}
