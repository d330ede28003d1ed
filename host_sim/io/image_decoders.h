/* SPDX-License-Identifier: MIT */
#pragma once
// One decoder per format read (png_decode.cpp, jpeg_decode.cpp, bmp_decode.cpp, pnm_decode.cpp);
// decode_image (image_io.h) picks one by the file's first bytes.
//
// Each takes the whole file, checks the image's size against `max_pixels` before allocating its
// pixels, and returns grey (and grey with alpha) as 1 channel, anything in colour as 3 (alpha is
// dropped, not composited). Every failure is a DataError that names `path`, the byte offset where
// it was found and what was expected there; running out of memory is std::bad_alloc.
#include <cstdint>
#include <string>
#include <string_view>

#include "model/image.h"

namespace tristream {

Image decode_png(std::string_view bytes, const std::string& path, std::uint64_t max_pixels);
Image decode_jpeg(std::string_view bytes, const std::string& path, std::uint64_t max_pixels);
Image decode_bmp(std::string_view bytes, const std::string& path, std::uint64_t max_pixels);
Image decode_pnm(std::string_view bytes, const std::string& path, std::uint64_t max_pixels);

// Throws DataError naming `path` and the limit when a `width` x `height` image (as its header at
// byte `offset` says) has more than `max_pixels` pixels, or a side of 0.
void check_image_size(const std::string& path, std::uint64_t offset, std::uint64_t width, std::uint64_t height,
                      std::uint64_t max_pixels);

}  // namespace tristream
