// SPDX-License-Identifier: MIT
#include "io/image_io.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "io/atomic_file.h"
#include "io/limits.h"

// Implementations come from Debian's libstb (linked through pkg-config "stb").
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace tristream {

Image read_image(const std::string& path, std::uint64_t max_pixels) {
  const Activity activity("reading " + path);
  const std::string bytes = read_file(path);
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &n))
    throw DataError(path + ": expected a PNG, JPEG, BMP or PNM image, found undecodable data (" +
                    stbi_failure_reason() + ")");
  if (std::uint64_t(w) * std::uint64_t(h) > max_pixels)
    throw DataError(path + ": expected an image of at most " + std::to_string(max_pixels) +
                    " pixels (the limit for an image), found " + std::to_string(w) + "x" + std::to_string(h));
  const int want = (n <= 2) ? 1 : 3;
  stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w,
                                        &h, &n, want);
  if (!data) throw DataError(path + ": cannot decode image (" + std::string(stbi_failure_reason()) + ")");
  Image img(w, h, want);
  std::memcpy(img.pixels.data(), data, img.pixels.size());
  stbi_image_free(data);
  return img;
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
