// SPDX-License-Identifier: MIT
// BMP through the project's decoder: every header, bit depth and row order stb_image read gives
// its pixels; what it does not read (RLE, bad headers, short files, bad palette indices) is refused
// with the byte.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>

#include "common/errors.h"
#include "io/image_io.h"
#include "stb_reference.h"

using namespace tristream;

namespace {

struct BmpSpec {
  int header = 40;  // 12 (OS/2), 40, 108 or 124
  int bits = 24;
  int compression = 0;  // 0 BI_RGB, 3 BI_BITFIELDS
  std::uint32_t masks[3] = {0, 0, 0};
  bool top_down = false;
  int width = 13, height = 7;
};

void put(std::string& out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out += char(value >> (8 * i) & 0xff);
}

// A BMP of random pixels (palette indices within the palette) written by the rules of the format.
std::string make_bmp(const BmpSpec& spec, std::uint32_t seed) {
  std::mt19937 random(seed);
  const bool core = spec.header == 12;
  const int entries = spec.bits <= 8 ? 1 << spec.bits : 0;
  const int entry_bytes = core ? 3 : 4;
  const bool masks_after = spec.header == 40 && spec.compression == 3;
  const std::uint64_t offset =
      14 + std::uint64_t(spec.header) + (masks_after ? 12 : 0) + std::uint64_t(entries * entry_bytes);
  const std::uint64_t stride = (std::uint64_t(spec.width) * std::uint64_t(spec.bits) + 31) / 32 * 4;
  std::string out = "BM";
  put(out, offset + stride * std::uint64_t(spec.height), 4);
  put(out, 0, 4);
  put(out, offset, 4);
  put(out, std::uint64_t(spec.header), 4);
  const std::int64_t height = spec.top_down ? -spec.height : spec.height;
  put(out, std::uint64_t(spec.width), core ? 2 : 4);
  put(out, std::uint64_t(height), core ? 2 : 4);
  put(out, 1, 2);
  put(out, std::uint64_t(spec.bits), 2);
  if (!core) {
    put(out, std::uint64_t(spec.compression), 4);
    put(out, stride * std::uint64_t(spec.height), 4);
    put(out, 2835, 4);
    put(out, 2835, 4);
    put(out, 0, 4);
    put(out, 0, 4);
    if (spec.header > 40 || masks_after)
      for (std::uint32_t m : spec.masks) put(out, m, 4);
    if (spec.header > 40) put(out, 0, 4);                            // alpha mask
    while (out.size() < 14 + std::size_t(spec.header)) out += '\0';  // colour space, intent, profile
    if (masks_after)
      for (std::uint32_t m : spec.masks) put(out, m, 4);
  }
  for (int i = 0; i < entries * entry_bytes; ++i) out += char(random());
  for (std::uint64_t i = 0; i < stride * std::uint64_t(spec.height); ++i) out += char(random());
  return out;
}

}  // namespace

TEST_CASE("BMP: every header, bit depth, mask and row order decodes to stb_image's pixels") {
  const std::vector<std::pair<std::string, BmpSpec>> cases = {
      {"24 bits", {40, 24}},
      {"24 bits, top-down", {40, 24, 0, {}, true}},
      {"24 bits, odd width (row padding)", {40, 24, 0, {}, false, 5, 3}},
      {"32 bits", {40, 32}},
      {"16 bits, 5-5-5", {40, 16}},
      {"16 bits, 5-6-5 bitfields", {40, 16, 3, {0xf800, 0x07e0, 0x001f}}},
      {"32 bits, bitfields B-G-R", {40, 32, 3, {0x000000ff, 0x0000ff00, 0x00ff0000}}},
      {"8-bit palette", {40, 8}},
      {"4-bit palette", {40, 4}},
      {"1-bit palette", {40, 1, 0, {}, false, 19, 5}},
      {"OS/2 header, 8-bit palette", {12, 8}},
      {"OS/2 header, 24 bits", {12, 24}},
      {"version 4 header, 32 bits, bitfields 4-4-4", {108, 32, 3, {0xf00, 0x0f0, 0x00f}}},
      {"version 5 header, 24 bits", {124, 24}},
      {"version 5 header, 16 bits, bitfields 1-5-5 (3-bit red)", {124, 16, 3, {0x7000, 0x0f80, 0x007c}}},
  };
  std::uint32_t seed = 1;
  for (const auto& [name, spec] : cases) {
    INFO(name);
    const std::string bytes = make_bmp(spec, seed++);
    const auto stb = test::stb_decode(bytes);
    REQUIRE(stb.has_value());
    const Image image = decode_image(bytes, "x.bmp");
    CHECK(image.channels == 3);
    CHECK(test::max_difference(image, *stb) == 0);
  }
}

TEST_CASE("BMP: what is not read is refused with the byte and what was expected") {
  const std::string good = make_bmp(BmpSpec{}, 1);
  auto refused = [](const std::string& bytes, const std::string& text) {
    CHECK_THROWS_AS(decode_image(bytes, "bad.bmp"), DataError);
    CHECK_THROWS_WITH(decode_image(bytes, "bad.bmp"), Catch::StartsWith("bad.bmp: byte ") && Catch::Contains(text));
  };
  refused(good.substr(0, good.size() - 30), "expected the pixels");
  refused(good.substr(0, 20), "the whole header");
  std::string rle = make_bmp(BmpSpec{40, 8}, 2);
  rle[30] = 1;  // BI_RLE8
  refused(rle, "RLE");
  std::string header = good;
  header[14] = 20;
  refused(header, "expected a header of 12, 40, 56, 108 or 124 bytes, found 20");
  std::string bits = good;
  bits[28] = 7;
  refused(bits, "expected 1, 4, 8, 16, 24 or 32 bits per pixel, found 7");
  std::string palette = make_bmp(BmpSpec{40, 8}, 3);
  palette[46] = 2;  // two palette entries used: most indices are past them
  refused(palette, "expected a palette index below 2");
  std::string masks = make_bmp(BmpSpec{40, 16, 3, {0xf800, 0x07e0, 0x0011}}, 4);
  refused(masks, "contiguous");
  std::string wide = good;
  wide.replace(18, 8, std::string("\x00\x80\x00\x00\x00\x80\x00\x00", 8));  // 32768 x 32768
  refused(wide, "the limit for an image");
}
