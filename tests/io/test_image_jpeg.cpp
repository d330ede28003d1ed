// SPDX-License-Identifier: MIT
// JPEG through libjpeg-turbo: grey, YCbCr at every chroma subsampling, progressive, CMYK and YCCK
// decode close to stb_image's pixels (which read JPEGs before) and the same on every run; damaged
// JPEGs are refused with the byte and libjpeg's reason, never as another format.
#include <cstddef>
#include <cstdio>  // jpeglib.h needs size_t and FILE declared first

#include <jpeglib.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.h"
#include "io/image_io.h"
#include "stb_reference.h"

using namespace tristream;

namespace {

struct JpegSpec {
  J_COLOR_SPACE space = JCS_YCbCr;     // as stored: JCS_GRAYSCALE, JCS_YCbCr, JCS_CMYK or JCS_YCCK
  int h_sampling = 2, v_sampling = 2;  // of luma (chroma 1 x 1)
  bool progressive = false;
  int width = 38, height = 29, quality = 85;
};

// A smooth picture with some detail, as photographs are: samples of `channels` (4: C, M, Y, K).
std::vector<JSAMPLE> picture(int width, int height, int channels) {
  std::vector<JSAMPLE> samples;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        samples.push_back(
            JSAMPLE(127.5 + 100 * std::sin(0.21 * x + 0.13 * y + 1.7 * c) + 20 * std::cos(0.9 * x * y / 7.0)));
  return samples;
}

// A JPEG written by libjpeg (the same library decodes it; stb_image's decoder is the comparison).
std::string make_jpeg(const JpegSpec& spec) {
  jpeg_compress_struct cinfo{};
  jpeg_error_mgr errors{};
  cinfo.err = jpeg_std_error(&errors);
  jpeg_create_compress(&cinfo);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&cinfo, &buffer, &size);
  const bool grey = spec.space == JCS_GRAYSCALE, ink = spec.space == JCS_CMYK || spec.space == JCS_YCCK;
  cinfo.image_width = JDIMENSION(spec.width);
  cinfo.image_height = JDIMENSION(spec.height);
  cinfo.input_components = grey ? 1 : ink ? 4 : 3;
  cinfo.in_color_space = grey ? JCS_GRAYSCALE : ink ? JCS_CMYK : JCS_RGB;
  jpeg_set_defaults(&cinfo);
  jpeg_set_colorspace(&cinfo, spec.space);
  jpeg_set_quality(&cinfo, spec.quality, TRUE);
  cinfo.comp_info[0].h_samp_factor = spec.h_sampling;
  cinfo.comp_info[0].v_samp_factor = spec.v_sampling;
  if (spec.progressive) jpeg_simple_progression(&cinfo);
  jpeg_start_compress(&cinfo, TRUE);
  std::vector<JSAMPLE> samples = picture(spec.width, spec.height, cinfo.input_components);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = samples.data() + std::size_t(cinfo.next_scanline) * spec.width * cinfo.input_components;
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  jpeg_destroy_compress(&cinfo);
  std::string out(reinterpret_cast<const char*>(buffer), size);
  std::free(buffer);
  return out;
}

Image without_last_columns(const Image& image, int columns) {
  Image cropped(image.width - columns, image.height, image.channels);
  for (int y = 0; y < cropped.height; ++y)
    for (int x = 0; x < cropped.width; ++x)
      for (int c = 0; c < image.channels; ++c) cropped.at(x, y, c) = image.at(x, y, c);
  return cropped;
}

}  // namespace

TEST_CASE("JPEG: every stored colour space and subsampling decodes near stb_image's pixels, the same each run") {
  const std::vector<std::pair<std::string, JpegSpec>> cases = {
      {"grey", {JCS_GRAYSCALE, 1, 1}},
      {"YCbCr 4:4:4", {JCS_YCbCr, 1, 1}},
      {"YCbCr 4:2:2", {JCS_YCbCr, 2, 1}},
      {"YCbCr 4:2:0", {JCS_YCbCr, 2, 2}},
      {"YCbCr 4:2:0 progressive", {JCS_YCbCr, 2, 2, true}},
      {"grey progressive", {JCS_GRAYSCALE, 1, 1, true}},
      {"CMYK (Adobe)", {JCS_CMYK, 1, 1}},
      {"YCCK (Adobe)", {JCS_YCCK, 2, 2}},
  };
  for (const auto& [name, spec] : cases) {
    INFO(name);
    const std::string bytes = make_jpeg(spec);
    const Image image = decode_image(bytes, "x.jpg");
    CHECK(image.width == spec.width);
    CHECK(image.height == spec.height);
    CHECK(image.channels == (spec.space == JCS_GRAYSCALE ? 1 : 3));
    CHECK(decode_image(bytes, "x.jpg").pixels == image.pixels);
    const auto stb = test::stb_decode(bytes);
    REQUIRE(stb.has_value());
    // The two decoders round the inverse DCT, the chroma upsampling and the colour conversion
    // differently: by at most 4 levels on these pictures, but for the last two columns (next test).
    const int difference = test::max_difference(without_last_columns(image, 2), without_last_columns(*stb, 2));
    CHECK(difference >= 0);
    CHECK(difference <= 4);
  }
}

TEST_CASE("JPEG: with 4:2:2 chroma, the column before the last is nearer the picture than stb_image's") {
  // stb_image 2.27 upsamples the last chroma sample of a row from its left neighbour (weights 3:1
  // the wrong way round), which moves that column by up to about 25 levels.
  for (int width : {37, 38}) {
    INFO("width " << width);
    JpegSpec spec{JCS_YCbCr, 2, 1};
    spec.width = width;
    const std::string bytes = make_jpeg(spec);
    const Image image = decode_image(bytes, "x.jpg");
    const auto stb = test::stb_decode(bytes);
    REQUIRE(stb.has_value());
    const std::vector<JSAMPLE> source = picture(spec.width, spec.height, 3);
    const int x = (width - 1) / 2 * 2;  // the first column of the last chroma sample
    double ours = 0, theirs = 0;
    for (int y = 0; y < spec.height; ++y)
      for (int c = 0; c < 3; ++c) {
        const int want = source[std::size_t((y * spec.width + x) * 3 + c)];
        ours += std::abs(int(image.at(x, y, c)) - want);
        theirs += std::abs(int(stb->at(x, y, c)) - want);
      }
    CHECK(ours < theirs / 2);
    CHECK(test::max_difference(without_last_columns(image, 2), without_last_columns(*stb, 2)) <= 4);
  }
}

TEST_CASE("JPEG: every truncation is refused as a damaged JPEG, never named another format") {
  const std::string bytes = make_jpeg(JpegSpec{});
  REQUIRE(bytes.size() > 350);
  for (std::size_t n = 3; n < bytes.size() - 2; ++n) {  // the last 2 bytes are the end marker
    INFO(n << " of " << bytes.size() << " bytes");
    const std::string cut = bytes.substr(0, n);
    CHECK_THROWS_AS(decode_image(cut, "cut.jpg"), DataError);
    CHECK_THROWS_WITH(decode_image(cut, "cut.jpg"), Catch::StartsWith("cut.jpg: byte ") &&
                                                        Catch::Contains("not a valid JPEG: ") &&
                                                        !Catch::Contains("png", Catch::CaseSensitive::No));
  }
  CHECK_THROWS_WITH(decode_image(bytes.substr(0, 350), "cut.jpg"),
                    Catch::Equals("cut.jpg: byte 350: not a valid JPEG: Premature end of JPEG file"));
}

TEST_CASE("JPEG: corrupt entropy-coded data is refused, not decoded past") {
  std::string bytes = make_jpeg(JpegSpec{});
  const std::size_t scan = bytes.find("\xff\xda");
  REQUIRE(scan != std::string::npos);
  // A marker in the middle of the scan: libjpeg would warn and fill the rest of the picture in.
  for (std::size_t i = scan + 40; i < scan + 80; i += 2) bytes.replace(i, 2, "\xff\xd9");
  CHECK_THROWS_WITH(decode_image(bytes, "scan.jpg"),
                    Catch::StartsWith("scan.jpg: byte ") && Catch::Contains("not a valid JPEG: Corrupt JPEG data"));
}

TEST_CASE("JPEG: a frame claiming more pixels than the limit is refused before decoding") {
  std::string bytes = make_jpeg(JpegSpec{});
  const std::size_t frame = bytes.find("\xff\xc0");
  REQUIRE(frame != std::string::npos);
  bytes.replace(frame + 5, 4, std::string("\xea\x60\xea\x60", 4));  // 60000 x 60000
  CHECK_THROWS_WITH(decode_image(bytes, "big.jpg"), Catch::StartsWith("big.jpg: byte ") &&
                                                        Catch::Contains("the limit for an image") &&
                                                        Catch::Contains("60000x60000"));
}
