// SPDX-License-Identifier: MIT
// Coverage properties of the core: every pixel whose sample point lies in the domain is
// written exactly once, whatever the mesh, vertex order, winding or tiling.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>

#include "core_support.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

// Exact: is the sample point of pixel (i, j) in the closed union of the mesh's triangles
// (positions rounded to 1/16 pixel, as packed)?
std::vector<std::uint8_t> exact_domain(const Mesh& mesh, int w, int h) {
  std::vector<std::uint8_t> in(std::size_t(w) * h, 0);
  for (const Triangle& t : mesh.triangles) {
    std::int64_t x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = std::llround(mesh.points[t.v[k]].x * 16);
      y[k] = std::llround(mesh.points[t.v[k]].y * 16);
    }
    const std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    const int sgn = area > 0 ? 1 : -1;
    const int i0 = int(std::max<std::int64_t>(0, *std::min_element(x, x + 3) / 16));
    const int i1 = int(std::min<std::int64_t>(w - 1, *std::max_element(x, x + 3) / 16));
    const int j0 = int(std::max<std::int64_t>(0, *std::min_element(y, y + 3) / 16));
    const int j1 = int(std::min<std::int64_t>(h - 1, *std::max_element(y, y + 3) / 16));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          const int n = (e + 1) % 3;
          const std::int64_t o = (x[n] - x[e]) * (16 * j - y[e]) - (y[n] - y[e]) * (16 * i - x[e]);
          inside = sgn * o >= 0;
        }
        if (inside) in[std::size_t(j) * w + i] = 1;
      }
  }
  return in;
}

// Renders coverage counts at every tiling; checks exactly-once on the domain and zero outside.
void check_exactly_once(const Mesh& mesh, int w, int h, const std::string& what) {
  const Triangulation tri = single_mesh(mesh, w, h);
  const auto blob = pack_blob(tri, core::Method::bilinear);
  const auto domain = exact_domain(mesh, w, h);
  CoreOptions o;
  o.format = core::PixelFormat::coverage8;
  for (const Tiling& t : all_tilings()) {
    const CoreFrame f = core_frame(blob, o, t);
    int holes = 0, doubles = 0, outside = 0;
    for (std::size_t p = 0; p < f.bytes.size(); ++p) {
      if (domain[p]) {
        holes += f.bytes[p] == 0;
        doubles += f.bytes[p] > 1;
      } else {
        outside += f.bytes[p] != 0;
      }
    }
    INFO(what << ", tiles " << t.w << "x" << t.h);
    CHECK(holes == 0);
    CHECK(doubles == 0);
    CHECK(outside == 0);
  }
}

}  // namespace

TEST_CASE("lattice triangulations of the whole image: every pixel exactly once") {
  struct Case {
    int w, h, points, flips;
  };
  const Case cases[] = {{16, 16, 20, 0}, {64, 48, 200, 0}, {64, 48, 200, 300}, {33, 7, 60, 50},
                        {5, 90, 40, 40}, {40, 40, 1200, 0}, {70, 70, 3, 0}};
  std::uint32_t seed = 100;
  for (const Case& c : cases)
    for (int rep = 0; rep < 2; ++rep, ++seed)
      check_exactly_once(
          random_lattice_mesh(c.w, c.h, c.points, seed, c.flips), c.w, c.h,
          "lattice " + std::to_string(c.w) + "x" + std::to_string(c.h) + " seed " + std::to_string(seed));
}

TEST_CASE("sub-pixel vertices, with and without image corners (convex-hull domains)") {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    check_exactly_once(random_subpixel_mesh(47, 39, 80, seed, true), 47, 39, "corners seed " + std::to_string(seed));
    check_exactly_once(random_subpixel_mesh(47, 39, 60, seed, false), 47, 39, "hull seed " + std::to_string(seed));
    check_exactly_once(random_subpixel_mesh(20, 60, 8, seed, false), 20, 60, "few hull seed " + std::to_string(seed));
  }
}

TEST_CASE("slivers: long thin triangles between two rows and two columns") {
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    std::mt19937 rng(seed);
    Mesh mesh;
    const int w = 200, h = 9;
    std::set<int> top = {0, w - 1}, bottom = {0, w - 1};
    while (top.size() < 12) top.insert(int(rng() % w));
    while (bottom.size() < 12) bottom.insert(int(rng() % w));
    for (int x : top) mesh.points.push_back({double(x), 0.0});
    for (int x : bottom) mesh.points.push_back({double(x), double(h - 1)});
    mesh.points.push_back({(rng() % (16 * (w - 1))) / 16.0, 4.0 + (rng() % 16) / 16.0});
    mesh.values.assign(mesh.points.size(), 100.0);
    mesh.triangles = delaunay_triangulation(mesh.points);
    check_exactly_once(mesh, w, h, "horizontal slivers seed " + std::to_string(seed));
    Mesh turned = mesh;
    for (Point& p : turned.points) std::swap(p.x, p.y);
    turned.normalize_winding();
    check_exactly_once(turned, h, w, "vertical slivers seed " + std::to_string(seed));
  }
}

TEST_CASE("coordinates at the documented limits (2048 x 2048)") {
  const int n = core::config::max_dimension;
  Mesh mesh;
  mesh.points = {{0, 0}, {double(n - 1), 0}, {0, double(n - 1)}, {double(n - 1), double(n - 1)},
                 {1023.5, 0.0625}, {2047, 1000.9375}, {0.0625, 2046.9375}};
  mesh.values.assign(mesh.points.size(), 200.0);
  mesh.triangles = delaunay_triangulation(mesh.points);
  const auto blob = pack_blob(single_mesh(mesh, n, n), core::Method::bilinear);
  CoreOptions o;
  o.format = core::PixelFormat::coverage8;
  for (Tiling t : {Tiling{0, 0}, Tiling{64, 64}, Tiling{0, 1}}) {
    const CoreFrame f = core_frame(blob, o, t);
    CHECK(std::count(f.bytes.begin(), f.bytes.end(), std::uint8_t(1)) == std::int64_t(n) * n);
  }
}

TEST_CASE("vertex order and winding do not change the output") {
  for (std::uint32_t seed = 7; seed <= 9; ++seed) {
    Mesh mesh = random_subpixel_mesh(50, 40, 90, seed, true, 3);
    const Triangulation tri = single_mesh(mesh, 50, 40, ColorSpace::rgb);
    for (const char* method : {"bilinear", "zienkiewicz"}) {
      CoreOptions o;
      o.format = core::PixelFormat::rgb888;
      const CoreFrame base = render_core_frame(tri, method, o);
      std::mt19937 rng(seed);
      Mesh shuffled = mesh;
      for (Triangle& t : shuffled.triangles) {
        std::rotate(t.v.begin(), t.v.begin() + rng() % 3, t.v.end());
        if (rng() % 2) std::swap(t.v[1], t.v[2]);  // clockwise or counter-clockwise on screen
      }
      std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
      const CoreFrame other = render_core_frame(single_mesh(shuffled, 50, 40, ColorSpace::rgb), method, o);
      INFO(method << " seed " << seed);
      CHECK(bytes_differing(other.bytes, base.bytes) == 0);
    }
  }
}

TEST_CASE("output is bit-identical for every tiling, method, format and viewport") {
  Mesh mesh = random_subpixel_mesh(71, 45, 150, 42, true, 3);
  const Triangulation tri = single_mesh(mesh, 71, 45, ColorSpace::ycbcr);
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    const auto blob = pack_blob(tri, m);
    for (core::PixelFormat f : {core::PixelFormat::rgb888, core::PixelFormat::rgb565_be, core::PixelFormat::l8,
                                core::PixelFormat::xrgb8888}) {
      for (bool dither : {false, true}) {
        for (core::Rect view : {core::Rect{}, core::Rect{5, 3, 60, 40}}) {
          for (int out : {0, 1}) {
            CoreOptions o;
            o.format = f;
            o.dither = dither;
            o.viewport = view;
            if (out) o.width = 97, o.height = 61;
            const CoreFrame full = core_frame(blob, o, {0, 0});
            for (const Tiling& t : all_tilings()) {
              INFO("method " << int(m) << " format " << int(f) << " dither " << dither << " viewport " << view.x0
                             << " resized " << out << " tiles " << t.w << "x" << t.h);
              CHECK(bytes_differing(core_frame(blob, o, t).bytes, full.bytes) == 0);
            }
          }
        }
      }
    }
  }
}
