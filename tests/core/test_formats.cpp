// SPDX-License-Identifier: MIT
// Pixel formats, dithering, colour conversion and viewport placement, checked pixel by pixel
// against independent expectations.
#include <catch2/catch.hpp>

#include <array>

#include "core_support.h"
#include "pixel_conversion.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

// A flat-coloured 2-triangle image: every pixel of the domain has exactly (r, g, b).
Triangulation flat(int w, int h, double r, double g, double b, ColorSpace space = ColorSpace::rgb) {
  Mesh m;
  m.value_count = 3;
  m.points = {{0, 0}, {double(w - 1), 0}, {0, double(h - 1)}, {double(w - 1), double(h - 1)}};
  for (int k = 0; k < 4; ++k) m.values.insert(m.values.end(), {r, g, b});
  m.triangles = {Triangle{{0, 1, 3}}, Triangle{{0, 3, 2}}};
  m.normalize_winding();
  return single_mesh(m, w, h, space);
}

CoreFrame render(const Triangulation& t, core::PixelFormat f, bool dither = false) {
  CoreOptions o;
  o.format = f;
  o.dither = dither;
  o.tile_width = 8;
  o.tile_height = 8;
  return render_core_frame(t, "bilinear", o);
}

}  // namespace

TEST_CASE("byte layout of every format") {
  const Triangulation t = flat(9, 5, 200, 100, 50);
  const unsigned word = (unsigned(std::lround(200 * 31 / 255.0)) << 11) |
                        (unsigned(std::lround(100 * 63 / 255.0)) << 5) | unsigned(std::lround(50 * 31 / 255.0));
  CoreFrame f = render(t, core::PixelFormat::rgb888);
  CHECK((f.bytes[0] == 200 && f.bytes[1] == 100 && f.bytes[2] == 50));
  f = render(t, core::PixelFormat::rgb565_le);
  CHECK((f.bytes[0] == (word & 0xFF) && f.bytes[1] == (word >> 8)));
  f = render(t, core::PixelFormat::rgb565_be);
  CHECK((f.bytes[0] == (word >> 8) && f.bytes[1] == (word & 0xFF)));
  f = render(t, core::PixelFormat::xrgb8888);
  CHECK((f.bytes[0] == 50 && f.bytes[1] == 100 && f.bytes[2] == 200 && f.bytes[3] == 0xFF));
  f = render(t, core::PixelFormat::l8);
  CHECK(int(f.bytes[0]) == int(std::lround(0.299 * 200 + 0.587 * 100 + 0.114 * 50)));
  // Every pixel identical: a flat image has no seams.
  for (core::PixelFormat fmt : {core::PixelFormat::rgb888, core::PixelFormat::rgb565_be, core::PixelFormat::xrgb8888}) {
    f = render(t, fmt);
    const int bpp = core::bytes_per_pixel(fmt);
    int differing = 0;
    for (std::size_t i = 0; i < f.bytes.size(); ++i) differing += f.bytes[i] != f.bytes[i % bpp];
    CHECK(differing == 0);
  }
}

TEST_CASE("Bayer dithering of RGB565 averages to the true colour and follows the screen position") {
  // 8-bit 100 lies between the 5-bit levels 12 (98.7) and 13 (106.9): dithered tiles must mix them.
  const Triangulation t = flat(64, 64, 100, 100, 100);
  const CoreFrame f = render(t, core::PixelFormat::rgb565_le, true);
  double sum = 0;
  for (std::size_t i = 0; i < f.bytes.size(); i += 2) {
    const unsigned w = f.bytes[i] | f.bytes[i + 1] << 8;
    sum += (w >> 11) * 255.0 / 31;
  }
  CHECK(std::abs(sum / (64 * 64) - 100) < 1.0);
  // Pattern repeats every 4 pixels in x and y, independent of the 8x8 tiles.
  int mismatches = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x)
      mismatches += f.bytes[2 * (y * 64 + x)] != f.bytes[2 * ((y + 4) * 64 + x + 4)];
  CHECK(mismatches == 0);
  const CoreFrame plain = render(t, core::PixelFormat::rgb565_le, false);
  CHECK(bytes_differing(plain.bytes, f.bytes) > 0);
}

TEST_CASE("YCbCr is converted to RGB (BT.601 full range) and clamped") {
  // Y 128, Cb 128, Cr 255: R = 128 + 1.402 * 127 = 306 -> 255 (clamped), G = 128 - 0.714 * 127 = 37.3, B = 128.
  const CoreFrame f = render(flat(6, 6, 128, 128, 255, ColorSpace::ycbcr), core::PixelFormat::rgb888);
  CHECK(int(f.bytes[0]) == 255);
  CHECK(int(f.bytes[1]) == int(std::lround(128 - 0.714136286 * 127)));
  CHECK(int(f.bytes[2]) == 128);
  int r[3];
  core::detail::ycbcr_to_rgb_q8(100 * 256, 90 * 256, 200 * 256, r);
  CHECK(std::abs(r[0] / 256.0 - (100 + 1.402 * 72)) < 0.01);
  CHECK(std::abs(r[1] / 256.0 - (100 - 0.344136286 * -38 - 0.714136286 * 72)) < 0.01);
  CHECK(std::abs(r[2] / 256.0 - (100 + 1.772 * -38)) < 0.01);
}

TEST_CASE("background outside the domain, viewport placement") {
  Mesh m;  // a triangle covering the top-left half only
  m.points = {{0, 0}, {19, 0}, {0, 19}};
  m.values = {10, 10, 10};
  m.triangles = {Triangle{{0, 1, 2}}};
  m.normalize_winding();
  const Triangulation t = single_mesh(m, 20, 20);
  CoreOptions o;
  o.format = core::PixelFormat::l8;
  o.background = 77;
  o.tile_width = o.tile_height = 7;
  const CoreFrame full = render_core_frame(t, "bilinear", o);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      INFO(x << "," << y);
      CHECK(int(full.bytes[y * 20 + x]) == (x + y <= 19 ? 10 : 77));
    }
  o.viewport = core::Rect{3, 5, 17, 11};
  const CoreFrame part = render_core_frame(t, "bilinear", o);
  REQUIRE((part.width == 14 && part.height == 6));
  int wrong = 0;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 14; ++x) wrong += part.bytes[y * 14 + x] != full.bytes[(y + 5) * 20 + x + 3];
  CHECK(wrong == 0);
}

TEST_CASE("resized output maps corners to corners") {
  Mesh m;
  m.points = {{0, 0}, {9, 0}, {0, 9}, {9, 9}};
  m.values = {0, 90, 90, 180};  // v = 10 (x + y): linear, reproduced exactly by bilinear
  m.triangles = {Triangle{{0, 1, 3}}, Triangle{{0, 3, 2}}};
  m.normalize_winding();
  CoreOptions o;
  o.format = core::PixelFormat::l8;
  o.width = 19;
  o.height = 28;
  const CoreFrame f = render_core_frame(single_mesh(m, 10, 10), "bilinear", o);
  REQUIRE((f.width == 19 && f.height == 28));
  int worst = 0;
  for (int j = 0; j < 28; ++j)
    for (int i = 0; i < 19; ++i) {
      const double expect = 10 * (i * 9.0 / 18 + j * 9.0 / 27);
      worst = std::max(worst, std::abs(int(f.bytes[j * 19 + i]) - int(std::lround(expect))));
    }
  CHECK(worst <= 1);
  CHECK(int(f.bytes[0]) == 0);
  CHECK(int(f.bytes[28 * 19 - 1]) == 180);
}

TEST_CASE("every 8-bit value packs the same in RGB565, XRGB8888 and L8 as the RGB888 pixel says") {
  // A ramp 0..255 in R and B and 255..0 in G along x (bilinear reproduces it exactly): the
  // packed formats (SSE2 lanes on x86-64 hosts) must equal pack565 / luma of the RGB888 bytes for
  // every channel value, the whole range of the division by 255.
  Mesh m;
  m.value_count = 3;
  m.points = {{0, 0}, {255, 0}, {0, 3}, {255, 3}};
  m.values = {0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255};
  m.triangles = {Triangle{{0, 1, 3}}, Triangle{{0, 3, 2}}};
  m.normalize_winding();
  const Triangulation t = single_mesh(m, 256, 4, ColorSpace::rgb);
  const CoreFrame rgb = render(t, core::PixelFormat::rgb888);
  const CoreFrame le = render(t, core::PixelFormat::rgb565_le), be = render(t, core::PixelFormat::rgb565_be);
  const CoreFrame x = render(t, core::PixelFormat::xrgb8888), grey = render(t, core::PixelFormat::l8);
  int wrong = 0, ramp = 0;
  for (std::size_t i = 0; i < 256 * 4; ++i) {
    const std::uint8_t r = rgb.bytes[3 * i], g = rgb.bytes[3 * i + 1], b = rgb.bytes[3 * i + 2];
    ramp += r == i % 256 && g == 255 - i % 256 && b == i % 256;
    const unsigned w = core::detail::pack565(r, g, b, 127);
    wrong += le.bytes[2 * i] != (w & 0xFF) || le.bytes[2 * i + 1] != (w >> 8);
    wrong += be.bytes[2 * i] != (w >> 8) || be.bytes[2 * i + 1] != (w & 0xFF);
    wrong += x.bytes[4 * i] != b || x.bytes[4 * i + 1] != g || x.bytes[4 * i + 2] != r || x.bytes[4 * i + 3] != 0xFF;
    wrong += grey.bytes[i] != core::detail::luma(r, g, b);
  }
  CHECK(ramp == 256 * 4);
  CHECK(wrong == 0);
}

TEST_CASE("RGB565 without dithering by multiply-adds equals the division by 255 for every value") {
  // The fields are independent: every value of each channel, against every value of the others
  // in steps that cover all their low bits.
  int wrong = 0;
  for (unsigned r = 0; r < 256; ++r)
    for (unsigned g = 0; g < 256; ++g)
      for (unsigned b = 0; b < 256; b += 17)
        wrong += core::detail::pack565_nearest(r, g, b) !=
                     core::detail::pack565(std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 127) ||
                 core::detail::pack565_nearest(b, r, g) !=
                     core::detail::pack565(std::uint8_t(b), std::uint8_t(r), std::uint8_t(g), 127);
  CHECK(wrong == 0);
}

TEST_CASE("Dithered RGB565 by multiply-adds equals the division by 255 for every value and offset") {
  int wrong = 0;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) {
      const std::uint32_t o = core::detail::bayer_offset(column, row);
      for (unsigned v = 0; v < 256; ++v)
        for (unsigned w : {0u, 1u, 127u, 128u, 254u, 255u}) {
          const unsigned rgb[3][3] = {{v, w, w}, {w, v, w}, {w, w, v}};
          for (const auto& c : rgb)
            wrong += core::detail::pack565_dithered(c[0], c[1], c[2], o * core::detail::dither_scale) !=
                     core::detail::pack565(std::uint8_t(c[0]), std::uint8_t(c[1]), std::uint8_t(c[2]), o);
        }
    }
  CHECK(wrong == 0);
}

TEST_CASE("RGB565 by table equals the division by 255 for every value, in both byte orders") {
  // The bytes the table form stores against pack565's value in the format's order.
  auto bytes_of = [](std::uint16_t h) { return std::array<std::uint8_t, 2>{std::uint8_t(h), std::uint8_t(h >> 8)}; };
  auto expected = [](std::uint16_t w, bool be) {
    return be ? std::array<std::uint8_t, 2>{std::uint8_t(w >> 8), std::uint8_t(w)}
              : std::array<std::uint8_t, 2>{std::uint8_t(w), std::uint8_t(w >> 8)};
  };
  int wrong = 0;
  for (unsigned v = 0; v < 256; ++v)
    for (unsigned w : {0u, 1u, 127u, 128u, 254u, 255u}) {
      const unsigned rgb[3][3] = {{v, w, w}, {w, v, w}, {w, w, v}};
      for (const auto& c : rgb) {
        const std::uint16_t ref = core::detail::pack565(std::uint8_t(c[0]), std::uint8_t(c[1]), std::uint8_t(c[2]), 127);
        wrong += bytes_of(core::detail::pack565_bytes_by_table<core::PixelFormat::rgb565_le>(c[0], c[1], c[2])) !=
                 expected(ref, false);
        wrong += bytes_of(core::detail::pack565_bytes_by_table<core::PixelFormat::rgb565_be>(c[0], c[1], c[2])) !=
                 expected(ref, true);
        std::uint8_t px[2] = {0, 0};
        core::detail::store565_bytes(px, core::detail::pack565_bytes_by_table<core::PixelFormat::rgb565_be>(c[0], c[1], c[2]));
        wrong += px[0] != std::uint8_t(ref >> 8) || px[1] != std::uint8_t(ref);
      }
    }
  CHECK(wrong == 0);
}
