// SPDX-License-Identifier: MIT
// PNM through the project's decoder: binary PGM and PPM of 8 bits give stb_image's pixels, text
// (P2, P3) the same as binary, 16-bit samples their high byte and other maxvals a rounded scale;
// short files, samples above maxval and bad headers are refused with the byte.
#include <catch2/catch.hpp>
#include <random>
#include <string>
#include <vector>

#include "common/errors.h"
#include "io/image_io.h"
#include "stb_reference.h"

using namespace tristream;

namespace {

struct Pnm {
  std::string binary, text;
  std::vector<unsigned> samples;
};

// The same random samples as binary (P5/P6) and text (P2/P3), with comments in the header.
Pnm make_pnm(int channels, int width, int height, unsigned maxval, std::uint32_t seed) {
  std::mt19937 random(seed);
  Pnm pnm;
  const std::string size =
      std::to_string(width) + " # a comment\n" + std::to_string(height) + "\n" + std::to_string(maxval) + "\n";
  pnm.binary = (channels == 1 ? "P5\n" : "P6\n") + size;
  pnm.text = (channels == 1 ? "P2\n" : "P3\n") + size;
  for (int i = 0; i < width * height * channels; ++i) {
    const unsigned v = random() % (maxval + 1);
    pnm.samples.push_back(v);
    if (maxval > 255) pnm.binary += char(v >> 8);
    pnm.binary += char(v & 0xff);
    pnm.text += std::to_string(v) + (i % 7 == 6 ? "\n" : " ");
  }
  return pnm;
}

}  // namespace

TEST_CASE("PNM: 8-bit PGM and PPM decode to stb_image's pixels, and text to the same as binary") {
  for (int channels : {1, 3}) {
    INFO(channels << " channel(s)");
    const Pnm pnm = make_pnm(channels, 13, 7, 255, std::uint32_t(channels));
    const auto stb = test::stb_decode(pnm.binary);
    REQUIRE(stb.has_value());
    const Image binary = decode_image(pnm.binary, "x.pnm");
    CHECK(binary.channels == channels);
    CHECK(test::max_difference(binary, *stb) == 0);
    CHECK(decode_image(pnm.text, "x.pnm").pixels == binary.pixels);
  }
}

TEST_CASE("PNM: 16-bit samples keep their high byte, other maxvals scale to 255 rounded") {
  for (unsigned maxval : {65535u, 1023u, 15u, 1u, 256u}) {
    INFO("maxval " << maxval);
    const Pnm pnm = make_pnm(3, 11, 5, maxval, maxval);
    for (const std::string& bytes : {pnm.binary, pnm.text}) {
      const Image image = decode_image(bytes, "x.ppm");
      REQUIRE(image.pixels.size() == pnm.samples.size());
      for (std::size_t i = 0; i < pnm.samples.size(); ++i) {
        const unsigned v = pnm.samples[i];
        const unsigned want = maxval == 65535 ? v >> 8 : (v * 255 + maxval / 2) / maxval;
        CHECK(image.pixels[i] == want);
      }
    }
  }
}

TEST_CASE("PNM: what is not read is refused with the byte and what was expected") {
  auto refused = [](const std::string& bytes, const std::string& text) {
    CHECK_THROWS_AS(decode_image(bytes, "bad.pgm"), DataError);
    CHECK_THROWS_WITH(decode_image(bytes, "bad.pgm"), Catch::StartsWith("bad.pgm: byte ") && Catch::Contains(text));
  };
  const Pnm pnm = make_pnm(1, 4, 3, 255, 1);
  refused(pnm.binary.substr(0, pnm.binary.size() - 1), "expected 12 samples of 1 byte(s), found 11 bytes");
  refused("P5\n4 3\n", "expected the maximum value, found the end of the file");
  refused("P5\n4 x 255\n", "expected the height, found 'x'");
  refused("P5\n4 3 0\n", "expected a maximum value of 1 to 65535, found 0");
  refused("P5\n4 3 70000\n", "expected the maximum value of at most 65535");
  refused("P2\n2 1 9\n3 10\n", "byte 11: expected a sample of at most 9, found 10");
  refused("P2\n2 1 9\n3\n", "expected a sample, found the end of the file");
  refused("P5\n0 3 255\n", "expected an image of at least 1x1 pixels, found 0x3");
  refused("P5\n9000 9000 255\n", "the limit for an image");
  refused("P3\n1 1 255\n1 2 3x\n", "expected white space after a sample, found 'x'");
}
