// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "../support/random_mesh.h"
#include "reference/coverage.h"
#include "reference/methods/zienkiewicz.h"
#include "reference/render.h"

using namespace tristream;
using tristream::testing::random_lattice_mesh;

namespace {

Triangulation single(const Mesh& mesh, int w, int h, ColorSpace space = ColorSpace::grey) {
  Triangulation t;
  t.width = w;
  t.height = h;
  t.space = space;
  t.layers = {mesh};
  return t;
}

Field render_field(const Triangulation& tri, std::string_view method, int w = 0, int h = 0) {
  RenderOptions o;
  o.width = w;
  o.height = h;
  return render_reference_field(tri, *find_reference_method(method), o);
}

}  // namespace

TEST_CASE("every pixel is owned by exactly one triangle") {
  struct Case {
    int w, h, points, flips, out_w, out_h;
  };
  const Case cases[] = {{16, 16, 20, 0, 16, 16},   {64, 48, 200, 0, 64, 48},  {64, 48, 200, 300, 64, 48},
                        {33, 7, 60, 50, 33, 7},    {5, 90, 40, 40, 5, 90},    {64, 48, 150, 100, 37, 23},
                        {64, 48, 150, 100, 200, 129}, {40, 40, 1200, 0, 40, 40}};  // 40x40 dense: most lattice points
  std::uint32_t seed = 1;
  for (const Case& c : cases) {
    for (int rep = 0; rep < 3; ++rep, ++seed) {
      Mesh mesh = random_lattice_mesh(c.w, c.h, c.points, seed, c.flips);
      const Topology topo = build_topology(mesh);
      const PixelMapping map(c.w, c.h, c.out_w, c.out_h);
      std::vector<int> count(std::size_t(c.out_w) * c.out_h, 0);
      for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for_each_owned_pixel(mesh, topo, t, map,
                             [&](int i, int j, double, double, double) { ++count[j * c.out_w + i]; });
      int wrong = 0;
      for (int v : count) wrong += v != 1;
      INFO("case " << c.w << "x" << c.h << " points " << c.points << " flips " << c.flips << " out " << c.out_w
                   << "x" << c.out_h << " seed " << seed);
      CHECK(wrong == 0);
    }
  }
}

TEST_CASE("every pixel is owned exactly once with sub-pixel vertices") {
  // Lattices of step 1/2 (exact, many edges through pixel centres) and 1/3 (inexact decimals).
  for (int step : {2, 3}) {
    for (std::uint32_t seed = 200; seed < 204; ++seed) {
      const int w = 30, h = 22;
      Mesh mesh = random_lattice_mesh(step * (w - 1) + 1, step * (h - 1) + 1, 300, seed, 100);
      for (Point& p : mesh.points) p = {p.x / step, p.y / step};
      const Topology topo = build_topology(mesh);
      for (auto [ow, oh] : {std::pair{w, h}, std::pair{47, 31}}) {
        const PixelMapping map(w, h, ow, oh);
        std::vector<int> count(std::size_t(ow) * oh, 0);
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
          for_each_owned_pixel(mesh, topo, t, map, [&](int i, int j, double, double, double) { ++count[j * ow + i]; });
        int wrong = 0;
        for (int v : count) wrong += v != 1;
        INFO("step 1/" << step << " seed " << seed << " output " << ow << "x" << oh);
        CHECK(wrong == 0);
      }
    }
  }
}

TEST_CASE("vertex values are reproduced exactly") {
  for (std::uint32_t seed = 10; seed < 14; ++seed) {
    Mesh mesh = random_lattice_mesh(50, 40, 120, seed, 40);
    const Triangulation tri = single(mesh, 50, 40);
    for (const char* method : {"bilinear", "zienkiewicz"}) {
      const Field f = render_field(tri, method);
      for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        INFO(method << " vertex " << v);
        CHECK(f.at(int(mesh.points[v].x), int(mesh.points[v].y), 0) == Approx(mesh.value(v, 0)).margin(1e-9));
      }
    }
  }
}

TEST_CASE("linear data is reproduced exactly by bilinear and zienkiewicz") {
  Mesh mesh = random_lattice_mesh(60, 45, 150, 77, 80);
  auto linear = [](double x, double y) { return 0.7 * x - 1.3 * y + 100.0; };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) mesh.values[v] = linear(mesh.points[v].x, mesh.points[v].y);
  const Triangulation tri = single(mesh, 60, 45);
  for (const char* method : {"bilinear", "zienkiewicz"}) {
    const Field f = render_field(tri, method);
    double worst = 0;
    for (int j = 0; j < 45; ++j)
      for (int i = 0; i < 60; ++i) worst = std::max(worst, std::abs(f.at(i, j, 0) - linear(i, j)));
    INFO(method);
    CHECK(worst < 1e-9);
  }
}

TEST_CASE("zienkiewicz with exact gradients reproduces quadratic data") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(0, 100), coef(-1, 1), bary(0, 1);
  for (int rep = 0; rep < 50; ++rep) {
    const double q[6] = {coef(rng), coef(rng), coef(rng), coef(rng) * 10, coef(rng) * 10, coef(rng) * 100};
    auto f = [&](const Point& p) {
      return q[0] * p.x * p.x + q[1] * p.x * p.y + q[2] * p.y * p.y + q[3] * p.x + q[4] * p.y + q[5];
    };
    auto g = [&](const Point& p) {
      return Gradient{2 * q[0] * p.x + q[1] * p.y + q[3], q[1] * p.x + 2 * q[2] * p.y + q[4]};
    };
    const Point a{coord(rng), coord(rng)}, b{coord(rng), coord(rng)}, c{coord(rng), coord(rng)};
    const auto k = zienkiewicz_coefficients(a, b, c, f(a), f(b), f(c), g(a), g(b), g(c));
    for (int s = 0; s < 20; ++s) {
      double l0 = bary(rng), l1 = bary(rng) * (1 - l0), l2 = 1 - l0 - l1;
      const Point p{l0 * a.x + l1 * b.x + l2 * c.x, l0 * a.y + l1 * b.y + l2 * c.y};
      CHECK(zienkiewicz_value(k, l0, l1, l2) == Approx(f(p)).margin(1e-7));
    }
  }
}

TEST_CASE("zienkiewicz is a cubic Hermite curve on each edge, so continuous across edges") {
  // Triangles (a, b, c) and (b, a, d) share edge ab; both evaluate the same curve on it.
  const Point a{0, 0}, b{10, 3}, c{4, 9}, d{7, -8};
  const Gradient ga{0.3, -1.2}, gb{2.0, 0.5}, gc{-1, -1}, gd{4, 4};
  const auto k1 = zienkiewicz_coefficients(a, b, c, 10, 200, 50, ga, gb, gc);
  const auto k2 = zienkiewicz_coefficients(b, a, d, 200, 10, 90, gb, ga, gd);
  for (double s = 0; s <= 1.0; s += 0.125) {
    // Point (1 - s) a + s b: barycentrics (1 - s, s, 0) in the first, (s, 1 - s, 0) in the second.
    CHECK(zienkiewicz_value(k1, 1 - s, s, 0) == Approx(zienkiewicz_value(k2, s, 1 - s, 0)).margin(1e-9));
  }
  // And it is the Hermite cubic of the end values and edge derivatives.
  const double d0 = (b.x - a.x) * ga.gx + (b.y - a.y) * ga.gy, d1 = (b.x - a.x) * gb.gx + (b.y - a.y) * gb.gy;
  for (double s = 0; s <= 1.0; s += 0.125) {
    const double h = (2 * s * s * s - 3 * s * s + 1) * 10 + (s * s * s - 2 * s * s + s) * d0 +
                     (-2 * s * s * s + 3 * s * s) * 200 + (s * s * s - s * s) * d1;
    CHECK(zienkiewicz_value(k1, 1 - s, s, 0) == Approx(h).margin(1e-9));
  }
}

TEST_CASE("separate layers render like three grey triangulations") {
  Triangulation layered;
  layered.width = 40;
  layered.height = 30;
  layered.space = ColorSpace::rgb;
  for (std::uint32_t c = 0; c < 3; ++c) layered.layers.push_back(random_lattice_mesh(40, 30, 30 + 20 * c, 100 + c, 10));
  for (const char* method : {"bilinear", "zienkiewicz"}) {
    const Image rgb = render_reference(layered, *find_reference_method(method), {});
    for (int c = 0; c < 3; ++c) {
      const Image grey = render_reference(single(layered.layers[c], 40, 30), *find_reference_method(method), {});
      int diff = 0;
      for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) diff += grey.at(i, j, 0) != rgb.at(i, j, c);
      INFO(method << " channel " << c);
      CHECK(diff == 0);
    }
  }
}

TEST_CASE("YCbCr triangulations render as RGB, clamped and rounded") {
  Mesh mesh = random_lattice_mesh(20, 20, 10, 9, 0, 3);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    mesh.values[3 * v] = 120;
    mesh.values[3 * v + 1] = 90;
    mesh.values[3 * v + 2] = 250;  // strong red: R overshoots 255 and must clamp
  }
  const Image img = render_reference(single(mesh, 20, 20, ColorSpace::ycbcr), *find_reference_method("bilinear"), {});
  REQUIRE(img.channels == 3);
  // R = 120 + 1.402 * 122 = 291.0 -> 255; G = 120 - 0.344136 * -38 - 0.714136 * 122 = 46.0;
  // B = 120 + 1.772 * -38 = 52.66 -> 53.
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      CHECK(int(img.at(i, j, 0)) == 255);
      CHECK(int(img.at(i, j, 1)) == 46);
      CHECK(int(img.at(i, j, 2)) == 53);
    }
}

TEST_CASE("pixels outside the domain get the background") {
  Mesh mesh;
  mesh.points = {{0, 0}, {9, 0}, {0, 9}};
  mesh.values = {200, 200, 200};
  mesh.triangles = {{{0, 1, 2}}};
  mesh.normalize_winding();
  RenderOptions o;
  o.background = 7;
  const Image img = render_reference(single(mesh, 10, 10), *find_reference_method("bilinear"), o);
  CHECK(int(img.at(9, 9, 0)) == 7);
  CHECK(int(img.at(5, 5, 0)) == 7);   // x + y = 10 > 9: outside
  CHECK(int(img.at(4, 5, 0)) == 200);  // on the hypotenuse, a boundary edge: inside
  CHECK(int(img.at(0, 9, 0)) == 200);
}

TEST_CASE("every method's fits are its stretch at the same scale, shifted or cropped (reference/fit.h)") {
  // 64 x 48 inside 64 x 65 (scale 1, rows 8 .. 55), filling 49 x 48 (scale 1, columns 8 .. 56 of
  // the native render), and inside 127 x 200 (scale 2: the 127 x 95 stretch from row 52).
  const Triangulation tri = single(random_lattice_mesh(64, 48, 150, 11, 40), 64, 48);
  struct Case {
    Fit fit;
    int w, h, stretch_w, stretch_h, dx, dy;  // output pixel (i, j) = stretch pixel (i - dx, j - dy)
  };
  const Case cases[] = {{Fit::inside, 64, 65, 64, 48, 0, 8}, {Fit::fill, 49, 48, 64, 48, -8, 0},
                        {Fit::inside, 127, 200, 127, 95, 0, 52}};
  for (const MethodInfo& m : reference_methods()) {
    for (const Case& c : cases) {
      RenderOptions o;
      o.width = c.w;
      o.height = c.h;
      o.fit = c.fit;
      const Field fitted = render_reference_field(tri, m, o);
      const Field stretched = render_field(tri, m.name, c.stretch_w, c.stretch_h);
      REQUIRE((fitted.width == c.w && fitted.height == c.h));
      std::size_t differ = 0, picture = 0;
      for (int j = 0; j < c.h; ++j)
        for (int i = 0; i < c.w; ++i) {
          const int x = i - c.dx, y = j - c.dy;
          const double v = fitted.at(i, j, 0);
          if (x < 0 || y < 0 || x >= c.stretch_w || y >= c.stretch_h) {
            differ += !std::isnan(v);  // the border is outside the domain
            continue;
          }
          ++picture;
          const double s = stretched.at(x, y, 0);
          differ += !(v == s || (std::isnan(v) && std::isnan(s)));
        }
      INFO(m.name << " " << c.w << "x" << c.h);
      CHECK(picture == std::size_t(std::min(c.w, c.stretch_w)) * std::min(c.h, c.stretch_h));
      CHECK(differ == 0);
    }
  }
}

TEST_CASE("fits at other scales sample (i - o) d / n: linear data, every method that reproduces it") {
  Mesh mesh = random_lattice_mesh(60, 45, 150, 78, 80);
  auto linear = [](double x, double y) { return 0.7 * x - 1.3 * y + 100.0; };
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) mesh.values[v] = linear(mesh.points[v].x, mesh.points[v].y);
  const Triangulation tri = single(mesh, 60, 45);
  // Scales such as 40/59 (inside 41 x 90), 89/59 (fill 90 x 41) and 76/59 (inside 77 x 77).
  for (Fit fit : {Fit::inside, Fit::fill})
    for (auto [w, h] : {std::pair{41, 90}, std::pair{200, 45}, std::pair{90, 41}, std::pair{77, 77}}) {
      const FitLayout f = fit_layout(60, 45, w, h, fit);
      for (const char* method : {"bilinear", "zienkiewicz", "clough-tocher", "natural"}) {
        RenderOptions o;
        o.width = w;
        o.height = h;
        o.fit = fit;
        const Field got = render_reference_field(tri, *find_reference_method(method), o);
        double worst = 0;
        std::size_t wrong_coverage = 0;
        for (int j = 0; j < h; ++j)
          for (int i = 0; i < w; ++i) {
            const double x = double((i - f.x0) * f.d) / double(f.n), y = double((j - f.y0) * f.d) / double(f.n);
            const bool inside = x >= 0 && y >= 0 && x <= 59 && y <= 44;
            const double v = got.at(i, j, 0);
            wrong_coverage += inside == std::isnan(v);
            if (inside && !std::isnan(v)) worst = std::max(worst, std::abs(v - linear(x, y)));
          }
        INFO(method << (fit == Fit::inside ? " inside " : " fill ") << w << "x" << h << " scale " << f.n << "/" << f.d);
        CHECK(wrong_coverage == 0);
        CHECK(worst < 1e-9);
      }
    }
}
