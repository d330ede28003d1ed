// SPDX-License-Identifier: MIT
// An image resampled for a panel (encoder/panel.h): the picture's box for each fit, and where its
// pixels sample the image.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "common/errors.h"
#include "encoder/panel.h"

using namespace tristream;

namespace {

// Channel 0 rises by 2 a column, channel 1 by 3 a row (below 255 on a 96x64 image): a linear
// function that the filter keeps, so a resampled pixel tells where it sampled (up to the sRGB
// curvature and rounding, a level or so).
Image ramps(int w, int h) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      img.at(x, y, 0) = std::uint8_t(20 + 2 * x);
      img.at(x, y, 1) = std::uint8_t(30 + 3 * y);
      img.at(x, y, 2) = 100;
    }
  return img;
}

// Checks that picture pixel (i, j) holds the ramps' values at ((i + dx) s, (j + dy) s) on its interior.
void check_samples(const Image& pic, double sx, double sy, double dx, double dy) {
  for (int j = 2; j < pic.height - 2; ++j)
    for (int i = 2; i < pic.width - 2; ++i) {
      INFO("picture pixel " << i << ", " << j);
      REQUIRE(std::fabs(pic.at(i, j, 0) - (20 + 2 * (i + dx) * sx)) <= 1.5);
      REQUIRE(std::fabs(pic.at(i, j, 1) - (30 + 3 * (j + dy) * sy)) <= 1.5);
    }
}

}  // namespace

TEST_CASE("fit_to_panel: stretch maps corner to corner", "[panel]") {
  const PanelPicture p = fit_to_panel(ramps(96, 64), 40, 40, Fit::stretch);
  REQUIRE(p.panel_width == 40);
  REQUIRE(p.panel_height == 40);
  REQUIRE(p.x0 == 0);
  REQUIRE(p.y0 == 0);
  REQUIRE(p.picture.width == 40);
  REQUIRE(p.picture.height == 40);
  check_samples(p.picture, 95.0 / 39, 63.0 / 39, 0, 0);
}

TEST_CASE("fit_to_panel: inside keeps the aspect and centres the picture", "[panel]") {
  // 96x64 on 40x40: n / d = 39 / 95, e_y = floor(63 * 39 / 95) = 25, o_y = floor((39 - 25) / 2) = 7.
  const PanelPicture p = fit_to_panel(ramps(96, 64), 40, 40, Fit::inside);
  REQUIRE(p.x0 == 0);
  REQUIRE(p.y0 == 7);
  REQUIRE(p.picture.width == 40);
  REQUIRE(p.picture.height == 26);
  check_samples(p.picture, 95.0 / 39, 95.0 / 39, 0, 0);
  const Image whole = panel_image(p, 9);
  REQUIRE(whole.width == 40);
  REQUIRE(whole.height == 40);
  for (int x = 0; x < 40; ++x)
    for (int c = 0; c < 3; ++c) {
      REQUIRE(whole.at(x, 6, c) == 9);
      REQUIRE(whole.at(x, 33, c) == 9);
      REQUIRE(whole.at(x, 7, c) == p.picture.at(x, 0, c));
      REQUIRE(whole.at(x, 32, c) == p.picture.at(x, 25, c));
    }
  // Portrait: the border goes left and right, the odd pixel to the right.
  const PanelPicture q = fit_to_panel(ramps(64, 96), 40, 40, Fit::inside);
  REQUIRE(q.x0 == 7);
  REQUIRE(q.picture.width == 26);
  REQUIRE(q.picture.height == 40);
}

TEST_CASE("fit_to_panel: fill covers the panel and crops the excess evenly", "[panel]") {
  // 96x64 on 40x40: n / d = 39 / 63, e_x = floor(95 * 39 / 63) = 58, o_x = floor((39 - 58) / 2) = -10:
  // panel pixel i samples (i + 10) * 63 / 39.
  const PanelPicture p = fit_to_panel(ramps(96, 64), 40, 40, Fit::fill);
  REQUIRE(p.x0 == 0);
  REQUIRE(p.y0 == 0);
  REQUIRE(p.picture.width == 40);
  REQUIRE(p.picture.height == 40);
  check_samples(p.picture, 63.0 / 39, 63.0 / 39, 10, 0);
}

TEST_CASE("fit_to_panel: the same aspect is the stretch for every fit", "[panel]") {
  const Image img = ramps(96, 64);
  const Image s = fit_to_panel(img, 191, 127, Fit::stretch).picture;
  REQUIRE(fit_to_panel(img, 191, 127, Fit::inside).picture.pixels == s.pixels);
  REQUIRE(fit_to_panel(img, 191, 127, Fit::fill).picture.pixels == s.pixels);
}

TEST_CASE("fit_to_panel: an inside picture under 2 pixels is refused", "[panel]") {
  REQUIRE_THROWS_AS(fit_to_panel(ramps(96, 2), 10, 10, Fit::inside), UsageError);
  REQUIRE_NOTHROW(fit_to_panel(ramps(96, 2), 10, 10, Fit::fill));
}
