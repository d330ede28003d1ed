/* SPDX-License-Identifier: MIT */
#pragma once
// Handing the frame to the caller: the tiles of one band, left to right, each drawn into the next
// tile buffer and given to the sink; and the adapter that lets a TileSink (no return value) take
// a FrameSink's place. Shared by the render of a v1 blob (render.cpp) and of a compressed one
// (compressed_render.cpp).
#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "frame_plan.h"
#include "tile_renderer.h"
#include "tristream/blob.h"
#include "tristream/render_params.h"
#include "tristream/tile.h"

namespace tristream::core::detail {
namespace {

// The caller's tile buffers: with a second one the tiles alternate (first, second, first, ...).
struct TileBuffers {
  uint8_t* base[2];
  int next = 0;

  explicit TileBuffers(const RenderBuffers& b)
      : base{static_cast<uint8_t*>(b.tile[0]), static_cast<uint8_t*>(b.tile[1] ? b.tile[1] : b.tile[0])} {}
};

// The tiles of the band of rows [by, by1) (drawing positions) from the layers' active sets, each
// in the next tile buffer or, with a target, in place: Status::stopped when the sink says so (no
// sink: only with a target).
inline Status draw_band(TileRenderer draw, const Blob& blob, const RenderParams& params, const FramePlan& r,
                        ActiveSet* sets, int32_t by, int32_t by1, int16_t* scratch, TileBuffers* buffers,
                        FrameSink sink, void* context) {
  const int bpp = bytes_per_pixel(r.format);
  const bool cull_columns = r.tile_w < r.view.width();
  for (int32_t bx = r.view.x0; bx < r.view.x1; bx += r.tile_w) {
    const int32_t bx1 = bx + r.tile_w < r.view.x1 ? bx + r.tile_w : r.view.x1;
    Tile tile;
    if (params.target) {
      // In place: the tile's corner in the target (plan_frame checked the stride).
      tile.pixels =
          static_cast<uint8_t*>(params.target) + ptrdiff_t(by - r.view.y0) * r.target_stride + (bx - r.view.x0) * bpp;
      tile.stride = r.target_stride;
    } else {
      tile.pixels = buffers->base[buffers->next];
      tile.stride = (params.packed_tiles ? bx1 - bx : r.tile_w) * bpp;
    }
    tile.rect = Rect{bx, by, bx1, by1};
    tile.format = r.format;
    draw(blob, params, r.map, sets, tile.rect, cull_columns, tile.pixels, tile.stride, scratch);
    // The sink gets output positions (the drawing positions less the frame's shift).
    tile.rect = Rect{bx - r.shift_x, by - r.shift_y, bx1 - r.shift_x, by1 - r.shift_y};
    if (sink && !sink(context, &tile)) return Status::stopped;
    buffers->next ^= 1;
  }
  return Status::ok;
}

// A TileSink as a FrameSink that always goes on.
struct TileSinkAdapter {
  TileSink sink;
  void* context;
};

inline bool forward_tile(void* context, const Tile* tile) {
  const TileSinkAdapter* a = static_cast<const TileSinkAdapter*>(context);
  a->sink(a->context, tile);
  return true;
}

// The checks of a render call's buffers and sink before its parameters': a sink and a tile buffer
// unless there is a target, and a workspace unless it has 0 bytes.
inline bool buffers_given(const RenderParams& params, const RenderBuffers& b, FrameSink sink) {
  return (params.target || (b.tile[0] && sink)) && (b.workspace || !b.workspace_bytes);
}

// Whether the tile buffers hold a tile (none needed with a target).
inline bool tile_buffers_hold(const RenderParams& params, const FramePlan& r, const RenderBuffers& b) {
  return params.target || b.tile_bytes >= size_t(r.tile_w) * r.tile_h * bytes_per_pixel(r.format);
}

// The buffers of a render call with one tile buffer.
inline RenderBuffers single_buffers(void* tile_buffer, size_t tile_buffer_bytes, void* workspace,
                                    size_t workspace_bytes) {
  RenderBuffers buffers;
  buffers.tile[0] = tile_buffer;
  buffers.tile_bytes = tile_buffer_bytes;
  buffers.workspace = workspace;
  buffers.workspace_bytes = workspace_bytes;
  return buffers;
}

}  // namespace
}  // namespace tristream::core::detail
