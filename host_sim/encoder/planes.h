/* SPDX-License-Identifier: MIT */
#pragma once
// The encoder's working copy of an image: float channels in the encoding colour space.
#include <cstddef>
#include <vector>

#include "model/image.h"
#include "model/triangulation.h"

namespace tristream::encoder {

// width x height pixels, `channels` (1 to 4) interleaved floats each, row-major.
struct Planes {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> v;

  Planes() = default;
  Planes(int w, int h, int c) : width(w), height(h), channels(c), v(std::size_t(w) * h * c, 0.0f) {}
  float at(int x, int y, int c) const { return v[(std::size_t(y) * width + x) * channels + c]; }
  float& at(int x, int y, int c) { return v[(std::size_t(y) * width + x) * channels + c]; }
};

// The image in `space`: grey takes a 1-channel image as is, rgb a 3-channel one as is, ycbcr
// converts a 3-channel one (colour.h, unrounded). Throws std::invalid_argument on a mismatch.
Planes to_planes(const Image& image, ColorSpace space);

// One channel of `planes`.
Planes channel_of(const Planes& planes, int c);

// Separable Gaussian blur (kernel radius ceil(3 sigma), weights normalised, edges clamped).
// sigma <= 0 returns a copy.
Planes gaussian_blur(const Planes& planes, double sigma);

}  // namespace tristream::encoder
