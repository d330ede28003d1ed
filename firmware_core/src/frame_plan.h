/* SPDX-License-Identifier: MIT */
#pragma once
// What a render call resolves from its parameters before drawing: output size, viewport, tile
// size, pixel format and the position mapping, with the checks that reject bad parameters.
#include <stdint.h>

#include "output_mapping.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#include "tristream/render.h"

namespace tristream::core::detail {
namespace {

struct FramePlan {
  int32_t out_w = 0, out_h = 0;
  Rect view;
  int32_t tile_w = 0, tile_h = 0;
  PixelFormat format = PixelFormat::rgb888;
  Mapping map;
};

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
  if (!(config::pixel_formats >> int(p.format) & 1) || !(config::methods >> int(blob.method) & 1))
    return Status::not_compiled;
  r->format = p.format;
  r->map.identity = r->out_w == blob.width && r->out_h == blob.height;
  r->map.nx = uint32_t(r->out_w - 1);
  r->map.dx = uint32_t(blob.width - 1);
  r->map.ny = uint32_t(r->out_h - 1);
  r->map.dy = uint32_t(blob.height - 1);
  return Status::ok;
}

}  // namespace
}  // namespace tristream::core::detail
