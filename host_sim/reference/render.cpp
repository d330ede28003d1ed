// SPDX-License-Identifier: MIT
#include "reference/render.h"

#include <cmath>
#include <limits>

#include "common/errors.h"
#include "model/color.h"

namespace tristream {

Field::Field(int w, int h, int c)
    : width(w), height(h), channels(c), v(std::size_t(w) * h * c, std::numeric_limits<double>::quiet_NaN()) {}

Field render_reference_field(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options) {
  const int w = options.width > 0 ? options.width : tri.width;
  const int h = options.height > 0 ? options.height : tri.height;
  const int nc = tri.channels();
  if (!tri.layered()) {
    Field out(w, h, nc);
    method.render(tri.layers.at(0), tri.width, tri.height, options, out);
    return out;
  }
  Field out(w, h, nc);
  for (int c = 0; c < nc; ++c) {
    Field layer(w, h, 1);
    method.render(tri.layers.at(c), tri.width, tri.height, options, layer);
    for (std::size_t p = 0; p < std::size_t(w) * h; ++p) out.v[p * nc + c] = layer.v[p];
  }
  return out;
}

Image render_reference(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options) {
  const Field field = render_reference_field(tri, method, options);
  const int nc = field.channels;
  Image img(field.width, field.height, nc, options.background);
  // Clamp, then round half away from zero (x >= 0 here, so x - floor(x) is exact).
  auto to_byte = [](double x) {
    x = x < 0 ? 0 : x > 255 ? 255 : x;  // not NaN here
    const int r = static_cast<int>(x);
    return static_cast<std::uint8_t>(r + int(x - r >= 0.5));  // no branch: half the pixels round up
  };
  for (std::size_t p = 0; p < std::size_t(field.width) * field.height; ++p) {
    const double* f = &field.v[p * nc];
    bool covered = true;
    for (int c = 0; c < nc; ++c) covered = covered && !std::isnan(f[c]);
    if (!covered) continue;  // a pixel outside any channel's domain keeps the background
    if (tri.space == ColorSpace::ycbcr) {
      const auto rgb = ycbcr_to_rgb(f[0], f[1], f[2]);
      for (int c = 0; c < 3; ++c) img.pixels[p * 3 + c] = to_byte(rgb[c]);
    } else {
      for (int c = 0; c < nc; ++c) img.pixels[p * nc + c] = to_byte(f[c]);
    }
  }
  return img;
}

}  // namespace tristream
