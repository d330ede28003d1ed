// SPDX-License-Identifier: MIT
// The resampler (io/resample.h): where output pixels sample the source, and how it filters.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "io/resample.h"

using namespace tristream;

namespace {

constexpr double pi = 3.14159265358979323846;

// A smooth grey image: slopes up to 6 levels a pixel, so a sample point off by 0.3 pixel is
// off by up to 2 levels.
double smooth(double x, double y) { return 128 + 100 * std::sin(2 * pi * x / 100) * std::cos(2 * pi * y / 120); }

Image smooth_image(int w, int h) {
  Image img(w, h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y, 0) = std::uint8_t(std::lround(smooth(x, y)));
  return img;
}

// The largest |output - smooth(sample point)| over output pixels whose sample point lies at least
// `margin` source pixels inside the image (near the edges the filter sees the edge repeated).
double worst_interior_error(const Image& out, const Image& in, ResampleAxis ax, ResampleAxis ay, double margin) {
  double worst = 0;
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i) {
      const double u = (i - ax.origin) / ax.scale, v = (j - ay.origin) / ay.scale;
      if (u < margin || v < margin || u > in.width - 1 - margin || v > in.height - 1 - margin) continue;
      worst = std::max(worst, std::fabs(out.at(i, j, 0) - smooth(u, v)));
    }
  return worst;
}

}  // namespace

TEST_CASE("resample samples a smooth image where the mapping says, shrinking and growing", "[resample]") {
  const Image in = smooth_image(400, 300);
  SECTION("shrink corner to corner, 400x300 to 120x90") {
    const ResampleAxis ax{119.0 / 399, 0}, ay{89.0 / 299, 0};
    const Image out = resample(in, 120, 90, ax, ay);
    REQUIRE(out.width == 120);
    REQUIRE(out.height == 90);
    REQUIRE(out.channels == 1);
    // Rounding of the source (0.5) plus the filter's slight blur of a 100-pixel period.
    CHECK(worst_interior_error(out, in, ax, ay, 8) <= 1.5);
  }
  SECTION("shrink with an origin: a crop that starts 20 output pixels into the image") {
    const ResampleAxis ax{0.25, -20}, ay{0.25, -5};
    const Image out = resample(in, 70, 60, ax, ay);
    CHECK(worst_interior_error(out, in, ax, ay, 8) <= 1.5);
  }
  SECTION("grow, 400x300 to 700x500") {
    const ResampleAxis ax{699.0 / 399, 0}, ay{499.0 / 299, 0};
    CHECK(worst_interior_error(resample(in, 700, 500, ax, ay), in, ax, ay, 2) <= 1.5);
  }
}

TEST_CASE("resample at scale 1 copies the pixels", "[resample]") {
  Image in(37, 23, 3);
  for (std::size_t k = 0; k < in.pixels.size(); ++k) in.pixels[k] = std::uint8_t((k * 7919) % 251);
  const Image out = resample(in, 37, 23, {1, 0}, {1, 0});
  REQUIRE(out.pixels == in.pixels);
  // An integer origin shifts them.
  const Image shifted = resample(in, 30, 20, {1, -3}, {1, -2});
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x)
      for (int c = 0; c < 3; ++c) REQUIRE(shifted.at(x, y, c) == in.at(x + 3, y + 2, c));
}

TEST_CASE("resample filters light, not code values", "[resample]") {
  // One-pixel stripes of 0 and 255: half the light. Its sRGB value is 187.5; averaging the code
  // values would give 128.
  Image in(64, 64, 3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) in.at(x, y, c) = (x & 1) ? 255 : 0;
  const Image out = resample(in, 16, 16, {15.0 / 63, 0}, {15.0 / 63, 0});
  for (int y = 2; y < 14; ++y)
    for (int x = 2; x < 14; ++x)
      for (int c = 0; c < 3; ++c) {
        INFO("pixel " << x << ", " << y);
        REQUIRE(std::abs(int(out.at(x, y, c)) - 188) <= 2);
      }
}

TEST_CASE("resample refuses empty sizes and bad scales", "[resample]") {
  const Image in(4, 4, 1);
  REQUIRE_THROWS_AS(resample(in, 0, 4, {1, 0}, {1, 0}), std::invalid_argument);
  REQUIRE_THROWS_AS(resample(in, 4, 4, {0, 0}, {1, 0}), std::invalid_argument);
  REQUIRE_THROWS_AS(resample(in, 4, 4, {1, NAN}, {1, 0}), std::invalid_argument);
  // Sample points past the edge: stb would abort, resample refuses.
  REQUIRE_THROWS_AS(resample(in, 4, 4, {1, -1}, {1, 0}), std::invalid_argument);
  REQUIRE_THROWS_AS(resample(in, 4, 4, {1, 0}, {1, 1}), std::invalid_argument);
  REQUIRE_THROWS_AS(resample(in, 5, 4, {1, 0}, {1, 0}), std::invalid_argument);
}
