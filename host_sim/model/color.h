/* SPDX-License-Identifier: MIT */
#pragma once
// JPEG YCbCr (ITU-R BT.601, full range, chroma offset 128), in double precision.
#include <array>

namespace tristream {

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
