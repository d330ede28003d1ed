/* SPDX-License-Identifier: MIT */
#pragma once
// Image files through stb_image (PNG, JPEG, BMP, PGM/PPM in) and stb_image_write (PNG out).
#include <cstdint>
#include <string>

#include "io/limits.h"

#include "model/image.h"

namespace tristream {

// Grey and grey+alpha load as 1 channel, RGB and RGBA as 3 (alpha dropped).
// Throws InputError when missing or unreadable, DataError when not a decodable image or larger than
// `max_pixels` (checked before decoding; the message names the limit). stb does not check PNG CRCs: a PNG whose
// chunks have wrong CRCs but decode is read without complaint.
Image read_image(const std::string& path, std::uint64_t max_pixels = limits::max_image_pixels);

// Writes a PNG through a temporary file and a rename. Throws OutputError.
void write_png(const std::string& path, const Image& image);
// The bytes of the PNG that write_png writes. Throws OutputError naming `path` when encoding fails.
std::string encode_png(const Image& image, const std::string& path);

}  // namespace tristream
