// SPDX-License-Identifier: MIT
// Greedy point removal (baselines/gpr.h): a valid mesh of N vertices tiling the rectangle, the
// same on every run, the significance bookkeeping exact, the greedy choice the least.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "baselines/gpr.h"
#include "baselines/removal_mesh.h"
#include "common/errors.h"
#include "encoder/least_squares.h"
#include "encoder/planes.h"
#include "geometry/mesh_check.h"

using namespace tristream;
using baselines::GprOptions;
using baselines::PointRemoval;

namespace {

// Smooth shading, a sharp disc and noise, so that significances differ.
Image picture(int w, int h, int channels, unsigned seed) {
  Image img(w, h, channels);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-10, 10);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        const bool disc = (x - 0.6 * w) * (x - 0.6 * w) + (y - 0.4 * h) * (y - 0.4 * h) < 0.05 * w * h;
        const double v = (disc ? 200 : 60) + 40 * std::sin(0.3 * x + c) * std::cos(0.2 * y) + noise(rng);
        img.at(x, y, c) = std::uint8_t(std::clamp(v, 0.0, 255.0));
      }
  return img;
}

// The mesh tiles [0, W-1] x [0, H-1]: no overlap and no T-junction, every triangle positive, the
// areas add up to the rectangle's, the four corners are vertices and every vertex is used.
void require_tiling(const Mesh& m, int w, int h) {
  REQUIRE_FALSE(find_mesh_defect(m.points, m.triangles).has_value());
  double area2 = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    REQUIRE(m.doubled_area(t) > 0);
    area2 += m.doubled_area(t);
  }
  REQUIRE(area2 == 2.0 * (w - 1) * (h - 1));
  REQUIRE(m.used_vertices().size() == m.vertex_count());
  for (const Point corner :
       {Point{0, 0}, Point{double(w - 1), 0}, Point{0, double(h - 1)}, Point{double(w - 1), double(h - 1)}}) {
    const bool found = std::any_of(m.points.begin(), m.points.end(),
                                   [&](const Point& p) { return p.x == corner.x && p.y == corner.y; });
    REQUIRE(found);
  }
}

baselines::GprResult gpr(const Image& img, std::size_t n, VertexFit values = VertexFit::pixel) {
  GprOptions o;
  o.vertices = n;
  o.values = values;
  return baselines::greedy_point_removal(img, o);
}

}  // namespace

TEST_CASE("gpr: N vertices, corners included, tiling the rectangle, at every N", "[gpr]") {
  for (int channels : {1, 3}) {
    const Image img = picture(19, 13, channels, 7);
    for (std::size_t n : {std::size_t(4), std::size_t(5), std::size_t(12), std::size_t(60), std::size_t(19 * 13)}) {
      INFO("channels " << channels << ", N = " << n);
      const auto r = gpr(img, n);
      REQUIRE(r.triangulation.layers.size() == 1);
      const Mesh& m = r.triangulation.layers[0];
      REQUIRE(m.vertex_count() == n);
      REQUIRE(r.vertices == n);
      REQUIRE(m.value_count == channels);
      require_tiling(m, img.width, img.height);
    }
  }
}

TEST_CASE("gpr: every intermediate mesh tiles the rectangle; sides are thinned", "[gpr]") {
  const Image img = picture(16, 11, 1, 3);
  const encoder::Planes target = encoder::to_planes(img, ColorSpace::grey);
  PointRemoval removal(target);
  bool side_removed = false;
  while (removal.step()) {
    const auto p = removal.removal_mesh().pixel(removal.last_removed());
    side_removed = side_removed || p.x == 0 || p.y == 0 || p.x == img.width - 1 || p.y == img.height - 1;
    require_tiling(removal.mesh(), img.width, img.height);
  }
  REQUIRE(removal.vertex_count() == 4);
  REQUIRE(side_removed);
}

TEST_CASE("gpr: the same result on every run", "[gpr]") {
  const Image img = picture(23, 17, 3, 11);
  const auto a = gpr(img, 40, VertexFit::lsq), b = gpr(img, 40, VertexFit::lsq);
  const Mesh &ma = a.triangulation.layers[0], &mb = b.triangulation.layers[0];
  REQUIRE(ma.values == mb.values);
  REQUIRE(ma.triangles.size() == mb.triangles.size());
  for (std::size_t t = 0; t < ma.triangles.size(); ++t) REQUIRE(ma.triangles[t].v == mb.triangles[t].v);
  for (std::size_t v = 0; v < ma.points.size(); ++v) {
    REQUIRE(ma.points[v].x == mb.points[v].x);
    REQUIRE(ma.points[v].y == mb.points[v].y);
  }
  REQUIRE(a.psnr == b.psnr);
}

TEST_CASE("gpr: a planar image is reproduced exactly by the four corners", "[gpr]") {
  Image img(21, 14, 3);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      img.at(x, y, 0) = std::uint8_t(2 * x + 3 * y + 5);
      img.at(x, y, 1) = std::uint8_t(200 - 4 * x);
      img.at(x, y, 2) = std::uint8_t(7 * y);
    }
  const auto r = gpr(img, 4);
  REQUIRE(r.triangulation.layers[0].vertex_count() == 4);
  REQUIRE(std::isinf(r.psnr));
}

TEST_CASE("gpr: each step removes the least significant vertex and adds exactly its significance", "[gpr]") {
  const Image img = picture(14, 10, 3, 5);
  const encoder::Planes target = encoder::to_planes(img, ColorSpace::rgb);
  PointRemoval removal(target);
  const auto& mesh = removal.removal_mesh();
  const std::uint32_t pixels = std::uint32_t(img.width * img.height);
  double scale = 1;  // the error's size, for the tolerance of sums in another order
  while (removal.vertex_count() > 4) {
    double least = INFINITY;
    std::uint32_t first_least = 0;
    for (std::uint32_t v = 0; v < pixels; ++v)
      if (mesh.alive(v) && !mesh.is_corner(v)) {
        const double s = removal.significance(v);
        if (s < least) least = s, first_least = v;
      }
    const double before = removal.total_squared_error();
    REQUIRE(removal.step());
    REQUIRE(removal.last_significance() == least);
    REQUIRE(removal.last_removed() == first_least);
    const double after = removal.total_squared_error();
    scale = std::max(scale, after);
    REQUIRE(std::abs(after - (before + least)) <= 1e-9 * scale);
    // The triangles' errors are the error of the whole interpolant (an independent sum).
    REQUIRE(std::abs(encoder::linear_squared_error(removal.mesh(), target) - after) <= 1e-9 * scale);
  }
}

TEST_CASE("gpr: least-squares values never have a larger error than pixel values", "[gpr]") {
  for (int channels : {1, 3}) {
    const Image img = picture(25, 18, channels, 13);
    const encoder::Planes target = encoder::to_planes(img, channels == 1 ? ColorSpace::grey : ColorSpace::rgb);
    for (std::size_t n : {std::size_t(8), std::size_t(30), std::size_t(120)}) {
      INFO("channels " << channels << ", N = " << n);
      const auto pixel = gpr(img, n, VertexFit::pixel), lsq = gpr(img, n, VertexFit::lsq);
      const Mesh &mp = pixel.triangulation.layers[0], &ml = lsq.triangulation.layers[0];
      REQUIRE(ml.points.size() == mp.points.size());
      REQUIRE(ml.triangles.size() == mp.triangles.size());
      REQUIRE(encoder::linear_squared_error(ml, target) <= encoder::linear_squared_error(mp, target));
      REQUIRE(lsq.psnr >= pixel.psnr);
    }
  }
}

TEST_CASE("gpr: refuses impossible vertex counts and images", "[gpr]") {
  const Image img = picture(8, 6, 1, 1);
  REQUIRE_THROWS_AS(gpr(img, 3), UsageError);
  REQUIRE_THROWS_AS(gpr(img, 49), UsageError);
  REQUIRE_THROWS_AS(gpr(Image(1, 5, 1), 4), DataError);
  REQUIRE_THROWS_AS(gpr(Image(4, 4, 2), 4), DataError);
  REQUIRE(gpr(img, 48).psnr == INFINITY);
}
