// SPDX-License-Identifier: MIT
#include "model/image.h"

#include <cmath>

namespace tristream {

Image to_grey(const Image& image) {
  if (image.channels == 1) return image;
  Image grey(image.width, image.height, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double l = 0.299 * image.at(x, y, 0) + 0.587 * image.at(x, y, 1) + 0.114 * image.at(x, y, 2);
      grey.at(x, y, 0) = static_cast<std::uint8_t>(std::lround(std::fmin(255.0, l)));
    }
  return grey;
}

}  // namespace tristream
