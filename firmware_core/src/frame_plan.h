/* SPDX-License-Identifier: MIT */
#pragma once
// What a render call resolves from its parameters before drawing: output size, viewport, tile
// size, pixel format and the position mapping, with the checks that reject bad parameters.
#include <stdint.h>

#include "output_mapping.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#include "tristream/render_params.h"
#include "tristream/status.h"

namespace tristream::core::detail {
namespace {

// Rectangles and the mapping are in drawing positions: output positions + (shift_x, shift_y), the
// smallest multiples of 4 that keep the domain's mapped positions non-negative (0 unless a fill
// crops). Pixels do not depend on it: everything the core computes is relative to a triangle's
// vertices or a row's first pixel, and the Bayer matrix repeats every 4 pixels.
struct FramePlan {
  int32_t out_w = 0, out_h = 0;
  Rect view;  // drawing positions
  int32_t tile_w = 0, tile_h = 0;
  PixelFormat format = PixelFormat::rgb888;
  Mapping map;
  int32_t shift_x = 0, shift_y = 0;
  int32_t target_stride = 0;  // a target's stride (RenderParams::target; 0 resolved), 0 without one
};

// The largest |RenderParams::target_stride|: rows - 1 of it and a row stay below 2^31 bytes.
inline constexpr int32_t max_target_stride = 1 << 19;
static_assert(int64_t(config::max_dimension - 1) * max_target_stride + 4 * config::max_dimension <= INT32_MAX,
              "a target's byte offsets fit an int32_t");

// The smallest multiple of 4 at least -o (0 for o >= 0).
constexpr int32_t crop_shift(int32_t o) { return o < 0 ? (3 - o) / 4 * 4 : 0; }

inline Status plan_frame(const Blob& blob, const RenderParams& p, FramePlan* r) {
  if (!blob.bytes) return Status::null_argument;
  r->out_w = p.output_width ? p.output_width : blob.width;
  r->out_h = p.output_height ? p.output_height : blob.height;
  if (r->out_w < 2 || r->out_h < 2 || r->out_w > config::max_dimension || r->out_h > config::max_dimension)
    return Status::bad_params;
  r->view = p.viewport;
  const Rect& v = p.viewport;
  if (v.x0 == 0 && v.y0 == 0 && v.x1 == 0 && v.y1 == 0) {
    r->view = Rect{0, 0, r->out_w, r->out_h};
  } else if (v.empty()) {
    return Status::bad_params;
  }
  if (r->view.x0 < 0 || r->view.y0 < 0 || r->view.x1 > r->out_w || r->view.y1 > r->out_h) return Status::bad_params;
  r->tile_w = p.tile_width ? p.tile_width : r->view.width();
  r->tile_h = p.tile_height ? p.tile_height : r->view.height();
  if (r->tile_w > r->view.width()) r->tile_w = r->view.width();
  if (r->tile_h > r->view.height()) r->tile_h = r->view.height();
  if (bytes_per_pixel(p.format) == 0) return Status::bad_params;
  if (!(config::pixel_formats >> int(p.format) & 1) || !(config::methods >> int(blob.method) & 1) ||
      !(config::color_spaces >> int(blob.space) & 1) || (blob.layer_count > 1 && !config::layered))
    return Status::not_compiled;
  r->format = p.format;
  // A target: its stride (0: the viewport's rows back to back) holds a row, and at most
  // max_target_stride bytes keep every byte offset in the int32_t of the pixel writers; no packed
  // tiles (the target's rows are its own).
  int32_t stride = p.target_stride;
  if (p.target) {
    const int32_t row = r->view.width() * bytes_per_pixel(p.format);
    if (!stride) stride = row;
    const uint32_t step = stride < 0 ? 0u - uint32_t(stride) : uint32_t(stride);
    if (p.packed_tiles || step < uint32_t(row) || step > uint32_t(max_target_stride)) return Status::bad_params;
  } else if (stride) {
    return Status::bad_params;
  }
  r->target_stride = stride;
  if (p.fit != Fit::stretch && p.fit != Fit::inside && p.fit != Fit::fill) return Status::bad_params;
  const FitLayout f = fit_layout(blob.width, blob.height, r->out_w, r->out_h, p.fit);
  r->shift_x = crop_shift(f.ox);
  r->shift_y = crop_shift(f.oy);
  r->map = drawing_mapping(f, r->shift_x, r->shift_y);
  // The coordinate budget (docs/FIXED_POINT.md): drawing positions below max_dimension 2^S. Only a
  // fill goes beyond, when its picture is about max_dimension pixels long or longer.
  constexpr int32_t budget = (config::max_dimension << config::subpixel_bits) - 1;
  if (r->map.x((blob.width - 1) << config::subpixel_bits) > budget ||
      r->map.y((blob.height - 1) << config::subpixel_bits) > budget)
    return Status::bad_params;
  r->view = Rect{r->view.x0 + r->shift_x, r->view.y0 + r->shift_y, r->view.x1 + r->shift_x, r->view.y1 + r->shift_y};
  return Status::ok;
}

}  // namespace
}  // namespace tristream::core::detail
