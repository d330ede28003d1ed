// SPDX-License-Identifier: MIT
// Formats are told by their first bytes; those the README does not list are refused, naming the
// ones that are read, even when stb_image (which read images before) decoded them.
#include <catch2/catch.hpp>
#include <string>

#include "common/errors.h"
#include "io/image_format.h"
#include "io/image_io.h"
#include "stb_reference.h"

using namespace tristream;

namespace {

// Small files stb_image decodes, each of a format the tools do not read.
const std::string gif(  // 1 x 1, one colour
    "GIF89a\x01\x00\x01\x00\x80\x00\x00\xff\x00\x00\x00\x00\x00,"
    "\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02\x44\x01\x00;",
    35);
const std::string tga(  // 2 x 1, uncompressed true colour, no footer (TGA has no signature)
    "\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00\x00\x00\x02\x00\x01\x00\x18\x00\x10\x20\x30\x40\x50\x60", 24);
const std::string hdr =
    std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n") + std::string("\x80\x80\x80\x81", 4);

void refused(const std::string& bytes, const std::string& found) {
  INFO(found);
  CHECK_THROWS_AS(decode_image(bytes, "x.img"), DataError);
  CHECK_THROWS_WITH(decode_image(bytes, "x.img"),
                    Catch::StartsWith("x.img: byte 0: expected a PNG, JPEG, BMP or PNM (PGM or PPM) image, found ") &&
                        Catch::Contains(found));
}

}  // namespace

TEST_CASE("GIF, TGA and HDR, which stb_image decoded, are refused naming the formats read") {
  REQUIRE(test::stb_decode(gif).has_value());
  REQUIRE(test::stb_decode(tga).has_value());
  REQUIRE(test::stb_decode(hdr).has_value());
  refused(gif, "a GIF image, which is not read");
  refused(tga, "an unknown format (first bytes 00 00 02 00 00 00 00 00)");
  refused(hdr, "an HDR (Radiance) image, which is not read");
}

TEST_CASE("other formats are named by their signatures, anything else by its first bytes") {
  refused("8BPS\x00\x01", "a PSD (Photoshop) image");
  refused(std::string("\x53\x80\xf6\x34PICT", 8), "a PIC (Softimage) image");
  refused(std::string("RIFF\x10\x00\x00\x00WEBPVP8 ", 16), "a WebP image");
  refused(std::string("II*\x00\x08\x00\x00\x00", 8), "a TIFF image");
  refused("P4\n1 1\n\x80", "a PBM (bitmap) image");
  refused("P7\nWIDTH 1\n", "a PAM image");
  refused(std::string(20, '\x00') + std::string("TRUEVISION-XFILE.\x00", 18), "a TGA image");
  refused("this is not an image", "an unknown format (first bytes 74 68 69 73 20 69 73 20)");
  refused("", "an empty file");
  refused("P6", "an unknown format");  // a PNM magic needs white space after it
}

TEST_CASE("the first bytes choose the decoder, whatever the name") {
  CHECK(detect_image_format("\x89PNG\r\n\x1a\n") == ImageFormat::png);
  CHECK(detect_image_format("\xff\xd8\xff\xe0") == ImageFormat::jpeg);
  CHECK(detect_image_format("BM") == ImageFormat::bmp);
  CHECK(detect_image_format("P5 ") == ImageFormat::pnm);
  CHECK(detect_image_format("P3\n") == ImageFormat::pnm);
  CHECK(detect_image_format("\x89PNG") == ImageFormat::unknown);
  // A JPEG named .png is read as a JPEG, and its errors say JPEG.
  CHECK_THROWS_WITH(decode_image("\xff\xd8\xff\xd9", "x.png"), Catch::Contains("not a valid JPEG"));
}
