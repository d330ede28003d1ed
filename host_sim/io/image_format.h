/* SPDX-License-Identifier: MIT */
#pragma once
// Which image format a file holds, told by its first bytes (never by its name), and the refusal
// of every format the tools do not read.
#include <string>
#include <string_view>

namespace tristream {

enum class ImageFormat { png, jpeg, bmp, pnm, unknown };

// The format of `bytes` by its signature: PNG's eight bytes, JPEG's SOI marker and the next
// marker's FF, "BM", or PNM's "P2", "P3", "P5" or "P6" followed by white space.
ImageFormat detect_image_format(std::string_view bytes);

// The formats read, as the messages list them.
inline constexpr const char* readable_image_formats = "a PNG, JPEG, BMP or PNM (PGM or PPM) image";

// Throws DataError naming `path`: the formats that are read, and what `bytes` holds instead (GIF,
// PSD, TGA, HDR, PIC, PBM, PAM, WebP, TIFF named when recognised, else the first bytes in hex).
[[noreturn]] void refuse_image_format(std::string_view bytes, const std::string& path);

}  // namespace tristream
