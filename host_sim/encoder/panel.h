/* SPDX-License-Identifier: MIT */
#pragma once
// An image resampled for a panel of another size (triencode --width/--height/--fit): the picture
// lies where the renderers put a full-size triangulation rendered at the panel's size with the same
// fit (reference/fit.h, docs/CONVENTIONS.md "Fitting"), so a triangulation of it rendered on the
// panel at its own size (the stretch, an identity) shows what that render would, sharper.
#include <string>

#include "model/image.h"
#include "model/triangulation.h"
#include "reference/fit.h"

namespace tristream {

struct PanelPicture {
  int panel_width = 0, panel_height = 0;
  // The panel's pixels the picture covers: all of them for stretch and fill, the centred box of
  // fit_layout for inside (the rest is border). picture is that box resampled (io/resample.h).
  int x0 = 0, y0 = 0;
  Image picture;
};

// Resamples `image` (sides at least 2) for a width x height panel (sides at least 2). stretch maps
// corner to corner on each axis; inside and fill use one scale n / d for both axes, and output pixel
// (i, j) samples the image at ((i - o_x) d / n, (j - o_y) d / n) (fill: o <= 0, the excess cropped
// evenly, the odd pixel at the left or top). Throws UsageError when an inside picture would be less
// than 2 pixels on a side.
PanelPicture fit_to_panel(const Image& image, int width, int height, Fit fit);

// The picture an encoding of `image` takes: with `width` 0 the image itself on a panel of its own
// size, else fit_to_panel. Throws DataError naming `name` for an image below 2 x 2 to resample.
PanelPicture picture_for_panel(const Image& image, int width, int height, Fit fit, const std::string& name);

// A triangulation of p.picture placed on the panel: positions moved by the picture's offset, the
// size the panel's (with Fit::inside the border stays outside every triangle: the renderer's background).
Triangulation on_panel(Triangulation tri, const PanelPicture& p);

// The picture on the whole panel: the border (inside) holds `background` in every channel.
Image panel_image(const PanelPicture& p, std::uint8_t background = 0);

}  // namespace tristream
