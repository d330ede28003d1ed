// SPDX-License-Identifier: MIT
#include "reference/render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "io/limits.h"
#include "model/color.h"

namespace tristream {

Field::Field(int w, int h, int c)
    : width(w), height(h), channels(c), v(std::size_t(w) * h * c, std::numeric_limits<double>::quiet_NaN()) {}

namespace {

// The pixels of the picture's box, rendered with the fit's one scale, placed at the box's offset
// in an output of w x h (NaN elsewhere: the border of Fit::inside; the crop of Fit::fill is dropped).
Field render_fitted(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options, int w, int h) {
  const FitLayout f = fit_layout(tri.width, tri.height, w, h, options.fit);
  if (std::uint64_t(f.width) * std::uint64_t(f.height) > limits::max_image_pixels)
    throw UsageError("the fitted picture would be " + std::to_string(f.width) + " x " + std::to_string(f.height) +
                     " pixels, more than the render limit of " + std::to_string(limits::max_image_pixels));
  RenderOptions box = options;
  box.fit = Fit::stretch;
  box.width = int(f.width);
  box.height = int(f.height);
  box.fit_n = f.n;
  box.fit_d = f.d;
  const Field picture = render_reference_field(tri, method, box);
  Field out(w, h, picture.channels);
  const std::size_t nc = std::size_t(picture.channels);
  for (int j = 0; j < h; ++j) {
    const std::int64_t pj = j - f.y0;
    if (pj < 0 || pj >= f.height) continue;
    for (int i = 0; i < w; ++i) {
      const std::int64_t pi = i - f.x0;
      if (pi < 0 || pi >= f.width) continue;
      const double* src = &picture.v[(std::size_t(pj) * std::size_t(f.width) + std::size_t(pi)) * nc];
      std::copy(src, src + nc, &out.v[(std::size_t(j) * w + i) * nc]);
    }
  }
  return out;
}

}  // namespace

Field render_reference_field(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options) {
  const int w = options.width > 0 ? options.width : tri.width;
  const int h = options.height > 0 ? options.height : tri.height;
  const Activity activity("rendering " + std::to_string(w) + " x " + std::to_string(h) + " pixels (reference)");
  if (options.fit != Fit::stretch) {
    if (w < 2 || h < 2 || tri.width < 2 || tri.height < 2)
      throw UsageError("a fit needs an output and a triangulation of at least 2 x 2 pixels");
    return render_fitted(tri, method, options, w, h);
  }
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
  Image img(field.width, field.height, nc);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = options.background.rgb[i % nc];
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
