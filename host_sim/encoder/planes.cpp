// SPDX-License-Identifier: MIT
#include "encoder/planes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/color.h"

namespace tristream::encoder {

Planes to_planes(const Image& image, ColorSpace space) {
  const int expected = channel_count(space);
  if (image.channels != expected)
    throw std::invalid_argument("to_planes: " + std::to_string(image.channels) + " channels for a " +
                                std::string(to_string(space)) + " encoding");
  Planes p(image.width, image.height, expected);
  const std::size_t n = std::size_t(image.width) * image.height;
  if (space != ColorSpace::ycbcr) {
    for (std::size_t i = 0; i < n * expected; ++i) p.v[i] = image.pixels[i];
    return p;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto ycc = rgb_to_ycbcr(image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]);
    for (int c = 0; c < 3; ++c) p.v[3 * i + c] = float(ycc[c]);
  }
  return p;
}

Planes channel_of(const Planes& planes, int c) {
  Planes out(planes.width, planes.height, 1);
  const std::size_t n = std::size_t(planes.width) * planes.height;
  for (std::size_t i = 0; i < n; ++i) out.v[i] = planes.v[i * planes.channels + c];
  return out;
}

Planes gaussian_blur(const Planes& planes, double sigma) {
  if (sigma <= 0) return planes;
  const int radius = int(std::ceil(3 * sigma));
  std::vector<double> k(2 * radius + 1);
  double total = 0;
  for (int i = -radius; i <= radius; ++i) total += k[i + radius] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& w : k) w /= total;
  const int w = planes.width, h = planes.height, ch = planes.channels;
  Planes tmp(w, h, ch), out(w, h, ch);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < ch; ++c) {
        double s = 0;
        for (int i = -radius; i <= radius; ++i) s += k[i + radius] * planes.at(std::clamp(x + i, 0, w - 1), y, c);
        tmp.at(x, y, c) = float(s);
      }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < ch; ++c) {
        double s = 0;
        for (int i = -radius; i <= radius; ++i) s += k[i + radius] * tmp.at(x, std::clamp(y + i, 0, h - 1), c);
        out.at(x, y, c) = float(s);
      }
  return out;
}

}  // namespace tristream::encoder
