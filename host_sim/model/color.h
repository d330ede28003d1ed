/* SPDX-License-Identifier: MIT */
#pragma once
// JPEG YCbCr (ITU-R BT.601, full range, chroma offset 128), in double precision.
#include <array>
#include <cstdint>

namespace tristream {

// The colour of pixels outside a triangulation's domain: R, G, B, or one value for every channel.
// A grey output takes the first value (as the core's RenderParams::background does).
struct Background {
  std::uint8_t rgb[3] = {0, 0, 0};
  constexpr Background() = default;
  constexpr Background(std::uint8_t all) : rgb{all, all, all} {}  // NOLINT: one value is every channel
  constexpr Background(std::uint8_t r, std::uint8_t g, std::uint8_t b) : rgb{r, g, b} {}
};

inline std::array<double, 3> rgb_to_ycbcr(double r, double g, double b) {
  return {0.299 * r + 0.587 * g + 0.114 * b,
          128.0 - 0.168735892 * r - 0.331264108 * g + 0.5 * b,
          128.0 + 0.5 * r - 0.418687589 * g - 0.081312411 * b};
}

inline std::array<double, 3> ycbcr_to_rgb(double y, double cb, double cr) {
  return {y + 1.402 * (cr - 128.0),
          y - 0.344136286 * (cb - 128.0) - 0.714136286 * (cr - 128.0),
          y + 1.772 * (cb - 128.0)};
}

}  // namespace tristream
