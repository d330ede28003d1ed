// SPDX-License-Identifier: MIT
#include "encoder/panel.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/errors.h"
#include "io/resample.h"

namespace tristream {

PanelPicture fit_to_panel(const Image& image, int width, int height, Fit fit) {
  if (image.width < 2 || image.height < 2 || width < 2 || height < 2)
    throw std::invalid_argument("fit_to_panel: sides must be at least 2");
  PanelPicture p;
  p.panel_width = width;
  p.panel_height = height;
  if (fit == Fit::stretch) {
    p.picture = resample(image, width, height, {double(width - 1) / (image.width - 1), 0},
                         {double(height - 1) / (image.height - 1), 0});
    return p;
  }
  const FitLayout f = fit_layout(image.width, image.height, width, height, fit);
  const double scale = double(f.n) / double(f.d);
  if (fit == Fit::fill) {
    p.picture = resample(image, width, height, {scale, double(f.x0)}, {scale, double(f.y0)});
    return p;
  }
  if (f.width < 2 || f.height < 2)
    throw UsageError("--fit inside: the " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                     " picture would be " + std::to_string(f.width) + "x" + std::to_string(f.height) + " pixels on a " +
                     std::to_string(width) + "x" + std::to_string(height) + " panel; expected at least 2 a side");
  p.x0 = int(f.x0);
  p.y0 = int(f.y0);
  p.picture = resample(image, int(f.width), int(f.height), {scale, 0}, {scale, 0});
  return p;
}

Image panel_image(const PanelPicture& p, std::uint8_t background) {
  if (p.x0 == 0 && p.y0 == 0 && p.picture.width == p.panel_width && p.picture.height == p.panel_height)
    return p.picture;
  Image out(p.panel_width, p.panel_height, p.picture.channels, background);
  const std::size_t row = std::size_t(p.picture.width) * p.picture.channels;
  for (int y = 0; y < p.picture.height; ++y)
    std::copy_n(&p.picture.pixels[std::size_t(y) * row], row, &out.at(p.x0, p.y0 + y, 0));
  return out;
}

PanelPicture picture_for_panel(const Image& image, int width, int height, Fit fit, const std::string& name) {
  if (!width) {
    PanelPicture panel;
    panel.panel_width = image.width;
    panel.panel_height = image.height;
    panel.picture = image;
    return panel;
  }
  if (image.width < 2 || image.height < 2)
    throw DataError(name + ": expected an image of at least 2x2 pixels to resample, found " +
                    std::to_string(image.width) + "x" + std::to_string(image.height));
  return fit_to_panel(image, width, height, fit);
}

Triangulation on_panel(Triangulation tri, const PanelPicture& p) {
  tri.width = p.panel_width;
  tri.height = p.panel_height;
  for (Mesh& m : tri.layers)
    for (Point& q : m.points) {
      q.x += p.x0;
      q.y += p.y0;
    }
  return tri;
}

}  // namespace tristream
