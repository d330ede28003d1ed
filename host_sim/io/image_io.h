#pragma once
// Image files through stb_image (PNG, JPEG, BMP, PGM/PPM in) and stb_image_write (PNG out).
#include <string>

#include "model/image.h"

namespace tristream {

// Grey and grey+alpha load as 1 channel, RGB and RGBA as 3 (alpha dropped).
// Throws InputError when missing or unreadable, DataError when not a decodable image.
Image read_image(const std::string& path);

// Writes a PNG through a temporary file and a rename. Throws OutputError.
void write_png(const std::string& path, const Image& image);

}  // namespace tristream
