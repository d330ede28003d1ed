/* SPDX-License-Identifier: MIT */
#pragma once
// Resampling an image through stb_image_resize (Debian's libstb): one scale and one origin per
// axis, in the pixel-centre coordinates of docs/CONVENTIONS.md (pixel (i, j) is the point (i, j)).
#include "model/image.h"

namespace tristream {

// Output pixel i samples the source at u = (i - origin) / scale; `scale` is output pixels per source
// pixel (above 0).
struct ResampleAxis {
  double scale = 1;
  double origin = 0;
};

// A width x height image of `image`'s channels. Each axis is filtered separately: Mitchell-Netravali
// (B = C = 1/3) widened by 1 / scale where the axis shrinks (it averages what one output pixel covers
// and keeps ringing low), Catmull-Rom where it grows or keeps its size (interpolating: scale 1 at an
// integer origin copies the pixels). The filter works on light, not on code values: the 8-bit values
// are sRGB-decoded, filtered and encoded again, so a pattern too fine for the output keeps its
// brightness (one-pixel stripes of 0 and 255 become about 188, half the light, where averaging code
// values would give 128, a fifth of it). Every sample point must lie in the image; where the filter
// reaches past the edge it sees the edge pixels repeated. Throws std::invalid_argument for sizes
// below 1, a scale that is not above 0 or a sample point outside [0, W-1] x [0, H-1].
Image resample(const Image& image, int width, int height, ResampleAxis x, ResampleAxis y);

}  // namespace tristream
