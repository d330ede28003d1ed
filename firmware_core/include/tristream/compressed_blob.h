/* SPDX-License-Identifier: MIT */
#pragma once
// The compressed blob ("TSTC", docs/COMPRESSED_BLOB.md): the same meshes as a v1 blob (blob.h),
// each layer one stream of an adaptive binary range coder, decoded sequentially in the order the
// core consumes the mesh (triangles by top row). Layout (little-endian, offsets from byte 0):
//
//   header, 64 bytes
//     0  char[4] magic "TSTC"        4  u16 version (2)         6  u16 header size (64)
//     8  u32 total size             12  u16 width  14 u16 height
//    16  u8 colour space   17 u8 method   18 u8 layer count   19 u8 values per vertex
//    20  u8 sub-pixel bits   21 u8 gradient fraction bits   22 u16 flags (0)
//    24  u32 config hash (blob_config_hash())   28 u32 layer table offset (64)
//    32  u32 max triangle height in rows (informative, as in v1)   36..63 reserved, zero
//   layer table: layer count entries of 32 bytes
//     0 u32 vertex count   4 u32 triangle count   8 u32 stream offset   12 u32 stream bytes
//    16 u32 vertex window (ring slots the decoder needs)   20 u32 pinned slots   24..31 reserved, zero
//   streams: one per layer, inside [header + table, total size), in layer order.
//
// Fields 12..35 mean what they mean in v1. The decoder (LayerDecoder) checks every symbol as it
// goes: a corrupt stream ends in a status and the byte offset where the decoder stood.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/status.h"

namespace tristream::core {

inline constexpr uint16_t compressed_version = 2;  // 2: connectivity from open edges
inline constexpr uint32_t compressed_header_size = 64;
inline constexpr uint32_t compressed_layer_entry_size = 32;

struct CompressedLayer {
  uint32_t vertex_count = 0;
  uint32_t triangle_count = 0;
  const uint8_t* stream = nullptr;
  uint32_t stream_bytes = 0;
  uint32_t stream_offset = 0;  // of `stream` in the blob (for error offsets)
  uint32_t window = 0;         // vertex ring slots: 3 .. vertex_count
  uint32_t pinned = 0;         // slots for vertices decoded ahead of the ring: 0 .. vertex_count
};

// A compressed blob whose header and layer table are valid; a view of the caller's bytes.
struct CompressedBlob {
  const uint8_t* bytes = nullptr;
  uint32_t size = 0;
  uint16_t width = 0;
  uint16_t height = 0;
  ColorSpace space = ColorSpace::grey;
  Method method = Method::bilinear;
  uint8_t layer_count = 0;
  uint8_t values_per_vertex = 0;
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

// An adaptive probability of a 0 in 1/2048 (11 bits), moved 1/32 of the way per coded bit.
using Prob = uint16_t;
inline constexpr int prob_bits = 11;
inline constexpr int prob_shift = 5;
inline constexpr Prob prob_half = 1u << (prob_bits - 1);

// Contexts of an unsigned integer u in adaptive Exp-Golomb form: k = floor(log2(u + 1)) as k ones
// and a zero (bit i with prefix[min(i, 15)]), then the k bits of u + 1 below its leading one, the
// first two through a small tree per k (mantissa[min(k, 15)]), the others at probability 1/2.
struct UintModel {
  Prob prefix[16];
  Prob mantissa[16][3];
};
// A signed integer: zero or not, the sign, then |s| - 1 as an UintModel.
struct IntModel {
  Prob zero;
  Prob sign;
  UintModel magnitude;
};

// Every context of one layer's stream (docs/COMPRESSED_BLOB.md lists what each codes) but the
// value models: those of the integer parts of the values (predicted, see the doc) and of the
// gradients (gx, gy, against their prediction), of which a layer has only those it codes
// (compressed_value_models), in its decoder's ring memory.
struct StreamModels {
  UintModel gap;            // raster pixel gap to the previous vertex
  Prob subpixel;            // the vertex has non-zero sub-pixel bits
  Prob fraction;            // some value of the vertex has a non-zero fraction byte
  // A triangle's first vertex a against the previous triangle's: 0, +1, +2, -1 or an escape (7) to
  // top_far, context: how the previous triangle's anchor and third vertex were coded (6 classes).
  Prob top[6][8];
  IntModel top_far;
  // The anchor s (a second corner): one of a's open edges (0, 1) or gap-coded (7); context: a's step.
  Prob anchor[3][8];
  UintModel anchor_gap;     // a gap-coded anchor: s - a - 1
  Prob side;                // a gap-coded anchor: the side of a->s the third corner is on
  // The third corner t: the predicted one (the largest angle over a->s among the candidates) or
  // not; if not, unused so far (then the count of such vertices in the edge's columns between a
  // and t) or a gap t - a - 1; contexts: how the anchor was coded (open edge 0, 1, gap-coded).
  Prob predicted[3];
  Prob fresh[3];
  UintModel fresh_count;
  UintModel third_gap;
  Prob lift;                // a corner far ahead is decoded into a pinned slot
  UintModel lift_gap;       // its raster pixel gap to the last vertex of the ring
  Prob rotation[2];
  Prob flags_nonzero;
  Prob flag_bit[9];
};

// Set by start() (range_decoder.h); no initializers, so that LayerDecoder stays a trivial type.
struct RangeDecoder {
  const uint8_t* p;
  const uint8_t* end;
  uint32_t range;
  uint32_t code;
  bool overrun;  // asked for bytes past the end (never in a valid stream)
};

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

// Decodes one layer's stream triangle by triangle, keeping the last `window` vertices in a ring
// of caller memory (compressed_ring_bytes). Its own state is this object (about 1.1 KiB). A
// trivial type: begin sets every field, so it can live in caller memory (8-aligned bytes taken as
// a LayerDecoder) without being constructed; call begin before the other members.
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
  Status fail(Status s);
  Status decode_position();
  void enter_row(uint32_t row);
  Status place(uint32_t index);
  uint32_t pinned_slot(uint32_t index) const;
  uint8_t* pinned_record(uint32_t index) const;
  uint32_t ring_slot(uint32_t back, uint32_t window) const;
  uint16_t* tag_of(uint32_t index) const;
  void find_next_pinned();
  Status decode_values(uint8_t* rec, uint32_t index, const uint8_t* p0, const uint8_t* p1);
  template <int PerVertex>
  Status decode_values_of(uint8_t* rec, uint32_t index, const uint8_t* p0, const uint8_t* p1);
  struct Columns {
    int32_t lo, hi;  // 1/16 pixel
  };
  static Columns columns(const uint8_t* ra, const uint8_t* rs);
  uint32_t predict(uint32_t a, uint32_t s, uint8_t* ra, uint8_t* rs, int side, uint8_t** record_out) const;
  uint64_t fresh(uint32_t a, uint32_t count, Columns cols);
  void add_edge(uint8_t* from, uint32_t to, bool positive);
  uint8_t* record(uint32_t index) const;

  const CompressedBlob* blob_;
  const CompressedLayer* layer_;
  uint8_t* ring_;
  detail::IntModel* value_models_;  // in the ring memory: per value, then gx, gy (zienkiewicz)
  uint8_t* pins_;  // pinned records, then their indices (u32 each)
  uint16_t* tags_;  // keep_tags: per ring slot, then per pinned slot (null: none)
  uint32_t pin_slot_;  // the pinned slot the next lift takes
  uint32_t next_pinned_;  // smallest index pending in a pinned slot (0xFFFFFFFF: none)
  uint32_t record_;
  VertexSink sink_;
  void* sink_context_;
  detail::RangeDecoder rc_;
  detail::StreamModels m_;
  uint32_t decoded_;  // vertices decoded: indices [0, decoded_)
  uint32_t slot_;  // ring slot of vertex decoded_
  uint32_t triangles_;  // triangles decoded
  uint32_t pixel_;  // raster pixel index of the last vertex
  uint32_t row_;  // its pixel row
  uint32_t row_start_;  // the first vertex of that row
  uint32_t previous_top_;  // first index of the previous triangle
  int32_t previous_row_;  // top y (position_fx) of the previous triangle
  uint8_t previous_picks_;  // context of the next triangle's first vertex
  uint16_t last_values_[3];
  int32_t last_gradients_[3][2];
  Status failed_;
};

// Bytes of the v1 blob expand_compressed_blob writes (the layout tripack's packer writes).
size_t expanded_blob_size(const CompressedBlob& blob);
// Bytes of workspace expand_compressed_blob needs: the largest layer's ring.
size_t expand_workspace_size(const CompressedBlob& blob);
// Decodes every layer into a v1 blob at `out` (expanded_blob_size bytes), which open_blob accepts
// and which renders bit-identically to the v1 blob the stream was made from (its vertices are
// numbered in the stream's raster order). `error` receives the offset of a failure.
Status expand_compressed_blob(const CompressedBlob& blob, void* out, size_t out_bytes, void* workspace,
                              size_t workspace_bytes, BlobError* error = nullptr);

}  // namespace tristream::core
