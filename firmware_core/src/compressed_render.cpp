// SPDX-License-Identifier: MIT
// The render of a compressed blob from its streams, band by band (render.h): per band and layer,
// the band store keeps the triangles carried over whose last row reaches the band, then takes
// those the layer's decoder yields whose top row is at most the band's last row; the first one
// past the band waits in the layer's stream state for the next band. The band stores are read
// through a Blob whose layers point into them, by the same tile path as a v1 blob (this
// translation unit has its own copy of the private headers' internal-linkage code, as render.cpp).
#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "band_store.h"
#include "band_tiles.h"
#include "frame_plan.h"
#include "tile_renderer.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"
#include "workspace_layout.h"

namespace tristream::core {
namespace {

// A layer's decoding state, in the workspace (its ring and its decoder's tags follow it).
// A trivial type, like LayerDecoder: 8-aligned workspace bytes are taken as one and its fields
// set by render, with no construction.
struct LayerStream {
  LayerDecoder decoder;
  DecodedTriangle held;  // decoded and not yet taken (its top row is past the last band's)
  uint32_t remaining;    // triangles not decoded yet
  bool has_held;
};
static_assert(alignof(LayerStream) <= 8, "the workspace sections are 8-aligned");
static_assert(__is_trivial(LayerDecoder) && __is_trivial(LayerStream),
              "the decoding state lives in caller memory without construction");

constexpr size_t align8(size_t n) { return (n + 7) / 8 * 8; }

size_t stream_bytes(const CompressedBlob& blob, int l) {
  return align8(sizeof(LayerStream)) + align8(compressed_ring_bytes(blob, l)) + align8(compressed_tag_bytes(blob, l));
}

// 8 - address mod 8 bytes (1 to 8) start every workspace: exact sizes for an 8-aligned one.
size_t pad_of(const void* p) { return 8 - uintptr_t(p) % 8; }

// The header fields of the compressed blob, no layers yet: what plan_frame and the tile path read.
Blob header_view(const CompressedBlob& c) {
  Blob b;
  b.bytes = c.bytes;
  b.size = c.size;
  b.width = c.width;
  b.height = c.height;
  b.space = c.space;
  b.method = c.method;
  b.layer_count = c.layer_count;
  b.values_per_vertex = c.values_per_vertex;
  return b;
}

uint32_t band_count(const detail::FramePlan& r) {
  return uint32_t((r.view.height() + r.tile_h - 1) / r.tile_h);
}

// Takes the layer to band [y0, y1]: drops what ended above y0, appends what starts by y1.
Status advance(LayerStream& s, detail::BandStore& store, const detail::Mapping& map, int32_t y0, int32_t y1) {
  store.begin_band(map, y0);
  for (;;) {
    if (!s.has_held) {
      if (s.remaining == 0) return Status::ok;
      const Status st = s.decoder.next(&s.held);
      if (st != Status::ok) return st;
      --s.remaining;
      s.has_held = true;
    }
    int32_t top, bottom;
    detail::decoded_row_extent(map, s.held, &top, &bottom);
    if (top > y1) return Status::ok;
    s.has_held = false;
    if (bottom < y0 || top > bottom) continue;  // above the viewport, or no row's sample points
    const Status st = store.append(s.held);
    if (st != Status::ok) return st;
  }
}

}  // namespace

Status tile_buffer_size(const CompressedBlob& blob, const RenderParams& params, size_t* bytes) {
  return tile_buffer_size(header_view(blob), params, bytes);
}

Status measure_scratch_size(const CompressedBlob& blob, const RenderParams& params, size_t* bytes) {
  if (!bytes) return Status::null_argument;
  detail::FramePlan r;
  const Status s = detail::plan_frame(header_view(blob), params, &r);
  if (s != Status::ok) return s;
  uint32_t most_vertices = 0;
  for (int l = 0; l < blob.layer_count; ++l)
    most_vertices = blob.layers[l].vertex_count > most_vertices ? blob.layers[l].vertex_count : most_vertices;
  *bytes = 8 + align8(sizeof(LayerDecoder)) + align8(expand_workspace_size(blob)) + 12 * (size_t(band_count(r)) + 1) +
           2 * size_t(most_vertices);
  return Status::ok;
}

Status workspace_size(const CompressedBlob& blob, const RenderParams& params, void* scratch, size_t scratch_bytes,
                      size_t* bytes, BlobError* error) {
  if (!bytes) return Status::null_argument;
  CompressedWorkspace figures;
  const Status s = workspace_size(blob, params, scratch, scratch_bytes, &figures, error);
  if (s == Status::ok) *bytes = figures.bytes;
  return s;
}

Status workspace_size(const CompressedBlob& blob, const RenderParams& params, void* scratch, size_t scratch_bytes,
                      CompressedWorkspace* figures, BlobError* error) {
  if (!figures || !scratch) return Status::null_argument;
  const Blob view = header_view(blob);
  detail::FramePlan r;
  Status s = detail::plan_frame(view, params, &r);
  if (s != Status::ok) return s;
  size_t need = 0;
  s = measure_scratch_size(blob, params, &need);
  if (s != Status::ok) return s;
  if (scratch_bytes < need) return Status::workspace_too_small;
  uint8_t* at = static_cast<uint8_t*>(scratch) + pad_of(scratch);
  LayerDecoder* decoder = reinterpret_cast<LayerDecoder*>(at);  // set by begin
  uint8_t* ring = at + align8(sizeof(LayerDecoder));
  const size_t ring_bytes = align8(expand_workspace_size(blob));
  const uint32_t bands = band_count(r);
  uint32_t* live = reinterpret_cast<uint32_t*>(ring + ring_bytes);  // per band: live triangles' difference
  uint32_t* live_flagged = live + (bands + 1);                      // live triangles with flags'
  uint32_t* live_vertices = live_flagged + (bands + 1);             // and live vertices'
  // Per stream index: the last band of a triangle using it, or 0xFFFF before the first (bands <=
  // 65,535: the output height is a u16).
  uint16_t* last_band = reinterpret_cast<uint16_t*>(live_vertices + (bands + 1));
  const bool gradients = blob.method == Method::zienkiewicz;
  uint32_t most = 0, most_vertices = 0;
  size_t store = 0, fixed = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    fixed += stream_bytes(blob, l);
    const uint32_t vertex_count = blob.layers[l].vertex_count;
    for (uint32_t b = 0; b <= bands; ++b) live[b] = live_flagged[b] = live_vertices[b] = 0;
    for (uint32_t v = 0; v < vertex_count; ++v) last_band[v] = 0xFFFF;
    s = decoder->begin(blob, l, ring, ring_bytes);
    if (s != Status::ok) return s;
    DecodedTriangle t;
    for (uint32_t k = 0; k < blob.layers[l].triangle_count; ++k) {
      s = decoder->next(&t);
      if (s != Status::ok) {
        if (error) error->offset = decoder->offset();
        return s;
      }
      // Live in the bands from the one holding its top row (the first if above the viewport) to
      // the one holding its last row, as advance() keeps it.
      int32_t top, bottom;
      detail::decoded_row_extent(r.map, t, &top, &bottom);
      if (top > bottom || bottom < r.view.y0 || top >= r.view.y1) continue;
      const int32_t last = bottom < r.view.y1 ? bottom : r.view.y1 - 1;
      const uint32_t b0 = top <= r.view.y0 ? 0 : uint32_t((top - r.view.y0) / r.tile_h);
      const uint32_t b1 = uint32_t((last - r.view.y0) / r.tile_h);
      ++live[b0];
      --live[b1 + 1];
      if (t.flags) {
        ++live_flagged[b0];
        --live_flagged[b1 + 1];
      }
      // A vertex is stored from the band of its first live triangle (the one with the least top
      // row: the stream is in top-row order) to the last band of any of them, and in every band
      // between: each of its triangles has the row floor(y) or floor(y) + 1 of the vertex, so
      // their bands overlap or touch.
      for (int k = 0; k < 3; ++k) {
        if (t.v[k] >= vertex_count) return Status::bad_index;  // never from a decoder
        uint16_t& last_of = last_band[t.v[k]];
        if (last_of == 0xFFFF) {
          ++live_vertices[b0];
          last_of = uint16_t(b1);
        } else if (b1 > last_of) {
          last_of = uint16_t(b1);
        }
      }
    }
    s = decoder->finish();
    if (s != Status::ok) {
      if (error) error->offset = decoder->offset();
      return s;
    }
    for (uint32_t v = 0; v < vertex_count; ++v)
      if (last_band[v] != 0xFFFF) --live_vertices[last_band[v] + 1];
    uint32_t n = 0, nf = 0, nv = 0;
    for (uint32_t b = 0; b < bands; ++b) {
      n += live[b];
      nf += live_flagged[b];
      nv += live_vertices[b];
      most = n > most ? n : most;
      most_vertices = nv > most_vertices ? nv : most_vertices;
      const size_t need = detail::band_store_bytes(nv, n, nf, blob.values_per_vertex, gradients);
      store = need > store ? need : store;
    }
  }
  figures->channel_scratch = detail::scratch_bytes(view, r, r.format);
  figures->decoders = fixed;
  figures->live_triangles = most;
  figures->live_vertices = most_vertices;
  figures->band_store = store;
  figures->bytes = 8 + figures->channel_scratch + fixed + size_t(blob.layer_count) * figures->band_store;
  return Status::ok;
}

Status render(const CompressedBlob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context, BlobError* error) {
  if (!detail::buffers_given(params, buffers, sink)) return Status::null_argument;
  Blob view = header_view(blob);
  detail::FramePlan r;
  Status s = detail::plan_frame(view, params, &r);
  if (s != Status::ok) return s;
  if (!detail::tile_buffers_hold(params, r, buffers)) return Status::tile_buffer_too_small;

  // Workspace: [1..8 bytes to 8-align][channel scratch][per layer: stream state, ring, tags][band
  // stores, one equal share per layer].
  uint8_t* const ws = static_cast<uint8_t*>(buffers.workspace);
  if (!ws) return Status::workspace_too_small;
  const size_t scratch = detail::scratch_bytes(view, r, r.format);
  size_t fixed = pad_of(ws) + scratch;
  for (int l = 0; l < blob.layer_count; ++l) fixed += stream_bytes(blob, l);
  if (buffers.workspace_bytes < fixed) return Status::workspace_too_small;
  int16_t* scratch_ptr = scratch ? reinterpret_cast<int16_t*>(ws + pad_of(ws)) : nullptr;
  const bool gradients = blob.method == Method::zienkiewicz;
  const size_t share = (buffers.workspace_bytes - fixed) / blob.layer_count / 4 * 4;
  LayerStream* streams[detail::max_layers] = {};
  uint16_t* tags[detail::max_layers] = {};
  detail::BandStore stores[detail::max_layers];
  detail::ActiveSet sets[detail::max_layers];
  uint8_t* at = ws + pad_of(ws) + scratch;
  for (int l = 0; l < blob.layer_count; ++l) {
    streams[l] = reinterpret_cast<LayerStream*>(at);
    uint8_t* ring = at + align8(sizeof(LayerStream));
    const size_t ring_bytes = align8(compressed_ring_bytes(blob, l));
    s = streams[l]->decoder.begin(blob, l, ring, ring_bytes);
    if (s != Status::ok) return s;
    tags[l] = reinterpret_cast<uint16_t*>(ring + ring_bytes);
    streams[l]->decoder.keep_tags(tags[l]);
    streams[l]->remaining = blob.layers[l].triangle_count;
    streams[l]->has_held = false;
    at = ring + ring_bytes + align8(compressed_tag_bytes(blob, l));
  }
  for (int l = 0; l < blob.layer_count; ++l) {
    stores[l].init(at + size_t(l) * share, share, blob.values_per_vertex, gradients, &view.layers[l], tags[l],
                   uint32_t(compressed_tag_bytes(blob, l) / 2));
    sets[l].layer = &view.layers[l];
  }
  const detail::TileRenderer draw = detail::tile_renderer<detail::BandStoreRecords>(r.format);
  detail::TileBuffers tiles(buffers);
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t by1 = by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1;
    for (int l = 0; l < blob.layer_count; ++l) {
      s = advance(*streams[l], stores[l], r.map, by, by1 - 1);
      if (s != Status::ok) {
        if (error && s != Status::workspace_too_small) error->offset = streams[l]->decoder.offset();
        return s;
      }
      // The bitmap's place and size follow the store's triangles, band by band.
      sets[l].words = stores[l].mark_all_live();
      if (!sets[l].words) return Status::workspace_too_small;
      sets[l].capacity = uint32_t(detail::bitmap_bytes(stores[l].count()) * 8);
      sets[l].base = 0;
      sets[l].cursor = stores[l].count();
    }
    s = detail::draw_band(draw, view, params, r, sets, by, by1, scratch_ptr, &tiles, sink, context);
    if (s != Status::ok) return s;
  }
  return Status::ok;
}

Status render(const CompressedBlob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context) {
  detail::TileSinkAdapter adapter{sink, context};
  return render(blob, params, detail::single_buffers(tile_buffer, tile_buffer_bytes, workspace, workspace_bytes),
                sink ? detail::forward_tile : nullptr, &adapter);
}

}  // namespace tristream::core
