// SPDX-License-Identifier: MIT
// The render calls of a v1 blob: its layers' records are the layer source of the band loop
// (render_driver.h). The private headers beside this file are included by the render translation
// units only, and their internals have internal linkage (an unnamed namespace inside detail), so
// that GCC inlines the per-pixel code into each render call.
#include "tristream/render.h"

#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "band_tiles.h"
#include "frame_plan.h"
#include "render_driver.h"
#include "triangle_records.h"
#include "workspace_layout.h"

namespace tristream::core {
namespace {

// The layer source of a v1 blob: each layer's active set is a bitmap over its own records, one
// equal share of the workspace per layer.
class BlobLayers {
 public:
  using Records = detail::BlobRecords;

  explicit BlobLayers(const Blob& blob) : blob_(blob) {}
  const Blob& view() const { return blob_; }

  Status carve(const detail::FramePlan& r, detail::WorkspaceCarver* ws, detail::ActiveSet* sets) {
    const size_t set_bytes = ws->share(blob_.layer_count);
    for (int l = 0; l < blob_.layer_count; ++l) {
      sets[l].layer = &blob_.layers[l];
      sets[l].words = reinterpret_cast<uint32_t*>(ws->take(set_bytes));
      sets[l].capacity = uint32_t(set_bytes * 8 > 0xFFFFFFE0u ? 0xFFFFFFE0u : set_bytes * 8);
      if (sets[l].capacity) sets[l].reset();
    }
    // Every buffer is checked before the first tile goes to the sink (no partial frame): a bitmap
    // of all its triangles always holds a layer's window, else the window is measured.
    for (int l = 0; l < blob_.layer_count; ++l)
      if (sets[l].capacity < blob_.layers[l].triangle_count &&
          detail::max_window(blob_.layers[l], r, sets[l].capacity) > sets[l].capacity)
        return Status::workspace_too_small;
    return Status::ok;
  }

  Status advance(const detail::Mapping& map, int32_t y0, int32_t y1, detail::ActiveSet* sets) {
    bool fits = true;  // every layer's window fits (carve checked it)
    for (int l = 0; l < blob_.layer_count; ++l) fits &= sets[l].advance(map, y0, y1);
    return fits ? Status::ok : Status::workspace_too_small;
  }

 private:
  const Blob& blob_;
};

}  // namespace


Status tile_buffer_size(const Blob& blob, const RenderParams& params, size_t* bytes) {
  if (!bytes) return Status::null_argument;
  detail::FramePlan r;
  Status s = detail::plan_frame(blob, params, &r);
  if (s != Status::ok) return s;
  *bytes = params.target ? 0 : size_t(r.tile_w) * r.tile_h * bytes_per_pixel(r.format);
  return Status::ok;
}

Status workspace_size(const Blob& blob, const RenderParams& params, size_t* bytes) {
  if (!bytes) return Status::null_argument;
  detail::FramePlan r;
  Status s = detail::plan_frame(blob, params, &r);
  if (s != Status::ok) return s;
  uint32_t longest = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    const uint32_t n = detail::max_window(blob.layers[l], r);
    longest = n > longest ? n : longest;
  }
  // The layout BlobLayers::carve takes: the channel scratch, then a bitmap of the longest window
  // for every layer.
  detail::WorkspaceCarver ws;
  ws.take(detail::scratch_bytes(blob, r, r.format));
  for (int l = 0; l < blob.layer_count; ++l) ws.take(detail::bitmap_bytes(longest));
  *bytes = ws.used();
  return Status::ok;
}

Status render(const Blob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context) {
  BlobLayers layers(blob);
  return detail::render_frame(layers, params, buffers, sink, context);
}

Status render(const Blob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context) {
  detail::TileSinkAdapter adapter{sink, context};
  return render(blob, params, detail::single_buffers(tile_buffer, tile_buffer_bytes, workspace, workspace_bytes),
                sink ? detail::forward_tile : nullptr, &adapter);
}

}  // namespace tristream::core
