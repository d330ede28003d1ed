/* SPDX-License-Identifier: MIT */
#pragma once
// The compressed blob ("TSTC", docs/COMPRESSED_BLOB.md): the same meshes as a v1 blob (blob.h),
// each layer one stream of an adaptive binary range coder, decoded sequentially in the order the
// core consumes the mesh (triangles by top row). Layout (little-endian, offsets from byte 0):
//
//   header, 64 bytes
//     0  char[4] magic "TSTC"        4  u16 version (3)         6  u16 header size (64)
//     8  u32 total size             12  u16 width  14 u16 height
//    16  u8 colour space   17 u8 method   18 u8 layer count   19 u8 values per vertex
//    20  u8 sub-pixel bits   21 u8 gradient fraction bits   22 u16 flags (0)
//    24  u32 config hash (blob_config_hash())   28 u32 layer table offset (64)
//    32  u32 max triangle height in rows (informative, as in v1)   36..63 reserved, zero
//   layer table: layer count entries of 32 bytes
//     0 u32 vertex count   4 u32 triangle count   8 u32 stream offset   12 u32 stream bytes
//    16 u32 vertex window (ring slots the decoder needs)   20 u32 pinned slots
//    24 u8 gradient step bits s (0 .. 24; 0 unless zienkiewicz: every gradient component of the
//       layer is a multiple of 2^s, coded in units of 2^s)   25..31 reserved, zero
//   streams: one per layer, inside [header + table, total size), in layer order.
//
// Fields 12..35 mean what they mean in v1. The decoder (LayerDecoder) checks every symbol as it
// goes: a corrupt stream ends in a status and the byte offset where the decoder stood.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/status.h"

namespace tristream::core {

inline constexpr uint16_t compressed_version = 3;  // 2: connectivity from open edges; 3: fresh_reach
// A third corner t coded "fresh" (by its count among the unused vertices after the triangle's first
// corner a) lies at most this many vertices after a: t - a <= compressed_fresh_reach (a farther one
// is gap-coded). It bounds the decoder's walk per triangle, so every valid stream decodes in time
// linear in its triangles (version 2 had no bound: a fan or a two-row strip decoded in quadratic time).
inline constexpr uint32_t compressed_fresh_reach = 2048;
inline constexpr uint32_t compressed_header_size = 64;
inline constexpr uint32_t compressed_layer_entry_size = 32;
// The largest gradient step bits of a layer (its table entry's byte 24).
inline constexpr uint32_t compressed_max_gradient_shift = 24;

struct CompressedLayer {
  uint32_t vertex_count = 0;
  uint32_t triangle_count = 0;
  const uint8_t* stream = nullptr;
  uint32_t stream_bytes = 0;
  uint32_t stream_offset = 0;  // of `stream` in the blob (for error offsets)
  uint32_t window = 0;         // vertex ring slots: 3 .. vertex_count
  uint32_t pinned = 0;         // slots for vertices decoded ahead of the ring: 0 .. vertex_count
  uint8_t gradient_shift = 0;  // gradient step bits s: components are multiples of 2^s (0 .. 24)
};

// A compressed blob whose header and layer table are valid; a view of the caller's bytes.
struct CompressedBlob : BlobInfo {
  uint32_t max_triangle_height = 0;
  CompressedLayer layers[3];
};

// Whether the bytes start with the compressed magic "TSTC" (size >= 4).
bool is_compressed_blob(const void* bytes, size_t size);

// Checks the header and the layer table (the streams are checked as they are decoded) and fills
// `out`. Never reads outside [bytes, bytes + size). `error` receives the offset of a failure.
Status open_compressed_blob(const void* bytes, size_t size, CompressedBlob* out, BlobError* error = nullptr);

// Bytes of a decoded vertex in the ring: x, y (u16), values (u16 each), a byte "values decoded",
// a byte of open-edge sides, rounded up to 4; two open-edge neighbours (u16 each); zienkiewicz
// gradients (i32 gx, gy per value).
uint32_t compressed_vertex_record_bytes(const CompressedBlob& blob);
// Bytes of ring memory LayerDecoder::begin needs for layer `layer`: 1 (to 2-align) + the value
// models the layer codes (compressed_value_models, 132 bytes each) + (window + pinned) * record
// bytes + 4 * pinned.
size_t compressed_ring_bytes(const CompressedBlob& blob, int layer);
// The adaptive models of a vertex's values that a layer codes, kept in the ring memory: one per
// value of a vertex (the integer parts), then for zienkiewicz two (gx, gy, shared by the values).
uint32_t compressed_value_models(const CompressedBlob& blob);
// Bytes of the tags LayerDecoder::keep_tags takes for layer `layer`: a u16 per ring slot and per
// pinned slot, 2 * (window + pinned).
size_t compressed_tag_bytes(const CompressedBlob& blob, int layer);

// The tag of a vertex the decoder holds that no caller set (keep_tags).
inline constexpr uint16_t compressed_tag_none = 0xFFFF;

namespace detail {
struct LayerDecoderState;  // layer_decoder_state.h, private to the core
}  // namespace detail

// One decoded triangle: its corners as in the v1 blob (v[0] first), each with its data.
struct DecodedTriangle {
  uint32_t v[3];  // vertex indices in the stream's (raster) numbering
  uint16_t flags;
  uint16_t x[3], y[3];
  uint16_t values[3][3];       // [corner][value], q8_8
  int32_t gradients[3][3][2];  // [corner][value][gx, gy], zienkiewicz only (not written otherwise)
  // With keep_tags: each corner's tag, which the caller may read and set until the next call of
  // next() (null without tags).
  uint16_t* tag[3];
};

// Receives each vertex once, when its values are decoded (not in index order; optional).
using VertexSink = void (*)(void* context, uint32_t index, uint16_t x, uint16_t y, const uint16_t* values,
                            const int32_t* gradients);

// Bytes and alignment of a LayerDecoder: its adaptive models (960 bytes) and its place in the
// stream, ten pointers among them (the core checks both against its state's type).
inline constexpr size_t layer_decoder_bytes = sizeof(void*) == 4 ? 1092 : 1144;
inline constexpr size_t layer_decoder_align = alignof(void*);

// Decodes one layer's stream triangle by triangle, keeping the last `window` vertices in a ring
// of caller memory (compressed_ring_bytes). Its own state is this object (layer_decoder_bytes,
// opaque). A trivial type: begin sets all of it, so it can live in caller memory (8-aligned bytes
// taken as a LayerDecoder) without being constructed; call begin before the other members.
class LayerDecoder {
 public:
  // Starts layer `layer` of `blob` (both must outlive the decoding); `ring` must hold
  // compressed_ring_bytes(blob, layer) bytes (any alignment): the value models, the ring, the
  // pinned slots.
  Status begin(const CompressedBlob& blob, int layer, void* ring, size_t ring_bytes, VertexSink sink = nullptr,
               void* sink_context = nullptr);
  // After begin: keeps a tag of 16 bits for each vertex while it is in the ring or pinned, in
  // `tags` (compressed_tag_bytes(blob, layer) bytes, 2-aligned, all set to compressed_tag_none
  // here). A vertex's tag is compressed_tag_none when it enters the ring or a pinned slot, follows
  // it from its pinned slot into the ring, and is reached by DecodedTriangle::tag while the vertex
  // is a corner; a caller can so attach a u16 of its own to the vertices it has seen (the band
  // store: the vertex's slot) without a map, and may rewrite every tag between triangles through
  // `tags` (ring slots first, then pinned slots).
  void keep_tags(uint16_t* tags);
  // Decodes the next triangle. Call triangle_count times, then finish().
  Status next(DecodedTriangle* out);
  // Decodes the vertices no triangle needed yet and checks that the stream ends exactly.
  Status finish();
  // Byte offset in the blob where the decoder stands (of the failure after a bad status).
  uint32_t offset() const;

 private:
  detail::LayerDecoderState& state();
  const detail::LayerDecoderState& state() const;

  alignas(layer_decoder_align) unsigned char state_[layer_decoder_bytes];
};

// Bytes of the v1 blob expand_compressed_blob writes (the layout tripack's packer writes).
size_t expanded_blob_size(const CompressedBlob& blob);
// Bytes of workspace expand_compressed_blob needs: the largest layer's ring.
size_t expand_workspace_size(const CompressedBlob& blob);
// Decodes every layer into a v1 blob at `out` (expanded_blob_size bytes), which open_blob accepts
// and which renders bit-identically to the v1 blob the stream was made from (its vertices are
// numbered in the stream's raster order). `error` receives the offset of a failure. bad_params
// when `out` (out_bytes) and the workspace (workspace_bytes) overlap.
Status expand_compressed_blob(const CompressedBlob& blob, void* out, size_t out_bytes, void* workspace,
                              size_t workspace_bytes, BlobError* error = nullptr);

}  // namespace tristream::core
