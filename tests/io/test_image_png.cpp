// SPDX-License-Identifier: MIT
// PNG through libpng: every colour type, bit depth and interlacing gives stb_image's pixels (which
// read PNGs before); damaged files are refused with the byte and libpng's reason.
#include <png.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "../support/test_images.h"
#include "common/errors.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "stb_reference.h"

using namespace tristream;

namespace {

struct PngSpec {
  int width = 13, height = 7, bit_depth = 8, color_type = PNG_COLOR_TYPE_RGB;
  bool interlaced = false;
  bool transparency = false;  // a tRNS chunk: alpha for palette entries, or one transparent colour
};

void append(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}

// A PNG of random samples (palette indices within the palette) written by libpng.
std::string make_png(const PngSpec& spec, std::uint32_t seed) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, png_uint_32(spec.width), png_uint_32(spec.height), spec.bit_depth, spec.color_type,
               spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  std::mt19937 random(seed);
  const int entries = 1 << std::min(spec.bit_depth, 8);
  std::vector<png_color> palette(static_cast<std::size_t>(entries));
  for (png_color& c : palette) c = {png_byte(random()), png_byte(random()), png_byte(random())};
  std::vector<png_byte> alpha(static_cast<std::size_t>(entries));
  for (png_byte& a : alpha) a = png_byte(random());
  png_color_16 colour{0, png_uint_16(random() % 2), png_uint_16(random() % 2), png_uint_16(random() % 2),
                      png_uint_16(random() % 2)};
  if (spec.color_type == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette.data(), entries);
  if (spec.transparency)
    png_set_tRNS(png, info, alpha.data(), spec.color_type == PNG_COLOR_TYPE_PALETTE ? entries : 0, &colour);
  png_write_info(png, info);
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  std::vector<png_byte> samples(row_bytes * std::size_t(spec.height));
  // Low samples often, so that a 1-bit transparent colour of 0 or 1 occurs.
  for (png_byte& s : samples) s = png_byte(random() % 4 == 0 ? 0 : random());
  std::vector<png_bytep> rows(std::size_t(spec.height));
  for (int y = 0; y < spec.height; ++y) rows[std::size_t(y)] = samples.data() + std::size_t(y) * row_bytes;
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void check_like_stb(const std::string& bytes, const std::string& name) {
  INFO(name);
  const auto stb = test::stb_decode(bytes);
  REQUIRE(stb.has_value());
  const Image image = decode_image(bytes, name);
  CHECK(test::max_difference(image, *stb) == 0);
}

}  // namespace

TEST_CASE("PNG: every colour type, bit depth, tRNS and interlacing decode to stb_image's pixels") {
  struct Kind {
    int color_type;
    std::vector<int> depths;
  };
  const std::vector<Kind> kinds = {{PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}},
                                   {PNG_COLOR_TYPE_RGB, {8, 16}},
                                   {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8}},
                                   {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16}},
                                   {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16}}};
  std::uint32_t seed = 1;
  for (const Kind& kind : kinds)
    for (int depth : kind.depths)
      for (bool interlaced : {false, true})
        for (bool transparency : {false, true}) {
          if (transparency && (kind.color_type & PNG_COLOR_MASK_ALPHA)) continue;
          const PngSpec spec{13, 7, depth, kind.color_type, interlaced, transparency};
          const std::string bytes = make_png(spec, seed++);
          check_like_stb(bytes, "colour type " + std::to_string(kind.color_type) + ", " + std::to_string(depth) +
                                    " bits" + (interlaced ? ", interlaced" : "") + (transparency ? ", tRNS" : ""));
          const Image image = decode_image(bytes, "x.png");
          CHECK(image.channels == ((kind.color_type & PNG_COLOR_MASK_COLOR) ? 3 : 1));
        }
}

TEST_CASE("PNG: the shipped pictures and the shared photographs decode to stb_image's pixels") {
  std::vector<std::filesystem::path> files = {test::demo_image()};
  for (const auto& e : std::filesystem::directory_iterator(std::string(TRISTREAM_SOURCE_DIR) + "/tests/golden"))
    if (e.path().extension() == ".png") files.push_back(e.path());
  const std::string shared = test::shared_images_dir();
  if (shared.empty()) WARN("the shared photographs are left out: $" << test::images_variable << " is unset");
  else
    for (const auto& e : std::filesystem::recursive_directory_iterator(shared))
      if (e.path().extension() == ".png") files.push_back(e.path());
  for (const auto& file : files) check_like_stb(read_file(file.string()), file.string());
}

TEST_CASE("PNG: a chunk whose CRC does not match is refused, naming the chunk") {
  std::string bytes = make_png(PngSpec{}, 7);
  const std::size_t idat = bytes.find("IDAT");
  REQUIRE(idat != std::string::npos);
  const std::size_t length =
      std::size_t(static_cast<unsigned char>(bytes[idat - 2])) << 8 | static_cast<unsigned char>(bytes[idat - 1]);
  bytes[idat + 4 + length] ^= 0x55;  // the first byte of IDAT's CRC
  CHECK_THROWS_AS(decode_image(bytes, "crc.png"), DataError);
  CHECK_THROWS_WITH(decode_image(bytes, "crc.png"), Catch::StartsWith("crc.png: byte ") &&
                                                        Catch::Contains("not a valid PNG") && Catch::Contains("IDAT") &&
                                                        Catch::Contains("CRC"));
}

TEST_CASE("PNG: every truncation of a file is refused with the byte it ends at") {
  const std::string bytes = make_png(PngSpec{}, 8);
  for (std::size_t n = 8; n < bytes.size() - 12; ++n) {  // the last 12 bytes are IEND, which is not read
    INFO(n << " of " << bytes.size() << " bytes");
    CHECK_THROWS_WITH(decode_image(bytes.substr(0, n), "cut.png"),
                      Catch::StartsWith("cut.png: byte ") && Catch::Contains("not a valid PNG"));
  }
}

TEST_CASE("PNG: a header claiming more pixels than the limit is refused before decoding") {
  std::string bytes = make_png(PngSpec{}, 9);
  bytes.replace(16, 8, std::string("\x00\x00\x75\x30\x00\x00\x75\x30", 8));  // 30000 x 30000, CRC now wrong
  CHECK_THROWS_WITH(decode_image(bytes, "big.png"), Catch::Contains("big.png: byte 16: ") &&
                                                        Catch::Contains("the limit for an image") &&
                                                        Catch::Contains("30000x30000"));
  CHECK_THROWS_WITH(decode_image(make_png(PngSpec{}, 10), "x.png", 13 * 7 - 1),
                    Catch::Contains("the limit for an image"));
  CHECK(decode_image(make_png(PngSpec{}, 10), "x.png", 13 * 7).width == 13);
}
