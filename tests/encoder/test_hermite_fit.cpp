// SPDX-License-Identifier: MIT
// Least-squares values and gradients for zienkiewicz and clough-tocher (encoder/hermite_fit.h).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "common/errors.h"
#include "encoder/encoder.h"
#include "encoder/hermite_fit.h"
#include "encoder/least_squares.h"
#include "encoder/planes.h"
#include "geometry/delaunay.h"
#include "metrics/metrics.h"
#include "model/topology.h"
#include "reference/gradients.h"
#include "reference/render.h"

using namespace tristream;
using encoder::HermiteMethod;

namespace {

// A mesh of random pixel positions (the four corners included) over w x h, Delaunay
// triangulated, with `channels` values each; with `even_rows` on even rows only (h odd).
Mesh random_mesh(int w, int h, int count, int channels, unsigned seed, bool even_rows = false) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> ux(1, w - 2), uy(1, h - 2);
  Mesh m;
  m.value_count = channels;
  m.points = {{0, 0}, {double(w - 1), 0}, {0, double(h - 1)}, {double(w - 1), double(h - 1)}};
  std::vector<char> taken(std::size_t(w) * h, 0);
  for (const Point& p : m.points) taken[std::size_t(p.y) * w + std::size_t(p.x)] = 1;
  while (int(m.points.size()) < count) {
    const int x = ux(rng), y = even_rows ? uy(rng) & ~1 : uy(rng);
    if (taken[std::size_t(y) * w + x]) continue;
    taken[std::size_t(y) * w + x] = 1;
    m.points.push_back({double(x), double(y)});
  }
  m.values.assign(m.points.size() * std::size_t(channels), 128.0);
  m.triangles = delaunay_triangulation(m.points);
  m.normalize_winding();
  return m;
}

template <class F>
encoder::Planes planes_of(int w, int h, int channels, F&& f) {
  encoder::Planes p(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) p.at(x, y, c) = float(f(x, y, c));
  return p;
}

// A smooth picture with a curved ridge: what cubic patches should fit better than planes.
double smooth(int x, int y, int c) {
  return 120 + 60 * std::sin(0.05 * x + 0.3 * c) * std::cos(0.04 * y) + 0.01 * (x - 40) * (y - 30);
}

}  // namespace

TEST_CASE("hermite fit reproduces linear data exactly, gradients included", "[encoder][hermite]") {
  for (HermiteMethod method : {HermiteMethod::zienkiewicz, HermiteMethod::clough_tocher}) {
    CAPTURE(int(method));
    Mesh m = random_mesh(61, 47, 40, 1, 3, true);
    // Gradient (2, -1.5), a multiple of the step (1/64 per pixel); the values at the vertices,
    // 80 + 2 x - 1.5 y (11 to 200), are halves, which the fit rounds: so y is even at every vertex.
    const auto plane = planes_of(61, 47, 1, [](int x, int y, int) { return 80 + 2.0 * x - 1.5 * y; });
    const auto report = encoder::fit_hermite(m, plane, {method, 6});
    CAPTURE(report.iterations, report.residual);
    REQUIRE(m.has_gradients());
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      CHECK(m.gradient(v, 0, 0) == Approx(2.0).margin(1e-12));
      CHECK(m.gradient(v, 0, 1) == Approx(-1.5).margin(1e-12));
    }
    CHECK(encoder::hermite_squared_error(m, plane, method) < 1e-6);
  }
}

TEST_CASE("hermite fit: rounded values, gradients on the step, deterministic", "[encoder][hermite]") {
  const auto target = planes_of(80, 60, 3, smooth);
  for (int step : {0, 6, 9}) {
    CAPTURE(step);
    Mesh a = random_mesh(80, 60, 60, 3, 11), b = a;
    encoder::fit_hermite(a, target, {HermiteMethod::zienkiewicz, step});
    encoder::fit_hermite(b, target, {HermiteMethod::zienkiewicz, step});
    CHECK(a.values == b.values);
    CHECK(a.gradients == b.gradients);
    REQUIRE(a.gradients.size() == a.vertex_count() * 3 * 2);
    const double unit = std::ldexp(1.0, step - 12);
    for (double v : a.values) CHECK((v == std::round(v) && v >= 0 && v <= 255));
    for (double g : a.gradients) {
      CHECK(g / unit == std::round(g / unit));
      CHECK(std::abs(g) <= 32767);
    }
  }
}

TEST_CASE("hermite fit beats the estimated gradients and the linear fit on smooth data", "[encoder][hermite]") {
  const auto target = planes_of(96, 72, 1, smooth);
  Mesh linear = random_mesh(96, 72, 80, 1, 5);
  encoder::fit_least_squares(linear, target, true);
  const double linear_error = encoder::linear_squared_error(linear, target);
  for (HermiteMethod method : {HermiteMethod::zienkiewicz, HermiteMethod::clough_tocher}) {
    CAPTURE(int(method));
    // The thesis's data: least-squares linear values, gradients estimated from the surface.
    const double estimated_error = encoder::hermite_squared_error(linear, target, method);
    Mesh fitted = linear;
    encoder::fit_hermite(fitted, target, {method, 6});
    const double fitted_error = encoder::hermite_squared_error(fitted, target, method);
    CHECK(fitted_error < 0.5 * estimated_error);
    CHECK(fitted_error < 0.5 * linear_error);
    // Moving any one gradient away from the fit makes the error larger: a minimum (up to the
    // rounding of values and gradients, which a step of 1/64 per pixel keeps small).
    for (std::size_t v : {std::size_t(7), std::size_t(30), std::size_t(55)}) {
      Mesh moved = fitted;
      moved.gradients[2 * v] += 0.25;
      CHECK(encoder::hermite_squared_error(moved, target, method) > fitted_error);
    }
  }
}

TEST_CASE("hermite fit: a vertex no triangle uses keeps finite data", "[encoder][hermite]") {
  const auto target = planes_of(40, 30, 1, smooth);
  Mesh m = random_mesh(40, 30, 20, 1, 2);
  // The last vertex leaves the triangulation: the mesh of the others.
  const Point unused = m.points.back();
  m.points.pop_back();
  m.values.pop_back();
  m.triangles = delaunay_triangulation(m.points);
  m.normalize_winding();
  m.points.push_back(unused);
  m.values.push_back(77);
  const auto report = encoder::fit_hermite(m, target, {HermiteMethod::zienkiewicz, 9});
  CHECK(report.residual < 1e-8);  // the solves converge: the unused vertex's blocks are not inverted
  for (double v : m.values) CHECK(std::isfinite(v));
  for (double g : m.gradients) CHECK(std::isfinite(g));
  CHECK(m.values.back() == 77);
}

TEST_CASE("hermite_squared_error equals the reference render's error", "[encoder][hermite]") {
  // The fit's basis is the reference's interpolant: the unrounded field of the reference has the
  // same squared error as hermite_squared_error.
  const auto target = planes_of(50, 40, 1, smooth);
  Mesh m = random_mesh(50, 40, 30, 1, 9);
  encoder::fit_hermite(m, target, {HermiteMethod::zienkiewicz, 6});
  Triangulation tri;
  tri.width = 50;
  tri.height = 40;
  tri.space = ColorSpace::grey;
  tri.layers.push_back(m);
  for (const char* name : {"zienkiewicz", "clough-tocher"}) {
    CAPTURE(name);
    const Field f = render_reference_field(tri, *find_reference_method(name), RenderOptions{});
    double sse = 0;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 50; ++x) {
        const double e = f.at(x, y, 0) - target.at(x, y, 0);
        sse += e * e;
      }
    const HermiteMethod method =
        std::string(name) == "zienkiewicz" ? HermiteMethod::zienkiewicz : HermiteMethod::clough_tocher;
    CHECK(encoder::hermite_squared_error(m, target, method) == Approx(sse).epsilon(1e-9));
  }
}

TEST_CASE("encode --method zienkiewicz: the same mesh, fitted values and gradients, a better render",
          "[encoder][hermite]") {
  Image img(90, 70, 1);
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> noise(-3, 3);
  for (int y = 0; y < 70; ++y)
    for (int x = 0; x < 90; ++x)
      img.at(x, y, 0) = std::uint8_t(std::clamp(int(std::lround(smooth(x, y, 0))) + noise(rng), 0, 255));
  EncodeOptions o;
  o.vertices = 120;
  const EncodeResult bilinear = encode(img, o);
  o.method = FitMethod::zienkiewicz;
  const EncodeResult z = encode(img, o);
  const Mesh& mb = bilinear.triangulation.layers[0];
  const Mesh& mz = z.triangulation.layers[0];
  CHECK(mb.points.size() == mz.points.size());
  for (std::size_t v = 0; v < mb.points.size(); ++v)
    CHECK((mb.points[v].x == mz.points[v].x && mb.points[v].y == mz.points[v].y));
  CHECK(!mb.has_gradients());
  REQUIRE(mz.has_gradients());
  const MethodInfo& zienkiewicz = *find_reference_method("zienkiewicz");
  const double estimated = psnr(render_reference(bilinear.triangulation, zienkiewicz, {}), img);
  const double fitted = psnr(render_reference(z.triangulation, zienkiewicz, {}), img);
  CHECK(z.psnr == Approx(fitted).margin(1e-9));
  CHECK(fitted > estimated + 0.5);
  o.fit = VertexFit::pixel;
  CHECK_THROWS_AS(encode(img, o), UsageError);
}
