// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <set>
#include <vector>

#include "common/errors.h"
#include "encoder/encoder.h"
#include "encoder/greedy.h"
#include "encoder/least_squares.h"
#include "encoder/pixel_scan.h"
#include "encoder/planes.h"
#include "encoder/relocate.h"
#include "geometry/delaunay.h"
#include "geometry/mesh_check.h"
#include "geometry/predicates.h"
#include "io/image_io.h"
#include "io/tri_file.h"

#include "../support/test_images.h"

using namespace tristream;

namespace {

// A deterministic test picture: smooth shading, a disc with a sharp edge, a ramp, noise.
Image synthetic(int w, int h, int channels, unsigned seed = 1) {
  Image img(w, h, channels);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-6, 6);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) {
        const double dx = x - 0.4 * w, dy = y - 0.55 * h;
        double v = 90 + 60 * std::sin(0.05 * x + 0.9 * c) * std::cos(0.07 * y);
        if (dx * dx + dy * dy < 0.06 * w * h) v += 70 - 30 * c;
        if (x > 0.75 * w) v = 20 + 2.5 * (y % 40) + 40 * c;
        img.at(x, y, c) = std::uint8_t(std::clamp(int(std::lround(v)) + noise(rng), 0, 255));
      }
  return img;
}

double squared_error(const Image& a, const Image& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    s += (double(a.pixels[i]) - b.pixels[i]) * (double(a.pixels[i]) - b.pixels[i]);
  return s;
}

// Visit count of every pixel when scanning all triangles of a mesh of pixel positions.
std::vector<int> visits(const Mesh& mesh, int w, int h) {
  std::vector<int> count(std::size_t(w) * h, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<encoder::IntPoint, 3> p;
    for (int e = 0; e < 3; ++e) {
      const Point& q = mesh.points[mesh.triangles[t].v[e]];
      p[e] = {std::int32_t(q.x), std::int32_t(q.y)};
    }
    encoder::scan_triangle(p, [&](int x, int y) {
      REQUIRE(x >= 0);
      REQUIRE(y >= 0);
      REQUIRE(x < w);
      REQUIRE(y < h);
      ++count[std::size_t(y) * w + x];
    });
  }
  return count;
}

EncodeOptions with_vertices(std::size_t n) {
  EncodeOptions o;
  o.vertices = n;
  return o;
}

}  // namespace

TEST_CASE("scan_triangle visits every pixel of a tiled rectangle exactly once", "[encoder]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const int w = 37 + int(seed) * 5, h = 23 + int(seed) * 3;
    std::mt19937 rng(seed);
    std::set<std::pair<int, int>> chosen = {{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}};
    // Random interior points, points on the border, and a lattice block (cocircular ties).
    for (int i = 0; i < 60; ++i) chosen.insert({int(rng() % w), int(rng() % h)});
    for (int i = 0; i < 10; ++i) {
      chosen.insert({int(rng() % w), 0}), chosen.insert({0, int(rng() % h)});
      chosen.insert({int(rng() % w), h - 1}), chosen.insert({w - 1, int(rng() % h)});
    }
    for (int y = 4; y < 12; y += 2)
      for (int x = 4; x < 12; x += 2) chosen.insert({x, y});
    Mesh mesh;
    for (auto [x, y] : chosen) mesh.points.push_back({double(x), double(y)});
    mesh.triangles = delaunay_triangulation(mesh.points);
    const auto count = visits(mesh, w, h);
    for (int c : count) REQUIRE(c == 1);
  }
}

TEST_CASE("scan_triangle's runs are the pixels the ownership rule gives, one test per pixel", "[encoder]") {
  // The rule of pixel_scan.h, pixel by pixel: p is owned when p + d is inside, d = (-1, -e) turned
  // inwards on x = 0 and y = 0; an edge function E of p + d is E(p) - dy sx + dx sy e.
  auto owned = [](const std::array<encoder::IntPoint, 3>& v, int x, int y) {
    const std::int64_t sx = x == 0 ? 1 : -1, sy = y == 0 ? 1 : -1;
    for (int e = 0; e < 3; ++e) {
      const encoder::IntPoint& a = v[e];
      const encoder::IntPoint& b = v[(e + 1) % 3];
      const std::int64_t dx = b.x - a.x, dy = b.y - a.y;
      const std::int64_t value = dx * (y - a.y) - dy * (x - a.x);
      if (value > 0) continue;
      if (value < 0) return false;
      const std::int64_t first = -dy * sx;  // the move's first order term, then its e term
      if (first != 0 ? first < 0 : dx * sy < 0) return false;
    }
    return true;
  };
  std::mt19937 rng(7);
  for (int i = 0; i < 1500; ++i) {
    const int reach = i % 3 == 0 ? 6 : (i % 3 == 1 ? 40 : 1 << 19);
    std::array<encoder::IntPoint, 3> v;
    for (auto& p : v) p = {int(rng() % reach), int(rng() % reach)};
    if (i % 7 == 0) v[1].y = v[0].y;  // a horizontal edge
    if (i % 11 == 0) v[2].x = v[0].x;  // a vertical edge
    const std::int64_t area = std::int64_t(v[1].x - v[0].x) * (v[2].y - v[0].y) -
                              std::int64_t(v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (area == 0) continue;
    if (area < 0) std::swap(v[1], v[2]);
    const int x0 = std::min({v[0].x, v[1].x, v[2].x}), x1 = std::max({v[0].x, v[1].x, v[2].x});
    const int y0 = std::min({v[0].y, v[1].y, v[2].y}), y1 = std::max({v[0].y, v[1].y, v[2].y});
    if (reach > 40) {
      // Coordinates up to 2^19: each row's run against the rule at its two ends and one column
      // past each (a run is one interval past x = 0), on a sample of rows.
      int rows = 0;
      encoder::scan_triangle_runs(v, [&](int y, int first, int last) {
        if (++rows % 4099 != 1) return;
        REQUIRE(first <= last);
        REQUIRE(owned(v, first, y));
        REQUIRE(owned(v, last, y));
        if (first > std::max(x0, 1)) REQUIRE_FALSE(owned(v, first - 1, y));
        if (last < x1) REQUIRE_FALSE(owned(v, last + 1, y));
      });
      continue;
    }
    std::set<std::pair<int, int>> scanned;
    encoder::scan_triangle(v, [&](int x, int y) { REQUIRE(scanned.insert({x, y}).second); });
    std::size_t count = 0;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        REQUIRE(owned(v, x, y) == (scanned.count({x, y}) == 1));
        count += owned(v, x, y);
      }
    REQUIRE(count == scanned.size());
  }
}

TEST_CASE("encode gives exactly the requested vertex count, a Delaunay mesh without flips", "[encoder]") {
  const Image img = synthetic(64, 48, 1);
  for (std::size_t n : {4u, 5u, 17u, 300u, 1500u}) {
    EncodeOptions o = with_vertices(n);
    o.flip_rounds = 0;
    const EncodeResult r = encode(img, o);
    REQUIRE(r.triangulation.layers.size() == 1);
    const Mesh& m = r.triangulation.layers[0];
    REQUIRE(m.vertex_count() == n);
    REQUIRE(r.vertices == n);
    REQUIRE(r.triangles == m.triangles.size());
    std::set<std::pair<double, double>> distinct;
    for (const Point& p : m.points) {
      REQUIRE(p.x == std::floor(p.x));
      REQUIRE(p.y == std::floor(p.y));
      distinct.insert({p.x, p.y});
    }
    REQUIRE(distinct.size() == n);
    for (const Triangle& t : m.triangles)
      for (const Point& p : m.points) REQUIRE(incircle(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]], p) <= 0);
    for (int c : visits(m, img.width, img.height)) REQUIRE(c == 1);
    for (double v : m.values) REQUIRE((v == std::round(v) && v >= 0 && v <= 255));
  }
  const Image colour = synthetic(40, 30, 3);
  EncodeOptions o = with_vertices(200);
  o.color = ColorMode::separate;
  const EncodeResult sep = encode(colour, o);
  REQUIRE(sep.triangulation.layers.size() == 3);
  for (const Mesh& m : sep.triangulation.layers) REQUIRE(m.vertex_count() == 200);
  o.color = ColorMode::co;
  o.cotri = CotriMethod::thesis;
  REQUIRE(encode(colour, o).triangulation.layers[0].vertex_count() == 200);
}

TEST_CASE("the error falls as the vertex count grows", "[encoder]") {
  for (int channels : {1, 3}) {
    const Image img = synthetic(96, 80, channels, 7);
    double last = INFINITY;
    for (std::size_t n : {30u, 120u, 480u, 1920u, 7680u}) {
      const EncodeResult r = encode(img, with_vertices(n));
      const double e = squared_error(render_linear(r.triangulation), img);
      REQUIRE(e < last);
      last = e;
    }
    // Every pixel a vertex: lossless (grey and RGB values are the pixels themselves).
    const EncodeResult all = encode(img, with_vertices(std::size_t(96) * 80));
    REQUIRE(squared_error(render_linear(all.triangulation), img) == 0);
    REQUIRE(std::isinf(all.psnr));
  }
}

TEST_CASE("the reported PSNR is that of the rendered linear interpolant", "[encoder]") {
  const Image img = synthetic(50, 40, 3, 3);
  for (ColorSpace space : {ColorSpace::rgb, ColorSpace::ycbcr}) {
    EncodeOptions o = with_vertices(150);
    o.space = space;
    const EncodeResult r = encode(img, o);
    const double mse = squared_error(render_linear(r.triangulation), img) / double(img.pixels.size());
    REQUIRE(r.psnr == Approx(10 * std::log10(255.0 * 255 / mse)).epsilon(1e-12));
  }
}

TEST_CASE("vertices reproduce their pixels; YCbCr round trips within one level", "[encoder]") {
  const Image img = synthetic(30, 20, 3, 5);
  EncodeOptions o = with_vertices(600);
  o.space = ColorSpace::ycbcr;
  const EncodeResult r = encode(img, o);
  const Image out = render_linear(r.triangulation);
  int worst = 0;
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    worst = std::max(worst, std::abs(int(out.pixels[i]) - img.pixels[i]));
  // 8-bit rounding of Y, Cb and Cr moves each RGB channel by at most 0.5 * (1 + 1.772).
  REQUIRE(worst <= 2);
}

TEST_CASE("--error stops at the first count whose RMS error is below the target", "[encoder]") {
  const Image img = synthetic(80, 60, 1, 11);
  const encoder::Planes target = encoder::to_planes(img, ColorSpace::grey);
  std::size_t previous = 0;
  for (double e : {12.0, 6.0, 3.0}) {
    EncodeOptions o;
    o.max_rms = e;
    o.fit = VertexFit::pixel;
    const EncodeResult r = encode(img, o);
    const Mesh& m = r.triangulation.layers[0];
    REQUIRE(std::sqrt(encoder::linear_squared_error(m, target) / (80.0 * 60)) <= e);
    REQUIRE(m.vertex_count() > previous);
    previous = m.vertex_count();
    // One vertex fewer did not reach the target: the run stopped as soon as it could.
    o.max_rms = 0;
    o.vertices = m.vertex_count() - 1;
    const EncodeResult fewer = encode(img, o);
    REQUIRE(std::sqrt(encoder::linear_squared_error(fewer.triangulation.layers[0], target) / (80.0 * 60)) > e);
  }
}

TEST_CASE("least squares reproduces a linear image and lowers the error", "[encoder]") {
  Image plane(41, 33, 1);
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 41; ++x) plane.at(x, y, 0) = std::uint8_t(2 * x + 3 * y + 7);
  EncodeOptions o = with_vertices(40);
  const encoder::Planes target = encoder::to_planes(plane, ColorSpace::grey);
  Mesh m = encode(plane, o).triangulation.layers[0];
  for (double& v : m.values) v = std::clamp(v + 9.0, 0.0, 255.0);  // far from the answer
  encoder::fit_least_squares(m, target);
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    REQUIRE(m.value(v, 0) == 2 * m.points[v].x + 3 * m.points[v].y + 7);

  const Image img = synthetic(90, 70, 3, 13);
  const encoder::Planes t3 = encoder::to_planes(img, ColorSpace::rgb);
  o = with_vertices(300);
  o.smoothing_sigma = 1;  // same positions for both fits
  o.relocate_passes = 0;
  o.fit = VertexFit::pixel;
  const Mesh pixel = encode(img, o).triangulation.layers[0];
  o.fit = VertexFit::lsq;
  const Mesh fitted = encode(img, o).triangulation.layers[0];
  REQUIRE(fitted.points.size() == pixel.points.size());
  for (std::size_t v = 0; v < pixel.points.size(); ++v) {
    REQUIRE(fitted.points[v].x == pixel.points[v].x);
    REQUIRE(fitted.points[v].y == pixel.points[v].y);
  }
  REQUIRE(encoder::linear_squared_error(fitted, t3) < 0.9 * encoder::linear_squared_error(pixel, t3));
}

TEST_CASE("relocation keeps a Delaunay tiling of distinct pixels and lowers the error", "[encoder]") {
  for (int channels : {1, 3}) {
    const Image img = synthetic(96, 80, channels, 23);
    const encoder::Planes target = encoder::to_planes(img, channels == 1 ? ColorSpace::grey : ColorSpace::rgb);
    EncodeOptions o = with_vertices(300);
    o.relocate_passes = 0;
    o.flip_rounds = 0;
    const Mesh before = encode(img, o).triangulation.layers[0];
    Mesh m = before;
    const encoder::RelocateReport report = encoder::relocate_vertices(m, target, 4);
    REQUIRE(report.passes >= 1);
    REQUIRE(report.moves > 0);
    REQUIRE(report.sse_before == Approx(encoder::linear_squared_error(before, target)).epsilon(1e-9));
    REQUIRE(report.sse_after == Approx(encoder::linear_squared_error(m, target)).epsilon(1e-9));
    REQUIRE(report.sse_after < 0.97 * report.sse_before);
    REQUIRE(m.vertex_count() == before.vertex_count());
    std::size_t moved = 0;
    std::set<std::pair<double, double>> distinct;
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      const Point& p = m.points[v];
      REQUIRE(p.x == std::floor(p.x));
      REQUIRE(p.y == std::floor(p.y));
      distinct.insert({p.x, p.y});
      moved += p.x != before.points[v].x || p.y != before.points[v].y;
      // Border vertices stay on their side.
      if (before.points[v].x == 0 || before.points[v].x == 95) REQUIRE(p.x == before.points[v].x);
      if (before.points[v].y == 0 || before.points[v].y == 79) REQUIRE(p.y == before.points[v].y);
    }
    REQUIRE(moved > 0);
    REQUIRE(distinct.size() == m.vertex_count());
    for (auto corner : {std::pair{0.0, 0.0}, {95.0, 0.0}, {0.0, 79.0}, {95.0, 79.0}})
      REQUIRE(distinct.count(corner) == 1);
    for (const Triangle& t : m.triangles) {
      REQUIRE(orient2d(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]]) > 0);
      for (const Point& p : m.points) REQUIRE(incircle(m.points[t.v[0]], m.points[t.v[1]], m.points[t.v[2]], p) <= 0);
    }
    for (int c : visits(m, img.width, img.height)) REQUIRE(c == 1);
  }
}

TEST_CASE("the two improvements beat plain Garland-Heckbert on a noisy picture", "[encoder]") {
  const Image img = synthetic(128, 96, 1, 17);
  // With pixel values (the claim). With a least-squares refit the gain depends on the
  // image and density (measured in the encoder's report), so it is not asserted here.
  for (VertexFit fit : {VertexFit::pixel}) {
    EncodeOptions plain = with_vertices(250);
    plain.fit = fit;
    plain.rank_by_total_error = false;
    plain.smoothing_sigma = 0;
    EncodeOptions improved = with_vertices(250);
    improved.fit = fit;
    const double e_plain = squared_error(render_linear(encode(img, plain).triangulation), img);
    const double e_improved = squared_error(render_linear(encode(img, improved).triangulation), img);
    REQUIRE(e_improved < e_plain);
  }
}

TEST_CASE("encoding is deterministic to the byte", "[encoder]") {
  const Image img = synthetic(70, 50, 3, 19);
  for (ColorMode mode : {ColorMode::co, ColorMode::separate}) {
    EncodeOptions o = with_vertices(400);
    o.color = mode;
    o.fit = VertexFit::lsq;
    REQUIRE(format_tri(encode(img, o).triangulation) == format_tri(encode(img, o).triangulation));
  }
}

TEST_CASE("encoder output is edge to edge: every mesh passes the reader's mesh check", "[encoder]") {
  // The reader rejects overlaps and T-junctions (geometry/mesh_check.h); the encoder's meshes
  // (Delaunay, then flipped and relocated) pass it in every colour mode.
  const Image img = synthetic(70, 50, 3, 23);
  for (ColorMode mode : {ColorMode::co, ColorMode::separate})
    for (CotriMethod cotri : {CotriMethod::greedy, CotriMethod::thesis}) {
      EncodeOptions o = with_vertices(300);
      o.color = mode;
      o.cotri = cotri;
      const Triangulation t = encode(img, o).triangulation;
      for (const Mesh& m : t.layers) REQUIRE_FALSE(find_mesh_defect(m.points, m.triangles).has_value());
      REQUIRE_NOTHROW(parse_tri(format_tri(t), "encoded.tri"));
    }
}

TEST_CASE("impossible options are usage errors", "[encoder]") {
  const Image img = synthetic(10, 10, 1);
  REQUIRE_THROWS_AS(encode(img, with_vertices(3)), UsageError);
  REQUIRE_THROWS_AS(encode(img, with_vertices(101)), UsageError);
  REQUIRE_THROWS_AS(encode(img, EncodeOptions{}), UsageError);
  REQUIRE_NOTHROW(encode(img, with_vertices(100)));
  REQUIRE_THROWS_AS(encode(Image(1, 10, 1), with_vertices(4)), DataError);
}

TEST_CASE("regular grid baseline", "[encoder]") {
  const Image img = synthetic(64, 48, 1);
  const Triangulation g = regular_grid(img, 100, ColorSpace::grey, VertexFit::pixel);
  const Mesh& m = g.layers[0];
  REQUIRE(m.vertex_count() >= 90);
  REQUIRE(m.vertex_count() <= 110);
  for (int c : visits(m, 64, 48)) REQUIRE(c == 1);
}

TEST_CASE("real photographs at 1% vertices meet the issue's targets", "[encoder][images]") {
  // Two of the project's test photographs, from $TRISTREAM_IMAGES (tests/support/test_images.h).
  const std::string grey_path = test::shared_image("grey/peppers_grey.png");
  const std::string colour_path = test::shared_image("colour/peppers.png");
  if (grey_path.empty() || colour_path.empty()) {
    WARN(test::skip_message("grey/peppers_grey.png and colour/peppers.png"));
    return;
  }
  const Image grey = read_image(grey_path);
  const EncodeResult r = encode(grey, with_vertices(2621));
  CHECK(r.psnr >= 26.5);  // grey 512x512, 1 % vertices
  // Adaptive beats a regular grid of the same count by at least 3 dB (both least squares).
  const Image grid = render_linear(regular_grid(grey, 2621, ColorSpace::grey, VertexFit::lsq));
  const double grid_psnr = 10 * std::log10(255.0 * 255 * double(grey.pixels.size()) / squared_error(grid, grey));
  CHECK(r.psnr >= grid_psnr + 3);
  const EncodeResult c = encode(read_image(colour_path), with_vertices(2621));
  CHECK(c.psnr >= 24.5);  // colour co-triangulation, 1 % vertices
}
