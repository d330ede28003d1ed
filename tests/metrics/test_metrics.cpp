// SPDX-License-Identifier: MIT
// Metrics against scikit-image (expected values from make_expected.py) and by construction.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "common/errors.h"
#include "io/image_io.h"
#include "metrics/metrics.h"

using namespace tristream;

namespace {

const std::string data_dir = std::string(TRISTREAM_SOURCE_DIR) + "/tests/metrics/data/";

Image load(const std::string& name) { return read_image(data_dir + name + ".png"); }

Image random_image(int w, int h, int c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> d(0, 255);
  Image im(w, h, c);
  for (auto& p : im.pixels) p = static_cast<std::uint8_t>(d(rng));
  return im;
}

}  // namespace

TEST_CASE("metrics equal scikit-image on Kodak crops and degraded versions") {
  std::ifstream in(data_dir + "expected.json");
  REQUIRE(in.good());
  const nlohmann::json expected = nlohmann::json::parse(in);
  REQUIRE(expected.at("pairs").size() >= 8);
  bool saw_grey = false, saw_rgb = false;
  for (const auto& pair : expected.at("pairs")) {
    const std::string a_name = pair.at("a"), b_name = pair.at("b");
    INFO(a_name << " vs " << b_name);
    const Image a = load(a_name), b = load(b_name);
    (a.channels == 1 ? saw_grey : saw_rgb) = true;
    CHECK(mse(a, b) == Approx(pair.at("mse").get<double>()).epsilon(0).margin(1e-9));
    CHECK(psnr(a, b) == Approx(pair.at("psnr").get<double>()).epsilon(0).margin(1e-9));
    CHECK(ssim(a, b) == Approx(pair.at("ssim_gaussian11").get<double>()).epsilon(0).margin(1e-4));
    CHECK(ssim(a, b, {.window = SsimWindow::uniform8}) ==
          Approx(pair.at("ssim_box8").get<double>()).epsilon(0).margin(1e-4));
    CHECK(ssim_uniform(a, b, 7) == Approx(pair.at("ssim_box7").get<double>()).epsilon(0).margin(1e-4));
    // Tighter than the required 1e-4: the computation is the same up to rounding.
    CHECK(std::abs(ssim(a, b) - pair.at("ssim_gaussian11").get<double>()) < 1e-10);
    // Symmetric in its arguments.
    CHECK(std::abs(ssim(b, a) - ssim(a, b)) < 1e-12);
  }
  CHECK(saw_grey);
  CHECK(saw_rgb);
}

TEST_CASE("identical images: MSE 0, PSNR infinite, SSIM 1") {
  for (int c : {1, 3}) {
    const Image a = random_image(40, 30, c, 7u + c);
    CHECK(mse(a, a) == 0.0);
    CHECK(std::isinf(psnr(a, a)));
    CHECK(is_identical_psnr(psnr(a, a)));
    CHECK(ssim(a, a) == Approx(1.0).epsilon(0).margin(1e-12));
    CHECK(ssim(a, a, {.window = SsimWindow::uniform8}) == Approx(1.0).epsilon(0).margin(1e-12));
    const Metrics m = compare_images(a, a);
    CHECK(m.mse == 0.0);
    CHECK(is_identical_psnr(m.psnr));
    CHECK(m.ssim == Approx(1.0).epsilon(0).margin(1e-12));
  }
}

TEST_CASE("known MSE and PSNR on a synthetic pair") {
  // Grey 10x10: a = 100 everywhere; b differs by 10 on 25 pixels and by -4 on 50 pixels.
  Image a(10, 10, 1, 100), b(10, 10, 1, 100);
  for (int i = 0; i < 25; ++i) b.pixels[i] = 110;
  for (int i = 25; i < 75; ++i) b.pixels[i] = 96;
  const double expected_mse = (25 * 100.0 + 50 * 16.0) / 100.0;  // 33
  CHECK(mse(a, b) == expected_mse);
  CHECK(psnr(a, b) == Approx(10 * std::log10(65025.0 / 33.0)).epsilon(1e-15));
  CHECK(psnr_from_mse(65025.0) == 0.0);
  CHECK(psnr_from_mse(65025.0 / 100.0) == Approx(20.0).epsilon(1e-15));

  // RGB: MSE averages over channels: one channel off by 3 everywhere -> 9 / 3 = 3.
  Image c(5, 4, 3, 50), d(5, 4, 3, 50);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) d.at(x, y, 1) = 53;
  CHECK(mse(c, d) == 3.0);
}

TEST_CASE("SSIM of constant images follows the formula with the stabilising constants") {
  // Constant windows: variances 0, so SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1).
  const Image a(16, 16, 1, 40), b(16, 16, 1, 200);
  const double c1 = (0.01 * 255) * (0.01 * 255);
  const double expected = (2.0 * 40 * 200 + c1) / (40.0 * 40 + 200.0 * 200 + c1);
  CHECK(ssim(a, b) == Approx(expected).epsilon(1e-12));
  CHECK(ssim(a, b, {.window = SsimWindow::uniform8}) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("SSIM of a single window equals the direct formula") {
  // An 8x8 image has exactly one 8x8 window: compare with the textbook computation.
  const Image a = random_image(8, 8, 1, 11), b = random_image(8, 8, 1, 12);
  double ma = 0, mb = 0;
  for (int i = 0; i < 64; ++i) ma += a.pixels[i], mb += b.pixels[i];
  ma /= 64, mb /= 64;
  double va = 0, vb = 0, cov = 0;
  for (int i = 0; i < 64; ++i) {
    va += (a.pixels[i] - ma) * (a.pixels[i] - ma);
    vb += (b.pixels[i] - mb) * (b.pixels[i] - mb);
    cov += (a.pixels[i] - ma) * (b.pixels[i] - mb);
  }
  va /= 64, vb /= 64, cov /= 64;
  const double c1 = 6.5025, c2 = 58.5225;
  const double expected = (2 * ma * mb + c1) * (2 * cov + c2) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
  CHECK(ssim(a, b, {.window = SsimWindow::uniform8}) == Approx(expected).epsilon(1e-12));
}

TEST_CASE("SSIM of an image and its negative is strongly negative") {
  const Image a = random_image(32, 32, 3, 5);
  Image b = a;
  for (auto& p : b.pixels) p = static_cast<std::uint8_t>(255 - p);
  CHECK(ssim(a, b) < -0.9);
}

TEST_CASE("mismatched or too small images are rejected with a clear error") {
  const Image a(20, 20, 1), b(20, 21, 1), c(20, 20, 3), tiny(10, 10, 1);
  CHECK_THROWS_AS(mse(a, b), DataError);
  CHECK_THROWS_AS(ssim(a, c), DataError);
  CHECK_THROWS_WITH(mse(a, c), Catch::Contains("expected 20x20x1, found 20x20x3"));
  CHECK_THROWS_WITH(ssim(tiny, tiny), Catch::Contains("expected at least 11x11"));
  CHECK_NOTHROW(ssim(tiny, tiny, {.window = SsimWindow::uniform8}));
  CHECK_THROWS_AS(ssim_uniform(a, a, 0), UsageError);
}
