// SPDX-License-Identifier: MIT
// Data-dependent triangulation (encoder/flips.h) and relocation without the Delaunay condition.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "encoder/encoder.h"
#include "encoder/flips.h"
#include "encoder/least_squares.h"
#include "encoder/pixel_scan.h"
#include "encoder/planes.h"
#include "encoder/relocate.h"
#include "geometry/mesh_check.h"
#include "geometry/predicates.h"

using namespace tristream;

namespace {

// Smooth shading, a rotated step edge and noise: edges that no Delaunay mesh follows.
Image slanted_edges(int w, int h, int channels, unsigned seed) {
  Image img(w, h, channels);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-4, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        double v = 80 + 50 * std::sin(0.06 * x + 0.5 * c) * std::cos(0.045 * y);
        if (0.83 * x - 0.56 * y > 0.2 * w) v += 90 - 25 * c;
        if (0.3 * x + 0.95 * y < 0.35 * h) v -= 50;
        img.at(x, y, c) = std::uint8_t(std::clamp(int(std::lround(v)) + noise(rng), 0, 255));
      }
  return img;
}

// Every pixel of the w x h rectangle is owned by exactly one triangle.
bool tiles_exactly(const Mesh& mesh, int w, int h) {
  std::vector<int> count(std::size_t(w) * h, 0);
  for (const Triangle& t : mesh.triangles) {
    std::array<encoder::IntPoint, 3> p;
    for (int e = 0; e < 3; ++e) p[e] = {std::int32_t(mesh.points[t.v[e]].x), std::int32_t(mesh.points[t.v[e]].y)};
    encoder::scan_triangle(p, [&](int x, int y) { ++count[std::size_t(y) * w + x]; });
  }
  for (int c : count)
    if (c != 1) return false;
  return true;
}

bool is_delaunay(const Mesh& m) {
  for (const Triangle& t : m.triangles)
    for (const Point& p : m.points)
      if (incircle(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]], p) > 0) return false;
  return true;
}

EncodeOptions options(std::size_t vertices, int flip_rounds) {
  EncodeOptions o;
  o.vertices = vertices;
  o.flip_rounds = flip_rounds;
  return o;
}

}  // namespace

TEST_CASE("an edge flips to the diagonal a crease in the picture follows", "[encoder]") {
  // 31 |x - y| on a 9 x 9 square: linear on each side of the diagonal (0, 0)-(8, 8). The mesh
  // starts with the other diagonal; the corners carry the picture's values.
  Image img(9, 9, 1);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) img.at(x, y, 0) = std::uint8_t(31 * std::abs(x - y));
  const encoder::Planes target = encoder::to_planes(img, ColorSpace::grey);
  Mesh m;
  m.points = {{0, 0}, {8, 0}, {0, 8}, {8, 8}};
  m.values = {0, 248, 248, 0};
  m.triangles = {Triangle{{0, 1, 2}}, Triangle{{1, 3, 2}}};
  const encoder::FlipReport report = encoder::flip_edges(m, target);
  REQUIRE(report.flips == 1);
  REQUIRE(report.sse_before > 1000);
  REQUIRE(report.sse_after < 1e-9);
  REQUIRE(m.triangles.size() == 2);
  for (const Triangle& t : m.triangles) {
    REQUIRE(orient2d(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]]) > 0);
    // Both triangles hold the diagonal 0-3.
    REQUIRE(std::set<std::uint32_t>(t.v.begin(), t.v.end()).count(0) == 1);
    REQUIRE(std::set<std::uint32_t>(t.v.begin(), t.v.end()).count(3) == 1);
  }
  // A second search finds nothing to gain.
  REQUIRE(encoder::flip_edges(m, target).flips == 0);
}

TEST_CASE("edge flips keep an exact tiling, the values and the counts, and lower the error", "[encoder]") {
  for (int channels : {1, 3}) {
    const Image img = slanted_edges(90, 70, channels, 5);
    const encoder::Planes target = encoder::to_planes(img, channels == 1 ? ColorSpace::grey : ColorSpace::rgb);
    const Mesh before = encode(img, options(250, 0)).triangulation.layers[0];
    REQUIRE(is_delaunay(before));
    Mesh m = before;
    const encoder::FlipReport report = encoder::flip_edges(m, target);
    REQUIRE(report.flips > 0);
    REQUIRE(report.sse_before == Approx(encoder::linear_squared_error(before, target)).epsilon(1e-9));
    REQUIRE(report.sse_after == Approx(encoder::linear_squared_error(m, target)).epsilon(1e-9));
    REQUIRE(report.sse_after < 0.99 * report.sse_before);
    REQUIRE(m.points.size() == before.points.size());
    REQUIRE(m.values == before.values);
    REQUIRE(m.triangles.size() == before.triangles.size());
    REQUIRE_FALSE(find_mesh_defect(m.points, m.triangles).has_value());
    for (const Triangle& t : m.triangles) REQUIRE(orient2d(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]]) > 0);
    REQUIRE(tiles_exactly(m, img.width, img.height));
    REQUIRE_FALSE(is_delaunay(m));
  }
}

TEST_CASE("relocation without the Delaunay condition keeps a tiling and lowers the error", "[encoder]") {
  const Image img = slanted_edges(80, 64, 1, 9);
  const encoder::Planes target = encoder::to_planes(img, ColorSpace::grey);
  Mesh m = encode(img, options(200, 0)).triangulation.layers[0];
  encoder::flip_edges(m, target);
  const Mesh flipped = m;
  const encoder::RelocateReport report = encoder::relocate_vertices(m, target, 4, false);
  REQUIRE(report.moves > 0);
  REQUIRE(report.sse_after < report.sse_before);
  REQUIRE(m.triangles.size() == flipped.triangles.size());
  std::set<std::pair<double, double>> distinct;
  for (const Point& p : m.points) distinct.insert({p.x, p.y});
  REQUIRE(distinct.size() == m.points.size());
  REQUIRE_FALSE(find_mesh_defect(m.points, m.triangles).has_value());
  REQUIRE(tiles_exactly(m, img.width, img.height));
}

TEST_CASE("flip rounds lower the encoder's error, deterministically", "[encoder]") {
  for (int channels : {1, 3}) {
    const Image img = slanted_edges(96, 72, channels, 13);
    const EncodeResult delaunay = encode(img, options(300, 0));
    const EncodeResult one = encode(img, options(300, 1));
    const EncodeResult two = encode(img, options(300, 2));
    REQUIRE(one.psnr > delaunay.psnr + 0.3);
    REQUIRE(two.psnr >= one.psnr - 0.05);
    for (const EncodeResult* r : {&one, &two}) {
      const Mesh& m = r->triangulation.layers[0];
      REQUIRE(m.vertex_count() == 300);
      REQUIRE_FALSE(find_mesh_defect(m.points, m.triangles).has_value());
      REQUIRE(tiles_exactly(m, img.width, img.height));
    }
    const EncodeResult again = encode(img, options(300, 2));
    REQUIRE(again.triangulation.layers[0].triangles.size() == two.triangulation.layers[0].triangles.size());
    for (std::size_t t = 0; t < again.triangulation.layers[0].triangles.size(); ++t)
      REQUIRE(again.triangulation.layers[0].triangles[t].v == two.triangulation.layers[0].triangles[t].v);
    REQUIRE(again.triangulation.layers[0].values == two.triangulation.layers[0].values);
  }
}
