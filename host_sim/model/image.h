/* SPDX-License-Identifier: MIT */
#pragma once
// An 8-bit image with interleaved channels, row-major, no padding.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tristream {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;  // 1 (grey) or 3 (RGB)
  std::vector<std::uint8_t> pixels;

  Image() = default;
  Image(int w, int h, int c, std::uint8_t fill = 0)
      : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, fill) {}

  std::uint8_t& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  std::uint8_t at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels + c]; }
};

// BT.601 luma of an RGB image (round to nearest); a grey image is returned as is.
Image to_grey(const Image& image);

}  // namespace tristream
