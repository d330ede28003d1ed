// SPDX-License-Identifier: MIT
#include "io/image_io.h"

#include <climits>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "io/atomic_file.h"
#include "io/image_decoders.h"
#include "io/image_format.h"
#include "io/limits.h"

// stb_image_write only writes (Debian's libstb, linked through pkg-config "stb"); no image is read through stb.
#include <stb/stb_image_write.h>

namespace tristream {

void check_image_size(const std::string& path, std::uint64_t offset, std::uint64_t width, std::uint64_t height,
                      std::uint64_t max_pixels) {
  const std::string at = path + ": byte " + std::to_string(offset) + ": ";
  if (width == 0 || height == 0)
    throw DataError(at + "expected an image of at least 1x1 pixels, found " + std::to_string(width) + "x" +
                    std::to_string(height));
  // Either side above 2^32 would overflow the product; such a side is over every limit anyway.
  if (width > UINT32_MAX || height > UINT32_MAX || width * height > max_pixels || width > INT_MAX || height > INT_MAX)
    throw DataError(at + "expected an image of at most " + std::to_string(max_pixels) +
                    " pixels (the limit for an image), found " + std::to_string(width) + "x" + std::to_string(height));
}

Image decode_image(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  switch (detect_image_format(bytes)) {
    case ImageFormat::png: return decode_png(bytes, path, max_pixels);
    case ImageFormat::jpeg: return decode_jpeg(bytes, path, max_pixels);
    case ImageFormat::bmp: return decode_bmp(bytes, path, max_pixels);
    case ImageFormat::pnm: return decode_pnm(bytes, path, max_pixels);
    case ImageFormat::unknown: break;
  }
  refuse_image_format(bytes, path);
}

Image read_image(const std::string& path, std::uint64_t max_pixels) {
  const Activity activity("reading " + path);
  const std::string bytes = read_file(path);
  return decode_image(bytes, path, max_pixels);
}

void write_png(const std::string& path, const Image& image) { write_file_atomically(path, encode_png(image, path)); }

std::string encode_png(const Image& image, const std::string& path) {
  std::string out;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), std::size_t(size));
  };
  if (!stbi_write_png_to_func(sink, &out, image.width, image.height, image.channels, image.pixels.data(),
                              image.width * image.channels))
    throw OutputError(path + ": PNG encoding failed");
  return out;
}

}  // namespace tristream
