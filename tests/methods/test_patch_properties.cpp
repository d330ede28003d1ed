// SPDX-License-Identifier: MIT
// Properties shared by the patch methods (bezier, coons), in both variants, and the exact
// micro-triangle rasterizer they use.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "../support/random_mesh.h"
#include "geometry/delaunay.h"
#include "common/errors.h"
#include "reference/methods/bilinear.h"
#include "reference/methods/patch/raster.h"
#include "reference/render.h"

using namespace tristream;

namespace {

Triangulation single_mesh(int w, int h, Mesh mesh) {
  Triangulation tri;
  tri.width = w;
  tri.height = h;
  tri.space = mesh.value_count == 3 ? ColorSpace::rgb : ColorSpace::grey;
  tri.layers.push_back(std::move(mesh));
  return tri;
}

Field render(const Triangulation& tri, const std::string& method, const std::string& variant, int w = 0, int h = 0) {
  const MethodInfo* m = find_reference_method(method);
  REQUIRE(m != nullptr);
  RenderOptions options;
  options.variant = variant;
  options.width = w;
  options.height = h;
  return render_reference_field(tri, *m, options);
}

template <class F>
void set_values(Mesh& mesh, F&& f) {
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int c = 0; c < mesh.value_count; ++c) mesh.values[v * mesh.value_count + c] = f(mesh.points[v], c);
}

struct Case {
  std::string method, variant;
};
const Case cases[] = {{"bezier", ""}, {"bezier", "thesis"}, {"coons", ""}, {"coons", "thesis"}};

}  // namespace

TEST_CASE("patch methods cover every pixel of the domain", "[bezier][coons]") {
  for (const Case& c : cases)
    for (std::uint32_t seed : {1u, 2u}) {
      INFO(c.method << " '" << c.variant << "' seed " << seed);
      const Triangulation tri = single_mesh(40, 30, testing::random_lattice_mesh(40, 30, 50, seed, 10));
      const Field f = render(tri, c.method, c.variant);
      for (double v : f.v) REQUIRE(std::isfinite(v));
    }
}

TEST_CASE("patch methods render a constant mesh as that constant", "[bezier][coons]") {
  for (const Case& c : cases) {
    INFO(c.method << " '" << c.variant << "'");
    Mesh mesh = testing::random_lattice_mesh(40, 30, 60, 3, 10, 3);
    set_values(mesh, [](const Point&, int ch) { return 17.0 + 50 * ch; });
    const Field f = render(single_mesh(40, 30, mesh), c.method, c.variant);
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x)
        for (int ch = 0; ch < 3; ++ch) REQUIRE(f.at(x, y, ch) == Approx(17.0 + 50 * ch).margin(1e-9));
  }
}

// Both patches are affine combinations of their control points in position and value alike,
// so linear data gives every surface point (x, y, L(x, y)).
TEST_CASE("the exact variant reproduces linear data", "[bezier][coons]") {
  const double gx = 1.3, gy = -0.8;
  auto linear = [&](const Point& p, int ch) { return 60.0 + gx * p.x + gy * p.y + 10 * ch; };
  for (const char* method : {"bezier", "coons"})
    for (std::uint32_t seed : {4u, 5u, 6u}) {
      INFO(method << " seed " << seed);
      Mesh mesh = testing::random_lattice_mesh(48, 40, 70, seed, 10, 3);
      set_values(mesh, linear);
      const Field f = render(single_mesh(48, 40, mesh), method, "");
      // Newton stops after a step below newton_step (patch/raster.h), leaving parameter errors
      // of about 1e-12 times the patch's relative curvature: far below 1e-6 of value here.
      for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 48; ++x)
          for (int ch = 0; ch < 3; ++ch)
            REQUIRE(f.at(x, y, ch) == Approx(linear({double(x), double(y)}, ch)).margin(1e-6));
    }
}

TEST_CASE("the exact variant reproduces linear data at another output size", "[bezier][coons]") {
  auto linear = [](const Point& p, int) { return 30.0 + 2 * p.x + p.y; };
  for (const char* method : {"bezier", "coons"}) {
    INFO(method);
    Mesh mesh = testing::random_lattice_mesh(40, 30, 50, 8, 5);
    set_values(mesh, linear);
    const Field f = render(single_mesh(40, 30, mesh), method, "", 79, 45);
    for (int y = 0; y < 45; ++y)
      for (int x = 0; x < 79; ++x)
        REQUIRE(f.at(x, y, 0) == Approx(linear({x * 39.0 / 78, y * 29.0 / 44}, 0)).margin(1e-6));
  }
}

// The thesis variant rounds each sample to the nearest pixel, so a pixel averages L over
// points at most half a pixel away in x and in y, plus the bilinear pre-fill L(x, y).
TEST_CASE("the thesis variant stays within half a pixel's slope of linear data", "[bezier][coons]") {
  const double gx = 1.3, gy = -0.8;
  auto linear = [&](const Point& p, int) { return 60.0 + gx * p.x + gy * p.y; };
  for (const char* method : {"bezier", "coons"}) {
    INFO(method);
    Mesh mesh = testing::random_lattice_mesh(40, 30, 50, 9, 10);
    set_values(mesh, linear);
    const Field f = render(single_mesh(40, 30, mesh), method, "thesis");
    double worst = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x)
        worst = std::max(worst, std::fabs(f.at(x, y, 0) - linear({double(x), double(y)}, 0)));
    CHECK(worst <= 0.5 * (std::fabs(gx) + std::fabs(gy)) + 1e-9);
    CHECK(worst > 0.01);  // the splatting does blur: it is not the exact variant
  }
}

// A Bezier patch is a convex combination of its control values, in both variants.
TEST_CASE("bezier stays within the vertex value range for any data", "[bezier]") {
  for (const char* variant : {"", "thesis"})
    for (std::uint32_t seed : {10u, 11u}) {
      INFO("'" << variant << "' seed " << seed);
      const Mesh mesh = testing::random_lattice_mesh(40, 30, 60, seed, 10);
      const auto [lo, hi] = std::minmax_element(mesh.values.begin(), mesh.values.end());
      const Field f = render(single_mesh(40, 30, mesh), "bezier", variant);
      for (double v : f.v) {
        REQUIRE(v >= *lo - 1e-9);
        REQUIRE(v <= *hi + 1e-9);
      }
    }
}

// Parabolas through three values overshoot when the data bends (0, 100, 100 peaks at 112.5),
// and on an irregular mesh even monotone data bends along a curve whose middle point is off
// centre (1, 0.2, 0 dips to -0.008). So the Coons patch keeps to the value range on smooth
// data over a regular mesh, which this checks.
TEST_CASE("coons stays within the vertex value range on a smooth regular mesh", "[coons]") {
  Mesh mesh;
  for (int y = 0; y <= 40; y += 4)
    for (int x = 0; x <= 48; x += 4) mesh.points.push_back({double(x), double(y)});
  mesh.triangles = delaunay_triangulation(mesh.points);
  mesh.values.resize(mesh.vertex_count());
  // Monotone in x and y, no interior extremum, gently curved.
  set_values(mesh, [](const Point& p, int) { return 128 + 40 * std::sin(p.x / 40 - 0.6) + 0.5 * p.y; });
  const auto [lo, hi] = std::minmax_element(mesh.values.begin(), mesh.values.end());
  for (const char* variant : {"", "thesis"}) {
    INFO("'" << variant << "'");
    const Field f = render(single_mesh(49, 41, mesh), "coons", variant);
    for (double v : f.v) {
      REQUIRE(v >= *lo - 1e-9);
      REQUIRE(v <= *hi + 1e-9);
    }
  }
}

TEST_CASE("patch methods fall back to bilinear without interior triangles", "[bezier][coons]") {
  // Two triangles: neither has three neighbours, so there is no patch (thesis §4.2).
  Mesh mesh;
  mesh.points = {{0, 0}, {19, 0}, {19, 14}, {0, 14}};
  mesh.values = {10, 200, 90, 40};
  mesh.triangles = {Triangle{{0, 1, 2}}, Triangle{{0, 2, 3}}};
  mesh.normalize_winding();
  const Triangulation tri = single_mesh(20, 15, mesh);
  const Field bilinear = render(tri, "bilinear", "");
  for (const Case& c : cases) {
    INFO(c.method << " '" << c.variant << "'");
    const Field f = render(tri, c.method, c.variant);
    for (std::size_t i = 0; i < f.v.size(); ++i) REQUIRE(f.v[i] == Approx(bilinear.v[i]).margin(1e-9));
  }
}

TEST_CASE("patch methods leave pixels outside a partial hull uncovered", "[bezier][coons]") {
  // A fan of triangles around (20, 15) that covers only the middle of a 40 x 30 image.
  Mesh mesh;
  mesh.points.push_back({20, 15});
  const int ring = 9;
  for (int k = 0; k < ring; ++k) {
    const double a = 2 * 3.14159265358979 * k / ring;
    mesh.points.push_back({std::round(20 + 10 * std::cos(a)), std::round(15 + 8 * std::sin(a))});
  }
  for (int k = 0; k < ring; ++k)
    mesh.triangles.push_back(Triangle{{0, std::uint32_t(1 + k), std::uint32_t(1 + (k + 1) % ring)}});
  // A second ring makes the inner triangles interior, so there are patches.
  for (int k = 0; k < ring; ++k) {
    const double a = 2 * 3.14159265358979 * (k + 0.5) / ring;
    mesh.points.push_back({std::round(20 + 17 * std::cos(a)), std::round(15 + 13 * std::sin(a))});
  }
  for (int k = 0; k < ring; ++k)
    mesh.triangles.push_back(
        Triangle{{std::uint32_t(1 + k), std::uint32_t(1 + ring + k), std::uint32_t(1 + (k + 1) % ring)}});
  mesh.normalize_winding();
  std::mt19937 rng(3);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) mesh.values.push_back(double(rng() % 256));
  const Triangulation tri = single_mesh(40, 30, mesh);
  const Field bilinear = render(tri, "bilinear", "");
  for (const Case& c : cases) {
    INFO(c.method << " '" << c.variant << "'");
    const Field f = render(tri, c.method, c.variant);
    int inside = 0;
    for (std::size_t i = 0; i < f.v.size(); ++i) {
      REQUIRE(std::isnan(f.v[i]) == std::isnan(bilinear.v[i]));
      inside += !std::isnan(f.v[i]);
    }
    CHECK(inside > 300);
    CHECK(inside < 40 * 30);
  }
}

TEST_CASE("patch methods reject an unknown variant", "[bezier][coons]") {
  const Triangulation tri = single_mesh(20, 15, testing::random_lattice_mesh(20, 15, 10, 1));
  for (const char* method : {"bezier", "coons"}) CHECK_THROWS_AS(render(tri, method, "fast"), UsageError);
}

// The bilinear pre-fill, and the tessellated candidates of the exact variant (Bezier patches
// that may fold), rest on this: micro-triangles that tile a region,
// with nodes anywhere (also exactly on pixel centres, so ties happen on edges and at nodes),
// cover each pixel sample point of the region exactly once, in either winding.
TEST_CASE("micro-triangles of a tiling cover each pixel exactly once", "[bezier][coons]") {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    // A Delaunay tiling of the square [2, 26]^2: its corners, points on its sides, inside
    // points half on pixel centres and half anywhere.
    std::vector<Point> p = {{2, 2}, {26, 2}, {26, 26}, {2, 26}};
    std::uniform_real_distribution<double> side(2, 26);
    for (int k = 0; k < 6; ++k) {
      const double a = std::round(side(rng)), b = side(rng);
      p.push_back({a, 2}), p.push_back({26, b}), p.push_back({b, 26}), p.push_back({2, a});
    }
    std::uniform_real_distribution<double> inner(2.5, 25.5);
    for (int k = 0; k < 40; ++k) {
      Point q{inner(rng), inner(rng)};
      if (k % 2) q = {std::round(q.x), std::round(q.y)};
      p.push_back(q);
    }
    std::sort(p.begin(), p.end(),
              [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }),
            p.end());
    const std::vector<Triangle> tiles = delaunay_triangulation(p);
    std::vector<detail::MicroVertex> node(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) REQUIRE(detail::snap(p[k].x, p[k].y, p[k].x, p[k].y, node[k]));
    std::vector<int> count(30 * 30, 0);
    auto visit = [&](int x, int y, double s, double t) {
      ++count[y * 30 + x];
      // The parameters here are the position: exact up to the 1/256-pixel snap of the nodes.
      CHECK(s == Approx(x).margin(1.0 / 256));
      CHECK(t == Approx(y).margin(1.0 / 256));
    };
    for (const Triangle& t : tiles) {
      if (trial % 2)
        detail::rasterize_micro_triangle(node[t.v[0]], node[t.v[2]], node[t.v[1]], 30, 30, visit);
      else
        detail::rasterize_micro_triangle(node[t.v[0]], node[t.v[1]], node[t.v[2]], 30, 30, visit);
    }
    // The square's own sides follow the tie rule: in the orient2d > 0 winding the square runs
    // (2,2) (26,2) (26,26) (2,26); edges going down (x = 26) or horizontally left (y = 26) own
    // their points, the others (y = 2, x = 2) do not.
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x) {
        INFO("trial " << trial << " pixel " << x << ", " << y);
        const bool inside = x > 2 && x <= 26 && y > 2 && y <= 26;
        REQUIRE(count[y * 30 + x] == (inside ? 1 : 0));
      }
  }
}

// The patches' pre-fill takes an integer fast path; it must agree with render_bilinear pixel
// for pixel: the same coverage, values equal up to rounding.
TEST_CASE("the patch pre-fill is the bilinear field", "[bezier][coons]") {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 12; ++trial) {
    Mesh mesh = testing::random_lattice_mesh(37, 29, 40 + trial * 5, 100 + trial, trial, 1 + 2 * (trial % 2));
    if (trial >= 8) {
      // Off the 1/256 grid: the fallback path.
      std::uniform_real_distribution<double> jitter(-0.3, 0.3);
      for (std::size_t v = 4; v < mesh.vertex_count(); ++v)
        mesh.points[v].x += jitter(rng), mesh.points[v].y += jitter(rng);
      mesh.triangles = delaunay_triangulation(mesh.points);
    } else if (trial >= 4) {
      // A partial domain: drop every triangle touching a corner.
      std::vector<Triangle> kept;
      for (const Triangle& t : mesh.triangles)
        if (t.v[0] > 3 && t.v[1] > 3 && t.v[2] > 3) kept.push_back(t);
      mesh.triangles = kept;
    }
    INFO("trial " << trial);
    Field fast(37, 29, mesh.value_count), reference(37, 29, mesh.value_count);
    detail::bilinear_prefill(mesh, build_topology(mesh), detail::triangles_by_cell(mesh), 37, 29, {}, fast);
    render_bilinear(mesh, 37, 29, {}, reference);
    for (std::size_t i = 0; i < fast.v.size(); ++i) {
      REQUIRE(std::isnan(fast.v[i]) == std::isnan(reference.v[i]));
      if (!std::isnan(fast.v[i])) REQUIRE(fast.v[i] == Approx(reference.v[i]).margin(1e-9));
    }
  }
}
