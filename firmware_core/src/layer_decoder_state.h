/* SPDX-License-Identifier: MIT */
#pragma once
// The state of a LayerDecoder (compressed_blob.h), which holds it as opaque bytes of
// layer_decoder_bytes: the layer and its ring, the range coder, the adaptive models and where the
// decoding stands. Its members do the work of LayerDecoder's (compressed_blob.cpp).
#include <stdint.h>

#include "tristream/compressed_blob.h"
#include "range_decoder.h"
#include "stream_models.h"

namespace tristream::core::detail {

// A trivial type (no initializers): begin sets every field.
struct LayerDecoderState {
  Status begin(const CompressedBlob& blob, int layer, void* ring, size_t ring_bytes, VertexSink sink,
               void* sink_context);
  void keep_tags(uint16_t* tags);
  Status next(DecodedTriangle* out);
  Status finish();
  uint32_t offset() const;

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
  IntModel* value_models_;  // in the ring memory: per value, then gx, gy (zienkiewicz)
  uint8_t* pins_;  // pinned records, then their indices (u32 each)
  uint16_t* tags_;  // keep_tags: per ring slot, then per pinned slot (null: none)
  uint32_t pin_slot_;  // the pinned slot the next lift takes
  uint32_t next_pinned_;  // smallest index pending in a pinned slot (0xFFFFFFFF: none)
  uint32_t record_;
  VertexSink sink_;
  void* sink_context_;
  RangeDecoder rc_;
  StreamModels m_;
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

}  // namespace tristream::core::detail
