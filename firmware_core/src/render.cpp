// SPDX-License-Identifier: MIT
// The public render calls. The private headers beside this file (one concept each) are included by
// this translation unit only, and their internals have internal linkage (an unnamed namespace
// inside detail): GCC then inlines the per-pixel code as it did when it was one file (with external
// linkage it inlined less: +6 % instructions per pixel at 40,000 triangles).
#include "tristream/render.h"

#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "band_tiles.h"
#include "frame_plan.h"
#include "tile_renderer.h"
#include "workspace_layout.h"

namespace tristream::core {

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
  *bytes = detail::workspace_alignment + detail::scratch_bytes(blob, r, r.format) +
           size_t(blob.layer_count) * detail::bitmap_bytes(longest);
  return Status::ok;
}

Status render(const Blob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context) {
  if (!detail::buffers_given(params, buffers, sink)) return Status::null_argument;
  detail::FramePlan r;
  Status s = detail::plan_frame(blob, params, &r);
  if (s != Status::ok) return s;
  if (!detail::tile_buffers_hold(params, r, buffers)) return Status::tile_buffer_too_small;

  // Workspace: [alignment padding][channel scratch][active-set bitmaps, one equal share per layer].
  const size_t workspace_bytes = buffers.workspace_bytes;
  uint8_t* ws = static_cast<uint8_t*>(buffers.workspace);
  const size_t pad = ws ? (detail::workspace_alignment - uintptr_t(ws) % detail::workspace_alignment) %
                              detail::workspace_alignment
                        : 0;
  const size_t scratch = detail::scratch_bytes(blob, r, r.format);
  if (workspace_bytes < pad + scratch) return Status::workspace_too_small;
  int16_t* scratch_ptr = scratch ? reinterpret_cast<int16_t*>(ws + pad) : nullptr;
  const size_t set_bytes = (workspace_bytes - pad - scratch) / blob.layer_count / 4 * 4;
  detail::ActiveSet sets[detail::max_layers];
  for (int l = 0; l < blob.layer_count; ++l) {
    sets[l].layer = &blob.layers[l];
    sets[l].words = reinterpret_cast<uint32_t*>(ws + pad + scratch + size_t(l) * set_bytes);
    sets[l].capacity = uint32_t(set_bytes * 8 > 0xFFFFFFE0u ? 0xFFFFFFE0u : set_bytes * 8);
    if (sets[l].capacity) sets[l].reset();
  }
  // Every buffer is checked before the first tile goes to the sink (no partial frame): a bitmap
  // of all its triangles always holds a layer's window, else the window is measured.
  for (int l = 0; l < blob.layer_count; ++l)
    if (sets[l].capacity < blob.layers[l].triangle_count &&
        detail::max_window(blob.layers[l], r, sets[l].capacity) > sets[l].capacity)
      return Status::workspace_too_small;
  const detail::TileRenderer draw = detail::tile_renderer<detail::BlobRecords>(r.format);
  detail::TileBuffers tiles(buffers);
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t by1 = by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1;
    for (int l = 0; l < blob.layer_count; ++l)
      if (!sets[l].advance(r.map, by, by1 - 1)) return Status::workspace_too_small;  // excluded above
    s = detail::draw_band(draw, blob, params, r, sets, by, by1, scratch_ptr, &tiles, sink, context);
    if (s != Status::ok) return s;
  }
  return Status::ok;
}


Status render(const Blob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context) {
  detail::TileSinkAdapter adapter{sink, context};
  return render(blob, params, detail::single_buffers(tile_buffer, tile_buffer_bytes, workspace, workspace_bytes),
                sink ? detail::forward_tile : nullptr, &adapter);
}

}  // namespace tristream::core
