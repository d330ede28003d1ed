// SPDX-License-Identifier: MIT
// The Bezier triangle patch of one triangle and its neighbours (thesis §3.3, docs/CONVENTIONS.md).
#include <catch2/catch.hpp>

#include "methods_support.h"
#include "model/topology.h"
#include "reference/methods/bezier.h"

using namespace tristream;
using tristream::testing::four_triangles;

namespace {

bool same(const Point& p, const Point& q) {
  return p.x == Approx(q.x).margin(1e-12) && p.y == Approx(q.y).margin(1e-12);
}

}  // namespace

TEST_CASE("bezier control points: the triangle's vertices and its neighbours' apexes", "[bezier]") {
  // A regular configuration: A, B, C are the midpoints of the big triangle of the apexes.
  const Point a{10, 4}, b{14, 10}, c{6, 10};
  const Point n_ab{18, 4}, n_bc{10, 16}, n_ca{2, 4};
  const Mesh mesh = four_triangles(a, b, c, n_ab, n_bc, n_ca);
  const Topology topo = build_topology(mesh);
  PatchControl control;
  REQUIRE(patch_control(mesh, topo, 0, PixelMapping(20, 20, 20, 20), control));
  // Triangle 0 keeps its vertex order (positive already) and so its edges AB, BC, CA.
  CHECK(same(control.pixel[p110], a));
  CHECK(same(control.pixel[p011], b));
  CHECK(same(control.pixel[p101], c));
  CHECK(same(control.pixel[p200], n_ca));
  CHECK(same(control.pixel[p020], n_ab));
  CHECK(same(control.pixel[p002], n_bc));
  CHECK(control.value[p200] == 60);
  CHECK(control.value[p020] == 40);
  CHECK(control.value[p002] == 50);

  const BezierPatch patch(control);
  // It passes through the apexes, not through A, B, C (it smooths)...
  CHECK(same(patch.position(1, 0), n_ca));
  CHECK(same(patch.position(0, 1), n_ab));
  CHECK(same(patch.position(0, 0), n_bc));
  double v = 0;
  patch.values(0.5, 0.5, &v);
  CHECK(v == Approx((60 + 2 * 10 + 40) / 4.0));
  // ...and here, with A, B, C at the midpoints, the position is affine: one micro-triangle.
  for (double s = 0; s <= 1; s += 0.125)
    for (double t = 0; s + t <= 1; t += 0.125) {
      const double r = 1 - s - t;
      CHECK(same(patch.position(s, t), {s * n_ca.x + t * n_ab.x + r * n_bc.x, s * n_ca.y + t * n_ab.y + r * n_bc.y}));
    }
  CHECK(patch.subdivisions() == 1);
}

TEST_CASE("bezier position derivatives match differences", "[bezier]") {
  const Mesh mesh = four_triangles({10, 4}, {15, 11}, {5, 9}, {19, 2}, {11, 17}, {1, 5});
  const Topology topo = build_topology(mesh);
  PatchControl control;
  REQUIRE(patch_control(mesh, topo, 0, PixelMapping(20, 20, 20, 20), control));
  const BezierPatch patch(control);
  CHECK(patch.subdivisions() > 1);
  for (double s = 0.1; s < 0.9; s += 0.2)
    for (double t = 0.05; s + t < 0.95; t += 0.2) {
      double x, y, xs, xt, ys, yt;
      patch.position(s, t, x, y, xs, xt, ys, yt);
      const double h = 1e-6;
      // Central differences are exact for quadratics up to rounding (about 1e-16 * 20 / h).
      CHECK(xs == Approx((patch.position(s + h, t).x - patch.position(s - h, t).x) / (2 * h)).margin(1e-8));
      CHECK(xt == Approx((patch.position(s, t + h).x - patch.position(s, t - h).x) / (2 * h)).margin(1e-8));
      CHECK(ys == Approx((patch.position(s + h, t).y - patch.position(s - h, t).y) / (2 * h)).margin(1e-8));
      CHECK(yt == Approx((patch.position(s, t + h).y - patch.position(s, t - h).y) / (2 * h)).margin(1e-8));
    }
}

TEST_CASE("a border triangle has no bezier patch", "[bezier]") {
  const Mesh mesh = four_triangles({10, 4}, {14, 10}, {6, 10}, {18, 4}, {10, 16}, {2, 4});
  const Topology topo = build_topology(mesh);
  PatchControl control;
  for (std::uint32_t t = 1; t < 4; ++t)
    CHECK_FALSE(patch_control(mesh, topo, t, PixelMapping(20, 20, 20, 20), control));
}
