// SPDX-License-Identifier: MIT
#include "io/resample.h"

#include <cmath>
#include <stdexcept>

// The implementation comes from Debian's libstb (linked through pkg-config "stb").
#include <stb/stb_image_resize.h>

namespace tristream {

namespace {

stbir_filter filter_for(double scale) { return scale < 1 ? STBIR_FILTER_MITCHELL : STBIR_FILTER_CATMULLROM; }

// stb maps output pixel centres i + 1/2 to source pixel centres u + 1/2 by (i + 1/2 + shift) / scale;
// u = (i - origin) / scale gives shift = scale / 2 - 1/2 - origin.
float stb_shift(ResampleAxis a) { return float(a.scale / 2 - 0.5 - a.origin); }

}  // namespace

Image resample(const Image& image, int width, int height, ResampleAxis x, ResampleAxis y) {
  if (width < 1 || height < 1 || image.width < 1 || image.height < 1)
    throw std::invalid_argument("resample: sizes must be at least 1");
  if (!(x.scale > 0) || !(y.scale > 0) || !std::isfinite(x.scale) || !std::isfinite(y.scale) ||
      !std::isfinite(x.origin) || !std::isfinite(y.origin))
    throw std::invalid_argument("resample: scales must be finite and above 0");
  // stb's filters read at most their radius past the edge (and abort beyond): every sample point
  // must lie in the image, up to float rounding.
  auto inside = [](ResampleAxis a, int out, int in) {
    const double slack = 1e-3;
    return -a.origin / a.scale >= -slack && (out - 1 - a.origin) / a.scale <= in - 1 + slack;
  };
  if (!inside(x, width, image.width) || !inside(y, height, image.height))
    throw std::invalid_argument("resample: sample points outside the image");
  Image out(width, height, image.channels);
  const int ok = stbir_resize_subpixel(image.pixels.data(), image.width, image.height, image.width * image.channels,
                                       out.pixels.data(), width, height, width * image.channels, STBIR_TYPE_UINT8,
                                       image.channels, STBIR_ALPHA_CHANNEL_NONE, 0, STBIR_EDGE_CLAMP, STBIR_EDGE_CLAMP,
                                       filter_for(x.scale), filter_for(y.scale), STBIR_COLORSPACE_SRGB, nullptr,
                                       float(x.scale), float(y.scale), stb_shift(x), stb_shift(y));
  if (!ok) throw std::runtime_error("resample: stb_image_resize failed");
  return out;
}

}  // namespace tristream
