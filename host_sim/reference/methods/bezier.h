#pragma once
// Interpolation on the second-degree Bezier triangle patch of each triangle and its three
// edge neighbours (thesis §3.3, §4.2; NOTES.md §3.3), averaged where patches overlap.
//
// Variants (RenderOptions::variant):
// - "thesis": a and b stepped by kBezierThesisStep from 0 while a <= 1 and b <= 1 - a, each
//   sample rounded to the nearest pixel and added to sum and count buffers; the bilinear
//   pre-fill counts as one sample in every domain pixel.
// - "" (default): the same surfaces, every pixel of a patch taken once (tessellation into
//   micro-triangles plus per-pixel inversion of the patch mapping, methods/patch_raster.h);
//   the value is the mean of the patches over the pixel, or bilinear where no patch reaches.
// Border triangles (fewer than three neighbours) have no patch (§4.2); a mesh without
// interior triangles renders as bilinear. Pixels outside the domain stay NaN.
#include "reference/methods/patch_control.h"
#include "reference/render.h"

namespace tristream {

inline constexpr double kBezierThesisStep = 0.006;

// P(a, b, c) = a^2 P200 + b^2 P020 + c^2 P002 + 2ab P110 + 2bc P011 + 2ac P101 with
// c = 1 - a - b, for position (output pixels) and every value channel.
class BezierPatch {
 public:
  explicit BezierPatch(const PatchControl& control) : control_(control) {}

  // Position and its partial derivatives with respect to a and b (c = 1 - a - b).
  void position(double a, double b, double& x, double& y, double& x_a, double& x_b, double& y_a,
                double& y_b) const;
  Point position(double a, double b) const;
  // control.channels values at (a, b).
  void values(double a, double b, double* out) const;
  // Subdivisions n per side so that the image of a parameter step of 1/n along any grid
  // direction is at most `max_edge` pixels: |dP| <= 2 * (longest control-net edge) / n.
  int subdivisions(double max_edge) const;

 private:
  const PatchControl& control_;
};

void render_bezier(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out);

}  // namespace tristream
