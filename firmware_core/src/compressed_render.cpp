// SPDX-License-Identifier: MIT
// The render calls of a compressed blob: its layers' decoded streams are the layer source of the
// band loop (render_driver.h). Per band and layer, the band store keeps the triangles carried over
// whose last row reaches the band, then takes those the layer's decoder yields whose top row is at
// most the band's last row; the first one past the band waits in the layer's stream state for the
// next band. The band stores are read through a Blob whose layers point into them, by the same
// tile path as a v1 blob (this translation unit has its own copy of the private headers'
// internal-linkage code, as render.cpp).
#include <stddef.h>
#include <stdint.h>

#include "active_set.h"
#include "band_store.h"
#include "band_tiles.h"
#include "frame_plan.h"
#include "render_driver.h"
#include "triangle_records.h"
#include "tuning.h"
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
  bool failed;           // its decoder stopped the frame (decoder.offset() is where)
};
static_assert(alignof(LayerStream) <= 8, "the workspace sections are 8-aligned");
static_assert(__is_trivial(LayerDecoder) && __is_trivial(LayerStream),
              "the decoding state lives in caller memory without construction");

constexpr size_t align8(size_t n) { return (n + 7) / 8 * 8; }

// Takes a layer's fixed sections of the workspace, in this order: its stream state (returned),
// its decoder's ring (stream_ring) and its tags (*tags). Nothing is set: the addresses are the
// carver's.
LayerStream* take_stream_sections(const CompressedBlob& blob, int l, detail::WorkspaceCarver* ws, uint16_t** tags) {
  LayerStream* const stream = reinterpret_cast<LayerStream*>(ws->take(align8(sizeof(LayerStream))));
  ws->take(align8(compressed_ring_bytes(blob, l)));
  *tags = reinterpret_cast<uint16_t*>(ws->take(align8(compressed_tag_bytes(blob, l))));
  return stream;
}
uint8_t* stream_ring(LayerStream* s) { return reinterpret_cast<uint8_t*>(s) + align8(sizeof(LayerStream)); }

// The header fields of the compressed blob, no layers yet: what plan_frame and the tile path read.
Blob header_view(const CompressedBlob& c) {
  Blob b;
  static_cast<BlobInfo&>(b) = c;
  return b;
}

uint32_t band_count(const detail::FramePlan& r) {
  return uint32_t((r.view.height() + r.tile_h - 1) / r.tile_h);
}

// Takes the layer to band [y0, y1]: drops what ended above y0, appends what starts by y1.
Status advance_layer(LayerStream& s, detail::BandStore& store, const detail::Mapping& map, int32_t y0, int32_t y1) {
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

// The layer source of a compressed blob: per layer a decoder in the workspace feeds a band store
// (one equal share of the workspace per layer) that holds the band's live triangles as a small
// v1-shaped layer of view(); a layer's active set is all of its store.
class StreamLayers {
 public:
  using Records = detail::BandStoreRecords;

  explicit StreamLayers(const CompressedBlob& blob) : blob_(blob), view_(header_view(blob)) {}
  const Blob& view() const { return view_; }

  Status carve(const detail::FramePlan&, detail::WorkspaceCarver* ws, detail::ActiveSet* sets) {
    uint16_t* tags[detail::max_layers];
    for (int l = 0; l < blob_.layer_count; ++l) streams_[l] = take_stream_sections(blob_, l, ws, &tags[l]);
    // Every layer's fixed sections fit before any decoder begins.
    if (!ws->fits()) return Status::workspace_too_small;
    for (int l = 0; l < blob_.layer_count; ++l) streams_[l]->failed = false;
    for (int l = 0; l < blob_.layer_count; ++l) {
      LayerStream* const at = streams_[l];
      const Status s = at->decoder.begin(blob_, l, stream_ring(at), align8(compressed_ring_bytes(blob_, l)));
      if (s != Status::ok) return s;
      at->decoder.keep_tags(tags[l]);
      at->remaining = blob_.layers[l].triangle_count;
      at->has_held = false;
    }
    const bool gradients = blob_.method == Method::zienkiewicz;
    const size_t share = ws->share(blob_.layer_count);
    for (int l = 0; l < blob_.layer_count; ++l) {
      stores_[l].init(ws->take(share), share, blob_.values_per_vertex, gradients, &view_.layers[l], tags[l],
                      uint32_t(compressed_tag_bytes(blob_, l) / 2));
      sets[l].layer = &view_.layers[l];
    }
    return Status::ok;
  }

  TS_BAND_ADVANCE Status advance(const detail::Mapping& map, int32_t y0, int32_t y1, detail::ActiveSet* sets) {
    for (int l = 0; l < blob_.layer_count; ++l) {
      const Status s = advance_layer(*streams_[l], stores_[l], map, y0, y1);
      if (s != Status::ok) {
        streams_[l]->failed = s != Status::workspace_too_small;
        return s;
      }
      // The bitmap's place and size follow the store's triangles, band by band.
      sets[l].words = stores_[l].mark_all_live();
      if (!sets[l].words) return Status::workspace_too_small;
      sets[l].capacity = uint32_t(detail::bitmap_bytes(stores_[l].count()) * 8);
      sets[l].base = 0;
      sets[l].cursor = stores_[l].count();
    }
    return Status::ok;
  }

  // After a frame that a stream stopped (a status other than ok, stopped or workspace_too_small
  // from advance): the failing decoder's byte offset in the blob. Kept in the stream state, not
  // here, so that the error pointer takes no room in the render's frame.
  void report(BlobError* error) const {
    for (int l = 0; l < detail::max_layers && l < blob_.layer_count; ++l)
      if (streams_[l] && streams_[l]->failed) error->offset = streams_[l]->decoder.offset();
  }

 private:
  const CompressedBlob& blob_;
  Blob view_;
  LayerStream* streams_[detail::max_layers] = {};
  detail::BandStore stores_[detail::max_layers];
};

// The sections of workspace_size's scratch, in this order (null when measuring): a decoder, its
// ring for the largest layer, per band + 1 the live triangles' difference, those with flags' and
// the live vertices', then per stream index the last band of a triangle using it.
struct MeasureSections {
  LayerDecoder* decoder;
  uint8_t* ring;
  size_t ring_bytes;
  uint32_t* live;
  uint32_t* live_flagged;
  uint32_t* live_vertices;
  uint16_t* last_band;
};

MeasureSections take_measure_sections(const CompressedBlob& blob, uint32_t bands, detail::WorkspaceCarver* ws) {
  uint32_t most_vertices = 0;
  for (int l = 0; l < blob.layer_count; ++l)
    most_vertices = blob.layers[l].vertex_count > most_vertices ? blob.layers[l].vertex_count : most_vertices;
  MeasureSections m;
  m.decoder = reinterpret_cast<LayerDecoder*>(ws->take(align8(sizeof(LayerDecoder))));
  m.ring_bytes = align8(expand_workspace_size(blob));
  m.ring = ws->take(m.ring_bytes);
  m.live = reinterpret_cast<uint32_t*>(ws->take(4 * (size_t(bands) + 1)));
  m.live_flagged = reinterpret_cast<uint32_t*>(ws->take(4 * (size_t(bands) + 1)));
  m.live_vertices = reinterpret_cast<uint32_t*>(ws->take(4 * (size_t(bands) + 1)));
  m.last_band = reinterpret_cast<uint16_t*>(ws->take(2 * size_t(most_vertices)));
  return m;
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
  detail::WorkspaceCarver m;
  take_measure_sections(blob, band_count(r), &m);
  *bytes = m.used();
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
  const uint32_t bands = band_count(r);
  // The padding rule of a render's workspace: measure_scratch_size is exact for an 8-aligned
  // scratch and enough for any other.
  detail::WorkspaceCarver carver(scratch, scratch_bytes);
  const MeasureSections m = take_measure_sections(blob, bands, &carver);
  if (!carver.fits()) return Status::workspace_too_small;
  LayerDecoder* const decoder = m.decoder;  // set by begin
  uint8_t* const ring = m.ring;
  const size_t ring_bytes = m.ring_bytes;
  uint32_t* const live = m.live;
  uint32_t* const live_flagged = m.live_flagged;
  uint32_t* const live_vertices = m.live_vertices;
  // Per stream index: the last band of a triangle using it, or 0xFFFF before the first (bands <=
  // 65,535: the output height is a u16).
  uint16_t* const last_band = m.last_band;
  const bool gradients = blob.method == Method::zienkiewicz;
  uint32_t most = 0, most_vertices = 0;
  size_t store = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
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
  // The layout StreamLayers::carve takes after the channel scratch: every layer's fixed sections,
  // then a band store of the largest need for every layer.
  detail::WorkspaceCarver ws;
  figures->channel_scratch = detail::scratch_bytes(view, r, r.format);
  ws.take(figures->channel_scratch);
  const size_t before_streams = ws.used();
  uint16_t* tags;
  for (int l = 0; l < blob.layer_count; ++l) take_stream_sections(blob, l, &ws, &tags);
  figures->decoders = ws.used() - before_streams;
  for (int l = 0; l < blob.layer_count; ++l) ws.take(store);
  figures->live_triangles = most;
  figures->live_vertices = most_vertices;
  figures->band_store = store;
  figures->bytes = ws.used();
  return Status::ok;
}

Status render(const CompressedBlob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context, BlobError* error) {
  StreamLayers layers(blob);
  const Status s = detail::render_frame(layers, params, buffers, sink, context);
  if (error && s != Status::ok && s != Status::stopped && s != Status::workspace_too_small) layers.report(error);
  return s;
}

Status render(const CompressedBlob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context) {
  detail::TileSinkAdapter adapter{sink, context};
  return render(blob, params, detail::single_buffers(tile_buffer, tile_buffer_bytes, workspace, workspace_bytes),
                sink ? detail::forward_tile : nullptr, &adapter);
}

}  // namespace tristream::core
