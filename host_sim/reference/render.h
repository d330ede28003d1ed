/* SPDX-License-Identifier: MIT */
#pragma once
// Double-precision reference renderers of every interpolation method (docs/CONVENTIONS.md).
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/color.h"
#include "model/image.h"
#include "model/triangulation.h"
#include "reference/fit.h"

namespace tristream {

struct RenderOptions {
  int width = 0;   // output size; 0 = the triangulation's size. With Fit::stretch the output is mapped
  int height = 0;  // corner to corner: pixel (i, j) samples the domain at (i*(W-1)/(W'-1), j*(H-1)/(H'-1)).
  Fit fit = Fit::stretch;  // inside, fill: one scale for both axes (reference/fit.h)
  std::string variant;  // method-specific variant ("" = default; e.g. "thesis" for patches)
  Background background;  // pixels outside the domain (R, G, B; a grey render takes the first)
  // What a ChannelRenderer maps with: 0, corner to corner; else fit_d / fit_n domain units per output
  // pixel on both axes from pixel (0, 0) (render_reference_field sets it for the picture's box).
  std::int64_t fit_n = 0, fit_d = 0;
};

// Unclamped interpolant values, `channels` interleaved per pixel; NaN where not covered.
struct Field {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<double> v;

  Field() = default;
  Field(int w, int h, int c);
  double& at(int x, int y, int c) { return v[(std::size_t(y) * width + x) * channels + c]; }
  double at(int x, int y, int c) const { return v[(std::size_t(y) * width + x) * channels + c]; }
};

// Renders every value channel of `mesh` into `out` (already sized to the output size with
// out.channels == mesh.value_count, filled with NaN). `domain_width/height` is the
// triangulation's size (for the corner-to-corner mapping); options.fit_n/fit_d a scale instead.
using ChannelRenderer = void (*)(const Mesh& mesh, int domain_width, int domain_height,
                                 const RenderOptions& options, Field& out);

struct MethodInfo {
  std::string_view name;
  std::string_view summary;
  ChannelRenderer render;
};

// All reference methods, in the order of docs and tables.
std::span<const MethodInfo> reference_methods();
// nullptr when there is no method of that name.
const MethodInfo* find_reference_method(std::string_view name);

// Renders a whole triangulation: each mesh (or layer), YCbCr converted to RGB, clamped to
// [0, 255] and rounded to nearest; uncovered pixels get options.background.
Image render_reference(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options);
Field render_reference_field(const Triangulation& tri, const MethodInfo& method, const RenderOptions& options);

}  // namespace tristream
