// SPDX-License-Identifier: MIT
// The Coons patch of one triangle and its neighbours (thesis §3.4, docs/CONVENTIONS.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "methods_support.h"
#include "model/topology.h"
#include "reference/methods/coons.h"

using namespace tristream;
using tristream::testing::four_triangles;

namespace {

PatchControl control_of(const Mesh& mesh) {
  const Topology topo = build_topology(mesh);
  PatchControl control;
  REQUIRE(patch_control(mesh, topo, 0, PixelMapping(30, 30, 30, 30), control));
  return control;
}

Point parabola(const Point& s, const Point& m, const Point& e, double t) {
  const Parabola x = Parabola::through(s.x, m.x, e.x), y = Parabola::through(s.y, m.y, e.y);
  return {x(t), y(t)};
}

void check_same(const Point& p, const Point& q) {
  CHECK(p.x == Approx(q.x).margin(1e-9));
  CHECK(p.y == Approx(q.y).margin(1e-9));
}

}  // namespace

TEST_CASE("coons boundary: the split curve's halves and the other two curves", "[coons]") {
  // Irregular, the curve through C (P200, P101, P002) is the longest.
  const Mesh mesh = four_triangles({12, 6}, {17, 12}, {5, 15}, {19, 3}, {13, 20}, {2, 6});
  const PatchControl control = control_of(mesh);
  const CoonsPatch patch(control);
  REQUIRE(patch.longest_curve() == 2);
  const auto k = patch.corners();  // A, M, B, C
  CHECK(k[0] == p200);
  CHECK(k[1] == p101);
  CHECK(k[2] == p002);
  CHECK(k[3] == p020);
  const Point A = control.pixel[k[0]], M = control.pixel[k[1]], B = control.pixel[k[2]], C = control.pixel[k[3]];
  const Point m_ac = control.pixel[p110], m_bc = control.pixel[p011];
  check_same(patch.position(0, 0), A);
  check_same(patch.position(1, 0), M);
  check_same(patch.position(1, 1), B);
  check_same(patch.position(0, 1), C);
  for (double t = 0; t <= 1; t += 0.125) {
    // The halves are the original curve A..M..B (T0.25 goes with A..M, T0.75 with M..B).
    check_same(patch.position(t, 0), parabola(A, M, B, t / 2));
    check_same(patch.position(1, t), parabola(A, M, B, (1 + t) / 2));
    check_same(patch.position(0, t), parabola(A, m_ac, C, t));
    check_same(patch.position(t, 1), parabola(C, m_bc, B, t));
  }
  // Values follow the same construction: the boundary values at M and at the middle of A..C.
  double v = 0;
  patch.values(1, 0, &v);
  CHECK(v == Approx(control.value[p101]));
  patch.values(0, 0.5, &v);
  CHECK(v == Approx(control.value[p110]));
}

// A regular configuration and mild perturbations of it: the Jacobian keeps one sign over the
// open square, so the patch does not fold over itself.
TEST_CASE("coons patch of a regular configuration does not fold", "[coons]") {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> jitter(-0.6, 0.6);
  for (int trial = 0; trial < 30; ++trial) {
    const double j = trial == 0 ? 0 : 1;
    auto p = [&](double x, double y) { return Point{x + j * jitter(rng), y + j * jitter(rng)}; };
    // Big triangle (2, 4) (22, 4) (12, 21.3): A, B, C near its edge midpoints.
    const Mesh mesh = four_triangles(p(12, 4), p(17, 12.65), p(7, 12.65), p(22, 4), p(12, 21.3), p(2, 4));
    const CoonsPatch patch(control_of(mesh));
    int positive = 0, negative = 0;
    for (double u = 0.0125; u < 1; u += 0.025)
      for (double v = 0.0125; v < 1; v += 0.025) {
        double x, y, xu, xv, yu, yv;
        patch.position(u, v, x, y, xu, xv, yu, yv);
        const double det = xu * yv - xv * yu;
        positive += det > 0, negative += det < 0;
      }
    INFO("trial " << trial);
    CHECK((positive == 0 || negative == 0));
  }
}

TEST_CASE("coons position derivatives match differences", "[coons]") {
  const Mesh mesh = four_triangles({12, 6}, {17, 12}, {5, 15}, {19, 3}, {13, 20}, {2, 6});
  const CoonsPatch patch(control_of(mesh));
  for (double u = 0.1; u < 1; u += 0.2)
    for (double v = 0.1; v < 1; v += 0.2) {
      double x, y, xu, xv, yu, yv;
      patch.position(u, v, x, y, xu, xv, yu, yv);
      const double h = 1e-5;
      // Central differences err by h^2 |P'''| / 6 (P is cubic in u v^2, u^2 v) plus rounding.
      CHECK(xu == Approx((patch.position(u + h, v).x - patch.position(u - h, v).x) / (2 * h)).margin(1e-6));
      CHECK(xv == Approx((patch.position(u, v + h).x - patch.position(u, v - h).x) / (2 * h)).margin(1e-6));
      CHECK(yu == Approx((patch.position(u + h, v).y - patch.position(u - h, v).y) / (2 * h)).margin(1e-6));
      CHECK(yv == Approx((patch.position(u, v + h).y - patch.position(u, v - h).y) / (2 * h)).margin(1e-6));
    }
}
