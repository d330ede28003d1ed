/* SPDX-License-Identifier: MIT */
#pragma once
// The one band loop of a render: a layer source (v1 records or a compressed blob's decoded
// streams) brings each layer's active set to the next band, and the band's tiles are drawn from
// those sets and handed to the sink. A template over the source, so that a v1 render calls no
// function through a pointer per band or triangle to reach its records.
//
// A layer source is a class with:
//   using Records = ...;  // the record layout the tile path reads (triangle_records.h)
//   const Blob& view() const;
//     The blob the frame plan and the tile path read: its header fields, and layers whose records
//     are where the active sets point (the blob itself, or layers the source fills band by band).
//   Status carve(const FramePlan& r, WorkspaceCarver* ws, ActiveSet* sets);
//     Takes the source's sections of the workspace after the channel scratch (its fixed sections,
//     then one equal share per layer), sets up sets[0 .. layer_count), and checks what it can
//     before the first tile (a failure then leaves the sink untouched).
//   Status advance(const Mapping& map, int32_t y0, int32_t y1, ActiveSet* sets);
//     Brings every layer's active set to the band of rows [y0, y1] (drawing positions).
// render_frame calls carve once, then advance once per band, top to bottom.
#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "band_tiles.h"
#include "frame_plan.h"
#include "tile_renderer.h"
#include "tristream/render_params.h"
#include "tristream/status.h"
#include "workspace_layout.h"

namespace tristream::core::detail {
namespace {

// The frame of a render call: its checks, the workspace's channel scratch and the source's
// sections, then the bands top to bottom, each band's tiles left to right. Inlined into the
// public call, so that the source object and its layer state are that call's locals (no frame
// between the call and the band loop, which the stack bound counts).
template <typename Source>
__attribute__((always_inline)) inline Status render_frame(Source& source, const RenderParams& params,
                                                          const RenderBuffers& buffers, FrameSink sink, void* context) {
  if (!buffers_given(params, buffers, sink)) return Status::null_argument;
  const Blob& view = source.view();
  FramePlan r;
  Status s = plan_frame(view, params, &r);
  if (s != Status::ok) return s;
  if (!tile_buffers_hold(params, r, buffers)) return Status::tile_buffer_too_small;
  ActiveSet sets[max_layers];
  int16_t* scratch;
  {  // the carver's scope ends before the band loop, which may then reuse its stack
    WorkspaceCarver ws(buffers.workspace, buffers.workspace_bytes);
    // The channel scratch (0 bytes unless layered: the tile path reads it only then).
    scratch = reinterpret_cast<int16_t*>(ws.take(scratch_bytes(view, r, r.format)));
    if (!ws.fits()) return Status::workspace_too_small;
    s = source.carve(r, &ws, sets);
    if (s != Status::ok) return s;
  }
  const TileRenderer draw = tile_renderer<typename Source::Records>(r.format);
  TileBuffers tiles(buffers);
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t by1 = by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1;
    s = source.advance(r.map, by, by1 - 1, sets);
    if (s != Status::ok) return s;
    s = draw_band(draw, view, params, r, sets, by, by1, scratch, &tiles, sink, context);
    if (s != Status::ok) return s;
  }
  return Status::ok;
}

}  // namespace
}  // namespace tristream::core::detail
