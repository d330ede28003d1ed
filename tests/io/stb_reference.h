/* SPDX-License-Identifier: MIT */
#pragma once
// stb_image 2.27, which read images before the format decoders: what it made of a file, to show
// that a decoder gives the pixels it gave (or where and by how much they differ). Tests only.
#include <cstdlib>
#include <optional>
#include <string_view>

#include <stb/stb_image.h>

#include "model/image.h"

namespace tristream::test {

// The pixels stb_image read from `bytes` as read_image asked for them (1 channel for grey and
// grey+alpha, else 3), or nothing when stb refused them.
inline std::optional<Image> stb_decode(std::string_view bytes) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  int w = 0, h = 0, n = 0;
  if (!stbi_info_from_memory(data, int(bytes.size()), &w, &h, &n)) return std::nullopt;
  const int want = n <= 2 ? 1 : 3;
  stbi_uc* pixels = stbi_load_from_memory(data, int(bytes.size()), &w, &h, &n, want);
  if (!pixels) return std::nullopt;
  Image image(w, h, want);
  std::copy(pixels, pixels + image.pixels.size(), image.pixels.begin());
  stbi_image_free(pixels);
  return image;
}

// The largest difference of two images' samples; -1 when their sizes or channels differ.
inline int max_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return -1;
  int most = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    most = std::max(most, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  return most;
}

}  // namespace tristream::test
