/* SPDX-License-Identifier: MIT */
#pragma once
// Image files: PNG (libpng), JPEG (libjpeg-turbo), BMP and PNM (PGM and PPM; own decoders) in, told
// apart by their first bytes; PNG out through stb_image_write.
#include <cstdint>
#include <string>
#include <string_view>

#include "io/limits.h"

#include "model/image.h"

namespace tristream {

// Grey and grey+alpha load as 1 channel, RGB, RGBA, palette and CMYK as 3 (alpha dropped).
// Throws InputError when missing or unreadable, DataError when not one of the formats read, damaged
// (a PNG chunk's CRC, JPEG data that libjpeg reports as corrupt, a short file) or larger than
// `max_pixels` (checked before the pixels are allocated; the message names the limit).
Image read_image(const std::string& path, std::uint64_t max_pixels = limits::max_image_pixels);

// The same from the file's bytes in memory; `path` names it in messages.
Image decode_image(std::string_view bytes, const std::string& path,
                   std::uint64_t max_pixels = limits::max_image_pixels);

// Writes a PNG through a temporary file and a rename. Throws OutputError.
void write_png(const std::string& path, const Image& image);
// The bytes of the PNG that write_png writes. Throws OutputError naming `path` when encoding fails.
std::string encode_png(const Image& image, const std::string& path);

}  // namespace tristream
