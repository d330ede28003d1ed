// SPDX-License-Identifier: MIT
// The compressed blob: header checks, the layer decoder and the expansion to a v1 blob
// (docs/COMPRESSED_BLOB.md is the format; this file is its only reader).
#include "tristream/compressed_blob.h"


#include "blob_header.h"
#include "layer_decoder_state.h"
#include "bytes.h"
#include "wire_layout.h"

namespace tristream::core {

using detail::LayerDecoderState;
using detail::load_u16;
using detail::load_u32;
using detail::store_u16;
using detail::store_u32;

namespace {

constexpr uint32_t align4(uint32_t n) { return (n + 3u) & ~3u; }

// Sizes of the coded integers (bits of |s| - 1 or of u + 1 below its leading one).
constexpr int gap_bits = 24;        // a raster pixel index of at most 4096 x 4096
constexpr int index_bits = 16;      // vertex indices below 65535
constexpr int value_bits = 9;       // residuals of at most 510
constexpr int gradient_bits = 31;   // wrapped 32-bit differences

// Fields of a ring record (compressed_vertex_record_bytes): x, y, values, then at 4 + 2 v (2 mod
// 4, as v is 1 or 3) a byte "values decoded" and a byte of the sides of the two open edges (bits
// 0-1 the first's, 2-3 the second's: 1 a triangle on the positive side of from->to is decoded, 2
// one on the negative side; 0 no edge), then at align4(4 + 2 v) the open edges' other ends (u16
// each, the most recent first), then the gradients.
constexpr uint32_t edges_at(uint32_t per_vertex) { return align4(4 + 2 * per_vertex); }
constexpr uint32_t gradients_at(uint32_t per_vertex) { return edges_at(per_vertex) + 4; }
constexpr uint32_t escape_symbol = 7;

struct Fail {
  BlobError* error;
  Status operator()(Status s, uint32_t offset) const {
    if (error) error->offset = offset;
    return s;
  }
};

}  // namespace

bool is_compressed_blob(const void* bytes, size_t size) {
  const uint8_t* b = static_cast<const uint8_t*>(bytes);
  return b && size >= 4 && wire::has_magic(b + wire::header::magic, wire::compressed_magic);
}

Status open_compressed_blob(const void* bytes, size_t size, CompressedBlob* out, BlobError* error) {
  if (!bytes || !out) return Status::null_argument;
  const uint8_t* b = static_cast<const uint8_t*>(bytes);
  const Fail fail{error};
  namespace h = wire::header;
  namespace L = wire::compressed_layer;
  if (size < h::bytes) return fail(Status::truncated, uint32_t(size));
  if (!is_compressed_blob(b, size)) return fail(Status::bad_magic, h::magic);
  CompressedBlob blob;
  blob.bytes = b;
  uint32_t at = 0;
  const Status shared = detail::check_shared_header(b, size, compressed_version, h::bytes, &blob, &at);
  if (shared != Status::ok) return fail(shared, at);
  if (load_u32(b + h::layer_table) != h::bytes) return fail(Status::bad_section, h::layer_table);
  blob.max_triangle_height = load_u32(b + h::max_triangle_height);
  for (uint32_t k = h::compressed_reserved; k < h::bytes; ++k)
    if (b[k] != 0) return fail(Status::bad_header, k);
  uint32_t next_stream = h::bytes + blob.layer_count * L::bytes;
  if (next_stream > blob.size) return fail(Status::truncated, h::layer_table);
  for (uint32_t l = 0; l < blob.layer_count; ++l) {
    const uint32_t e = h::bytes + l * L::bytes;
    CompressedLayer& layer = blob.layers[l];
    layer.vertex_count = load_u32(b + e + L::vertex_count);
    layer.triangle_count = load_u32(b + e + L::triangle_count);
    layer.stream_offset = load_u32(b + e + L::stream_offset);
    layer.stream_bytes = load_u32(b + e + L::stream_bytes);
    layer.window = load_u32(b + e + L::window);
    layer.pinned = load_u32(b + e + L::pinned);
    layer.gradient_shift = b[e + L::gradient_step];
    for (uint32_t k = L::reserved; k < L::bytes; ++k)
      if (b[e + k] != 0) return fail(Status::bad_header, e + k);
    // A gradient step only where there are gradients.
    if (layer.gradient_shift > (blob.method == Method::zienkiewicz ? compressed_max_gradient_shift : 0u))
      return fail(Status::bad_header, e + L::gradient_step);
    if (layer.vertex_count < 3 || layer.vertex_count > blob_max_vertices)
      return fail(Status::too_large, e + L::vertex_count);
    if (layer.triangle_count < 1 || layer.triangle_count > blob_max_triangles)
      return fail(Status::too_large, e + L::triangle_count);
    // Streams in layer order, each of at least the 4 bytes the decoder starts with.
    if (layer.stream_offset < next_stream || layer.stream_bytes < 4 ||
        uint64_t(layer.stream_offset) + layer.stream_bytes > blob.size)
      return fail(Status::bad_section, e + L::stream_offset);
    if (layer.window < 3 || layer.window > layer.vertex_count) return fail(Status::bad_header, e + L::window);
    if (layer.pinned > layer.vertex_count) return fail(Status::bad_header, e + L::pinned);
    layer.stream = b + layer.stream_offset;
    next_stream = layer.stream_offset + layer.stream_bytes;
  }
  *out = blob;
  return Status::ok;
}

uint32_t compressed_vertex_record_bytes(const CompressedBlob& blob) {
  const uint32_t nv = blob.values_per_vertex;
  return gradients_at(nv) + (blob.method == Method::zienkiewicz ? 8 * nv : 0);
}

uint32_t compressed_value_models(const CompressedBlob& blob) {
  return uint32_t(blob.values_per_vertex) + (blob.method == Method::zienkiewicz ? 2 : 0);
}

size_t compressed_ring_bytes(const CompressedBlob& blob, int layer) {
  if (layer < 0 || layer >= blob.layer_count) return 0;
  const CompressedLayer& l = blob.layers[layer];
  return 1 + compressed_value_models(blob) * sizeof(detail::IntModel) +
         (size_t(l.window) + l.pinned) * compressed_vertex_record_bytes(blob) + 4 * size_t(l.pinned);
}

size_t compressed_tag_bytes(const CompressedBlob& blob, int layer) {
  if (layer < 0 || layer >= blob.layer_count) return 0;
  return 2 * (size_t(blob.layers[layer].window) + blob.layers[layer].pinned);
}

// A failure after the decoder ran past the stream's end is its truncation.
Status LayerDecoderState::fail(Status s) {
  if (rc_.overrun) s = Status::truncated;
  failed_ = s;
  return s;
}

uint32_t LayerDecoderState::offset() const {
  if (!layer_) return 0;
  return layer_->stream_offset + uint32_t(rc_.p - layer_->stream);
}

Status LayerDecoderState::begin(const CompressedBlob& blob, int layer, void* ring, size_t ring_bytes, VertexSink sink,
                           void* sink_context) {
  layer_ = nullptr;  // offset() is 0 after a failed begin
  if (layer < 0 || layer >= blob.layer_count) return Status::bad_params;
  if (!ring) return Status::null_argument;
  if (ring_bytes < compressed_ring_bytes(blob, layer)) return Status::workspace_too_small;
  blob_ = &blob;
  layer_ = &blob.layers[layer];
  static_assert(alignof(detail::IntModel) <= 2, "one byte 2-aligns the value models");
  uint8_t* models = static_cast<uint8_t*>(ring) + uintptr_t(ring) % 2;
  value_models_ = reinterpret_cast<detail::IntModel*>(models);
  ring_ = models + compressed_value_models(blob) * sizeof(detail::IntModel);
  pins_ = ring_ + size_t(layer_->window) * compressed_vertex_record_bytes(blob);
  for (uint32_t i = 0; i < layer_->pinned; ++i)
    store_u32(pins_ + size_t(layer_->pinned) * compressed_vertex_record_bytes(blob) + 4 * i, 0xFFFFFFFFu);
  tags_ = nullptr;
  pin_slot_ = 0;
  next_pinned_ = 0xFFFFFFFFu;
  record_ = compressed_vertex_record_bytes(blob);
  sink_ = sink;
  sink_context_ = sink_context;
  detail::start(rc_, layer_->stream, layer_->stream + layer_->stream_bytes);
  detail::reset(m_.gap);
  m_.subpixel = m_.fraction = m_.flags_nonzero = detail::prob_half;
  for (uint32_t i = 0; i < compressed_value_models(blob); ++i) detail::reset(value_models_[i]);
  detail::reset(&m_.top[0][0], 6 * 8);
  detail::reset(m_.top_far);
  detail::reset(&m_.anchor[0][0], 3 * 8);
  detail::reset(m_.anchor_gap);
  m_.side = detail::prob_half;
  detail::reset(m_.predicted, 3);
  detail::reset(m_.fresh, 3);
  detail::reset(m_.fresh_count);
  detail::reset(m_.third_gap);
  previous_picks_ = 0;
  detail::reset(m_.rotation, 2);
  m_.lift = detail::prob_half;
  detail::reset(m_.lift_gap);
  detail::reset(m_.flag_bit, 9);
  decoded_ = slot_ = triangles_ = pixel_ = previous_top_ = 0;
  row_ = row_start_ = 0;
  previous_row_ = 0;
  for (int c = 0; c < 3; ++c) {
    last_values_[c] = 0;
    last_gradients_[c][0] = last_gradients_[c][1] = 0;
  }
  failed_ = Status::ok;
  return Status::ok;
}

void LayerDecoderState::keep_tags(uint16_t* tags) {
  tags_ = tags;
  if (!tags || !layer_) return;
  for (uint32_t i = 0; i < layer_->window + layer_->pinned; ++i) tags[i] = compressed_tag_none;
}

// The pinned slot of a vertex not yet in the ring, or 0xFFFFFFFF.
uint32_t LayerDecoderState::pinned_slot(uint32_t index) const {
  // next_pinned_ is the smallest index pending in a slot (decode_position takes it before it passes)
  if (index < decoded_ || index < next_pinned_) return 0xFFFFFFFFu;
  const uint8_t* indices = pins_ + size_t(layer_->pinned) * record_;
  for (uint32_t i = 0; i < layer_->pinned; ++i)
    if (load_u32(indices + 4 * i) == index) return i;
  return 0xFFFFFFFFu;
}

// The pinned record of a vertex not yet in the ring, or null.
uint8_t* LayerDecoderState::pinned_record(uint32_t index) const {
  const uint32_t i = pinned_slot(index);
  return i == 0xFFFFFFFFu ? nullptr : pins_ + size_t(i) * record_;
}

// The ring slot of the vertex `back` (1 .. window, the layer's) before vertex decoded_.
__attribute__((always_inline)) inline uint32_t LayerDecoderState::ring_slot(uint32_t back, uint32_t window) const {
  return slot_ >= back ? slot_ - back : slot_ + window - back;
}

// The tag of a vertex in the ring or pinned (as record()), or null. Inlined: three a triangle.
__attribute__((always_inline)) inline uint16_t* LayerDecoderState::tag_of(uint32_t index) const {
  if (index >= decoded_) {
    const uint32_t i = pinned_slot(index);
    return i == 0xFFFFFFFFu ? nullptr : tags_ + layer_->window + i;
  }
  const uint32_t back = decoded_ - index, window = layer_->window;
  return back > window ? nullptr : tags_ + ring_slot(back, window);
}

void LayerDecoderState::find_next_pinned() {
  const uint8_t* indices = pins_ + size_t(layer_->pinned) * record_;
  next_pinned_ = 0xFFFFFFFFu;
  for (uint32_t i = 0; i < layer_->pinned; ++i) {
    const uint32_t v = load_u32(indices + 4 * i);
    if (v >= decoded_ && v < next_pinned_) next_pinned_ = v;
  }
}

// The record of a vertex: in the ring, or pinned ahead of it; null when it is in neither.
// Inlined: it is called a dozen times per triangle.
__attribute__((always_inline)) inline uint8_t* LayerDecoderState::record(uint32_t index) const {
  if (index >= decoded_) return pinned_record(index);
  const uint32_t back = decoded_ - index, window = layer_->window;
  return back > window ? nullptr : ring_ + size_t(ring_slot(back, window)) * record_;
}

// Whether the values of a record are decoded, and the sides of its open edges (edges_at).
namespace {
uint8_t& known_byte(uint8_t* rec, int per_vertex) { return rec[4 + 2 * per_vertex]; }
uint8_t& sides_byte(uint8_t* rec, int per_vertex) { return rec[5 + 2 * per_vertex]; }
}  // namespace

namespace {
// A gradient component's prediction: the known corners' (one, or the mean of two), else `last`.
int32_t gradient_prediction(const uint8_t* p0, const uint8_t* p1, int nv, int c, int axis, int32_t last) {
  if (!p0) return last;
  const uint32_t at = gradients_at(uint32_t(nv)) + 8 * uint32_t(c) + 4 * uint32_t(axis);
  const int64_t g0 = int32_t(load_u32(p0 + at));
  return p1 ? int32_t((g0 + int32_t(load_u32(p1 + at))) >> 1) : int32_t(g0);
}
}  // namespace

// Vertex decoded_, of pixel row `row`, enters the ring. When it starts a later row, the previous
// row's vertices still in the ring and unused get their skips for fresh(), in the 4 bytes their
// open edges take once used: at edges_at the distance to the row's end (the first vertex after
// the row), at edges_at + 2 the distance to the first later vertex of the row in another 32-pixel
// block of columns, or to the row's end. 0 means not set (the last row, still open). Both stay
// below the window and point before decoded_, whatever the stream.
void LayerDecoderState::enter_row(uint32_t row) {
  if (decoded_ != 0 && row == row_) return;
  const uint32_t end = decoded_, window = layer_->window;
  const uint32_t oldest = end >= window ? end - window + 1 : 0;  // slot_ is being taken by `end`
  uint32_t i = end;
  if (decoded_ != 0 && end - row_start_ >= 2) {
    const int S = config::subpixel_bits;
    const uint32_t nv = blob_->values_per_vertex, known_at = 4 + 2 * nv, skips = edges_at(nv);
    const uint32_t first = row_start_ > oldest ? row_start_ : oldest;
    uint8_t* p = ring_ + size_t(slot_) * record_;
    uint32_t next_block = end, block = 0xFFFFFFFFu;
    while (i > first) {
      --i;
      p = p == ring_ ? ring_ + size_t(window - 1) * record_ : p - record_;
      const uint32_t b = uint32_t(load_u16(p)) >> (S + 5);
      if (b != block) next_block = i + 1, block = b;
      if (p[known_at]) continue;
      store_u16(p + skips, end - i);
      store_u16(p + skips + 2, next_block - i);
    }
  }
  row_ = row;
  row_start_ = end;
}

Status LayerDecoderState::decode_position() {
  using namespace detail;
  const CompressedBlob& blob = *blob_;
  const int S = config::subpixel_bits;
  // The slot's vertex leaves the ring: if no triangle asked for it, its values come now.
  uint8_t* rec = ring_ + size_t(slot_) * record_;
  if (decoded_ >= layer_->window && !known_byte(rec, blob.values_per_vertex)) {
    const Status st = decode_values(rec, decoded_ - layer_->window, nullptr, nullptr);
    if (st != Status::ok) return st;
  }
  if (decoded_ == next_pinned_) {
    // Decoded ahead: the pinned record (and its tag) moves into the ring, without bits.
    const uint32_t pin_slot = pinned_slot(decoded_);
    if (pin_slot == 0xFFFFFFFFu) return fail(Status::bad_index);
    const uint8_t* pin = pins_ + size_t(pin_slot) * record_;
    for (uint32_t i = 0; i < record_; ++i) rec[i] = pin[i];
    if (tags_) {
      tags_[slot_] = tags_[layer_->window + pin_slot];
      tags_[layer_->window + pin_slot] = compressed_tag_none;
    }
    pixel_ = uint32_t(load_u16(rec + 2) >> S) * blob.width + uint32_t(load_u16(rec) >> S);
    enter_row(pixel_ / blob.width);
    ++decoded_;
    slot_ = slot_ + 1 == layer_->window ? 0 : slot_ + 1;
    find_next_pinned();
    return Status::ok;
  }
  uint32_t gap;
  if (!decode_uint(rc_, m_.gap, gap_bits, &gap)) return fail(Status::coordinate_out_of_range);
  const uint64_t pixel = uint64_t(pixel_) + gap;
  if (pixel >= uint64_t(blob.width) * blob.height) return fail(Status::coordinate_out_of_range);
  const uint32_t py = uint32_t(pixel) / blob.width, px = uint32_t(pixel) - py * blob.width;
  uint32_t sx = 0, sy = 0;
  if (decode_bit(rc_, m_.subpixel)) {
    sx = decode_direct(rc_, S);
    sy = decode_direct(rc_, S);
  }
  const uint32_t x = (px << S) | sx, y = (py << S) | sy;
  if (x > (uint32_t(blob.width - 1) << S) || y > (uint32_t(blob.height - 1) << S))
    return fail(Status::coordinate_out_of_range);
  if (rc_.overrun) return fail(Status::truncated);
  store_u16(rec, x);
  store_u16(rec + 2, y);
  known_byte(rec, blob.values_per_vertex) = 0;
  sides_byte(rec, blob.values_per_vertex) = 0;
  store_u32(rec + edges_at(blob.values_per_vertex), 0);  // no skips yet (fresh)
  if (tags_) tags_[slot_] = compressed_tag_none;
  pixel_ = uint32_t(pixel);
  if (py != row_ || decoded_ == 0) enter_row(py);  // (its test inlined: most vertices stay in the row)
  ++decoded_;
  slot_ = slot_ + 1 == layer_->window ? 0 : slot_ + 1;
  return Status::ok;
}

// Values (and gradients) of the vertex at `rec`, predicted from the records `p0` and `p1` (the
// triangle's corners whose values are known; either may be null) or else from the last vertex
// whose values were decoded.
// Values per vertex are 1 or 3 (open_compressed_blob): one copy for each, its loops unrolled.
Status LayerDecoderState::decode_values(uint8_t* rec, uint32_t index, const uint8_t* p0, const uint8_t* p1) {
  return blob_->values_per_vertex == 1 ? decode_values_of<1>(rec, index, p0, p1)
                                       : decode_values_of<3>(rec, index, p0, p1);
}

template <int PerVertex>
Status LayerDecoderState::decode_values_of(uint8_t* rec, uint32_t index, const uint8_t* p0, const uint8_t* p1) {
  using namespace detail;
  const CompressedBlob& blob = *blob_;
  constexpr int nv = PerVertex;
  if (!p0) p0 = p1, p1 = nullptr;
  int32_t predicted[3];
  for (int c = 0; c < 3; ++c) {
    if (p0 && c < nv) {
      const int32_t h = load_u16(p0 + 4 + 2 * c) >> 8;
      predicted[c] = p1 ? (h + (load_u16(p1 + 4 + 2 * c) >> 8) + 1) >> 1 : h;
    } else {
      predicted[c] = last_values_[c] >> 8;
    }
  }
  // Integer parts against the prediction; in RGB, R and B also follow G's change.
  const bool rgb = blob.space == ColorSpace::rgb && nv == 3;
  int32_t high[3] = {0, 0, 0};
  int32_t shared = 0;
  // The coder's range and code in registers for the vertex (written back at the end; a failed
  // decoder is not read again).
  LocalCoder coder(rc_);
  for (int k = 0; k < nv; ++k) {
    const int c = rgb ? (k == 0 ? 1 : (k == 1 ? 0 : 2)) : k;
    int32_t r;
    if (!decode_int32(coder, value_models_[k], value_bits, &r)) return fail(Status::value_out_of_range);
    const int32_t h = predicted[c] + r + (rgb && k > 0 ? shared : 0);
    if (h < 0 || h > 255) return fail(Status::value_out_of_range);
    if (rgb && k == 0) shared = r;
    high[c] = h;
  }
  uint16_t values[3] = {0, 0, 0};
  const bool fraction = coder.bit(m_.fraction);
  for (int c = 0; c < nv; ++c) {
    const uint32_t low = fraction ? coder.direct(8) : 0;
    const uint32_t v = (uint32_t(high[c]) << 8) | low;
    if (v > 255u * 256u) return fail(Status::value_out_of_range);
    values[c] = uint16_t(v);
  }
  int32_t gradients[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  if (blob.method == Method::zienkiewicz) {
    const int64_t limit = int64_t(config::max_gradient) << config::gradient_frac_bits;
    // In units of the layer's step 2^s: the prediction floored to a multiple of it, plus r steps.
    const uint32_t shift = layer_->gradient_shift, step_mask = ~((1u << shift) - 1u);
    for (int c = 0; c < nv; ++c)
      for (int a = 0; a < 2; ++a) {
        int64_t r;
        if (!decode_int(coder, value_models_[nv + a], gradient_bits, &r)) return fail(Status::value_out_of_range);
        const uint32_t p = uint32_t(gradient_prediction(p0, p1, nv, c, a, last_gradients_[c][a])) & step_mask;
        const int32_t g = int32_t(p + (uint32_t(r) << shift));
        if (g > limit || g < -limit) return fail(Status::value_out_of_range);
        gradients[c][a] = g;
      }
  }
  coder.done();
  if (rc_.overrun) return fail(Status::truncated);
  for (int c = 0; c < nv; ++c) store_u16(rec + 4 + 2 * c, values[c]);
  if (blob.method == Method::zienkiewicz) {
    uint8_t* g = rec + gradients_at(uint32_t(nv));
    for (int c = 0; c < nv; ++c) {
      store_u32(g + 8 * c, uint32_t(gradients[c][0]));
      store_u32(g + 8 * c + 4, uint32_t(gradients[c][1]));
    }
  }
  known_byte(rec, nv) = 1;
  if (sink_) sink_(sink_context_, index, load_u16(rec), load_u16(rec + 2), values, &gradients[0][0]);
  for (int c = 0; c < 3; ++c) {
    last_values_[c] = values[c];
    last_gradients_[c][0] = gradients[c][0];
    last_gradients_[c][1] = gradients[c][1];
  }
  return Status::ok;
}

// A corner not decoded yet: the positions up to it into the ring, or (a lift) its position alone
// into the next pinned slot, whose vertex must have reached the ring.
Status LayerDecoderState::place(uint32_t index) {
  using namespace detail;
  if (!decode_bit(rc_, m_.lift)) {
    while (decoded_ <= index) {
      const Status st = decode_position();
      if (st != Status::ok) return st;
    }
    return Status::ok;
  }
  const CompressedBlob& blob = *blob_;
  const int S = config::subpixel_bits;
  if (layer_->pinned == 0) return fail(Status::bad_header);
  uint8_t* indices = pins_ + size_t(layer_->pinned) * record_;
  const uint32_t held = load_u32(indices + 4 * pin_slot_);
  if (held != 0xFFFFFFFFu && held >= decoded_) return fail(Status::bad_header);  // fewer slots than needed
  uint32_t gap;
  if (!decode_uint(rc_, m_.lift_gap, gap_bits, &gap)) return fail(Status::coordinate_out_of_range);
  const uint64_t pixel = uint64_t(pixel_) + gap;
  if (pixel >= uint64_t(blob.width) * blob.height) return fail(Status::coordinate_out_of_range);
  const uint32_t py = uint32_t(pixel) / blob.width, px = uint32_t(pixel) - py * blob.width;
  uint32_t sx = 0, sy = 0;
  if (decode_bit(rc_, m_.subpixel)) {
    sx = decode_direct(rc_, S);
    sy = decode_direct(rc_, S);
  }
  const uint32_t x = (px << S) | sx, y = (py << S) | sy;
  if (x > (uint32_t(blob.width - 1) << S) || y > (uint32_t(blob.height - 1) << S))
    return fail(Status::coordinate_out_of_range);
  if (rc_.overrun) return fail(Status::truncated);
  uint8_t* rec = pins_ + size_t(pin_slot_) * record_;
  store_u16(rec, x);
  store_u16(rec + 2, y);
  known_byte(rec, blob.values_per_vertex) = 0;
  sides_byte(rec, blob.values_per_vertex) = 0;
  store_u32(rec + edges_at(blob.values_per_vertex), 0);  // no skips yet (fresh)
  store_u32(indices + 4 * pin_slot_, index);
  if (tags_) tags_[layer_->window + pin_slot_] = compressed_tag_none;
  pin_slot_ = pin_slot_ + 1 == layer_->pinned ? 0 : pin_slot_ + 1;
  if (index < next_pinned_) next_pinned_ = index;
  return Status::ok;
}

// The columns (1/16 pixel) where the third corner of a triangle on the edge a->s is looked for:
// the edge's span widened by its length (L-infinity) and 2 pixels on each side; all of them when
// a or s has no record.
LayerDecoderState::Columns LayerDecoderState::columns(const uint8_t* ra, const uint8_t* rs) {
  if (!ra || !rs) return Columns{0, 0xFFFF};
  const int32_t ax = load_u16(ra), ay = load_u16(ra + 2), sx = load_u16(rs), sy = load_u16(rs + 2);
  const int32_t dx = ax > sx ? ax - sx : sx - ax, dy = ay > sy ? ay - sy : sy - ay;
  const int32_t reach = (dx > dy ? dx : dy) + (2 << config::subpixel_bits);
  return Columns{(ax < sx ? ax : sx) - reach, (ax > sx ? ax : sx) + reach};
}

// The third corner a Delaunay triangulation puts on side `side` (+1, -1) of the edge a->s: among
// the other ends of the open edges of a and of s (vertices some triangle used), the one above a
// with the largest angle over a->s (the smallest dot / cross of (a - q, s - q)), compared exactly
// in 64 bits on pixel coordinates (differences below 2^12, so dot and cross below 2^25); ties keep
// the first. 0xFFFFFFFF when a or s has no record or no candidate is on that side; its record in
// *record_out (null when none).
uint32_t LayerDecoderState::predict(uint32_t a, uint32_t s, uint8_t* ra, uint8_t* rs, int side, uint8_t** record_out) const {
  const int nv = blob_->values_per_vertex;
  const int S = config::subpixel_bits;
  *record_out = nullptr;
  if (!ra || !rs) return 0xFFFFFFFFu;
  const int32_t ax = load_u16(ra) >> S, ay = load_u16(ra + 2) >> S;
  const int32_t sx = load_u16(rs) >> S, sy = load_u16(rs + 2) >> S;
  uint32_t best = 0xFFFFFFFFu;
  uint8_t* best_record = nullptr;
  int32_t best_dot = 0, best_cross = 0;  // below 2^25: their products fit 64 bits (one SMULL each)
  // A fresh vertex (no triangle used it) is not tried: that would mean walking the ring.
  auto consider = [&](uint32_t q, uint8_t* rq) {
    const int32_t qx = load_u16(rq) >> S, qy = load_u16(rq + 2) >> S;
    const int32_t x1 = ax - qx, y1 = ay - qy, x2 = sx - qx, y2 = sy - qy;
    const int32_t cross = (x1 * y2 - y1 * x2) * side;
    if (cross <= 0) return;
    const int32_t dot = x1 * x2 + y1 * y2;
    if (best == 0xFFFFFFFFu || int64_t(dot) * best_cross < int64_t(best_dot) * cross) {
      best = q;
      best_record = rq;
      best_dot = dot;
      best_cross = cross;
    }
  };
  uint8_t* ends[2] = {ra, rs};
  for (uint8_t* e : ends) {
    const uint32_t sides = sides_byte(e, nv);
    for (int j = 0; j < 2; ++j) {
      if (!((sides >> (2 * j)) & 3u)) continue;
      const uint32_t q = load_u16(e + edges_at(uint32_t(nv)) + 2 * j);
      if (q <= a || q == s || q == best) continue;
      uint8_t* rq = record(q);
      if (rq) consider(q, rq);
    }
  }
  *record_out = best_record;
  return best;
}

// The vertex after `a` that `count` eligible unused ones precede: in the ring, those whose values
// are not decoded (no triangle used them) and whose column is in `cols`; beyond the ring, every
// one (pinned ones included, the encoder counts them alike). V (out of range) when `a + 1` is
// older than the ring. The walk skips runs of used vertices by their known bytes: a used vertex's
// byte k (1 .. 255) says it and the k - 1 after it are used (values are never undecoded, and all of
// them are below decoded_, so in the ring while it is); each run's first byte is set to the run's
// length as the walk finds it (capped at 255), so later walks skip it in one step. The walk ends
// past a + compressed_fresh_reach (at most that many steps): a farther result is refused by next().
uint64_t LayerDecoderState::fresh(uint32_t a, uint32_t count, Columns cols) {
  const int S = config::subpixel_bits;
  const uint32_t known_at = 4 + 2 * uint32_t(blob_->values_per_vertex);
  const uint32_t skips = edges_at(uint32_t(blob_->values_per_vertex));
  uint32_t r = a + 1;
  // The walk stops past a + compressed_fresh_reach (no vertex there can be the one) or at decoded_.
  const uint32_t end =
      decoded_ > a && decoded_ - a > compressed_fresh_reach + 1 ? a + compressed_fresh_reach + 1 : decoded_;
  if (r < end) {
    const uint32_t window = layer_->window, bytes = record_;
    uint8_t* const ring = ring_;
    const uint32_t back = decoded_ - r;
    if (back > window) return layer_->vertex_count;
    const uint32_t slot = ring_slot(back, window);
    const size_t span = size_t(window) * bytes;
    uint8_t* const ring_end = ring + span;
    uint8_t* p = ring + size_t(slot) * bytes;
    const int32_t lo = cols.lo, hi = cols.hi;
    while (r < end) {
      uint32_t k = p[known_at];
      if (k) {
        uint8_t* const first = p;
        uint32_t run = 0;
        do {
          run += k;
          r += k;
          p += size_t(k) * bytes;  // k <= decoded_ - r before the step, so within one wrap
          if (p >= ring_end) p -= span;
          if (r >= end) break;
          k = p[known_at];
        } while (k);
        first[known_at] = uint8_t(run < 255 ? run : 255);
        continue;
      }
      // An unused vertex: counted when in the columns, else the rest of its row (right of hi) or
      // of its 32-pixel block (left of lo) is skipped when the row is complete.
      const uint32_t x = load_u16(p);
      uint32_t step = 1;
      if (int32_t(x) < lo) {
        const uint32_t skip = load_u16(p + skips + 2);
        if (skip && int32_t(((x >> (S + 5)) + 1) << (S + 5)) <= lo) step = skip;
      } else if (int32_t(x) > hi) {
        const uint32_t skip = load_u16(p + skips);
        if (skip && int32_t((x >> S) << S) > hi) step = skip;
      } else {
        if (count == 0) return r;
        --count;
      }
      r += step;
      p += size_t(step) * bytes;  // the skips point before decoded_: within one wrap
      if (p >= ring_end) p -= span;
    }
  }
  return uint64_t(r) + count;
}

// Records the edge from->to (from < to) of a decoded triangle whose third corner is on its
// positive side or not: a side already known closes the edge (both triangles decoded), else it
// becomes the most recent open edge of `from`, the oldest of two dropped.
__attribute__((always_inline)) inline void LayerDecoderState::add_edge(uint8_t* rec, uint32_t to, bool positive) {
  const int nv = blob_->values_per_vertex;
  uint8_t* ends = rec + edges_at(uint32_t(nv));
  const uint32_t bit = positive ? 1u : 2u;
  uint32_t sides = sides_byte(rec, nv);
  for (int j = 0; j < 2; ++j) {
    const uint32_t m = (sides >> (2 * j)) & 3u;
    if (!m || load_u16(ends + 2 * j) != to) continue;
    if ((m | bit) != 3u) return;  // the same side again (a mesh that is not a manifold)
    if (j == 0) {  // the second moves up
      ends[0] = ends[2], ends[1] = ends[3];
      sides >>= 2;
    } else {
      sides &= 3u;
    }
    sides_byte(rec, nv) = uint8_t(sides);
    return;
  }
  ends[2] = ends[0], ends[3] = ends[1];
  store_u16(ends, to);
  sides_byte(rec, nv) = uint8_t(((sides << 2) & 0xCu) | bit);
}

Status LayerDecoderState::next(DecodedTriangle* out) {
  using namespace detail;
  if (!layer_ || !out) return Status::null_argument;
  if (failed_ != Status::ok) return failed_;
  if (triangles_ >= layer_->triangle_count) return Status::bad_params;
  const uint32_t V = layer_->vertex_count;
  const int nv = blob_->values_per_vertex;
  int64_t s;
  const uint32_t step = decode_symbol8(rc_, m_.top[previous_picks_]);
  if (step < 4) {
    s = step == 3 ? -1 : int64_t(step);
  } else {
    if (step != 7) return fail(Status::bad_index);
    if (!decode_int(rc_, m_.top_far, index_bits, &s)) return fail(Status::bad_index);
  }
  const uint32_t step_class = step < 2 ? step : 2;
  const int64_t a = int64_t(previous_top_) + s;
  if (a < 0 || a >= V) return fail(Status::bad_index);
  uint8_t* const ra = record(uint32_t(a));
  // The anchor: one of a's open edges (its third corner on the side not decoded yet) or a gap.
  const uint32_t pick = decode_symbol8(rc_, m_.anchor[step_class]);
  uint64_t anchor;
  int side;
  uint32_t kind;
  if (pick == escape_symbol) {
    uint32_t gap;
    if (!decode_uint(rc_, m_.anchor_gap, index_bits, &gap)) return fail(Status::bad_index);
    anchor = uint64_t(a) + 1 + gap;
    side = decode_bit(rc_, m_.side) ? -1 : 1;
    kind = 2;
  } else {
    const uint32_t m = pick < 2 && ra ? (sides_byte(ra, nv) >> (2 * pick)) & 3u : 0;
    if (!m) return fail(Status::bad_index);
    anchor = load_u16(ra + edges_at(uint32_t(nv)) + 2 * pick);
    side = m == 1 ? -1 : 1;
    kind = pick;
  }
  if (anchor >= V) return fail(Status::bad_index);
  // The third corner: predicted, else a fresh vertex by its count among the unused ones after a,
  // else a gap.
  uint8_t* const rs = record(uint32_t(anchor));
  const Columns cols = columns(ra, rs);
  uint8_t* guess_record;
  const uint32_t guess = predict(uint32_t(a), uint32_t(anchor), ra, rs, side, &guess_record);
  uint64_t third;
  bool hit = false;
  if (guess != 0xFFFFFFFFu && decode_bit(rc_, m_.predicted[kind])) {
    third = guess;
    hit = true;
  } else if (decode_bit(rc_, m_.fresh[kind])) {
    uint32_t count;
    if (!decode_uint(rc_, m_.fresh_count, index_bits, &count)) return fail(Status::bad_index);
    third = fresh(uint32_t(a), count, cols);
    if (third - uint64_t(a) > compressed_fresh_reach) return fail(Status::bad_index);
  } else {
    uint32_t gap;
    if (!decode_uint(rc_, m_.third_gap, index_bits, &gap)) return fail(Status::bad_index);
    third = uint64_t(a) + 1 + gap;
  }
  if (third >= V || third == anchor) return fail(Status::bad_index);
  const uint32_t b = uint32_t(anchor < third ? anchor : third), c = uint32_t(anchor < third ? third : anchor);
  if (rc_.overrun) return fail(Status::truncated);
  const uint32_t index[3] = {uint32_t(a), uint32_t(b), uint32_t(c)};
  const uint32_t before = decoded_;
  for (int k = 0; k < 3; ++k)
    if (index[k] >= decoded_ && !pinned_record(index[k])) {
      const Status st = place(index[k]);
      if (st != Status::ok) return st;
    }
  // Every corner must be in the ring (the window the header promised) or pinned. When every corner
  // was in the ring already, the records found above still hold (the ring did not move): a's,
  // the anchor's and a predicted third corner's.
  uint8_t* rec[3];
  if (decoded_ == before && c < before && ra && rs) {
    uint8_t* const rt = hit ? guess_record : record(uint32_t(third));
    if (!rt) return fail(Status::bad_index);
    rec[0] = ra;
    rec[1] = b == anchor ? rs : rt;
    rec[2] = b == anchor ? rt : rs;
  } else {
    for (int k = 0; k < 3; ++k)
      if (!(rec[k] = record(index[k]))) return fail(Status::bad_index);
  }
  const int64_t xa = load_u16(rec[0]), ya = load_u16(rec[0] + 2);
  const int64_t area = (int64_t(load_u16(rec[1])) - xa) * (int64_t(load_u16(rec[2] + 2)) - ya) -
                       (int64_t(load_u16(rec[1] + 2)) - ya) * (int64_t(load_u16(rec[2])) - xa);
  if (area == 0) return fail(Status::bad_triangle);
  // The rotation the v1 blob stored of the cyclic order with positive area.
  uint32_t r = 0;
  if (decode_bit(rc_, m_.rotation[0])) r = 1 + decode_bit(rc_, m_.rotation[1]);
  uint16_t flags = 0;
  if (decode_bit(rc_, m_.flags_nonzero))
    for (int i = 0; i < 9; ++i) flags = uint16_t(flags | (decode_bit(rc_, m_.flag_bit[i]) << i));
  if (rc_.overrun) return fail(Status::truncated);
  // The corners' values not decoded yet, in index order, from the corners known before them.
  for (int k = 0; k < 3; ++k) {
    if (known_byte(rec[k], nv)) continue;
    const uint8_t* known[2] = {nullptr, nullptr};
    for (int j = 0, n = 0; j < 3; ++j)
      if (j != k && known_byte(rec[j], nv)) known[n++] = rec[j];
    const Status st = decode_values(rec[k], index[k], known[0], known[1]);
    if (st != Status::ok) return st;
  }
  const bool z = blob_->method == Method::zienkiewicz;
  // Corner k of the v1 order: the positive cyclic order, (0, 1, 2) or (0, 2, 1), rotated by r.
  static constexpr uint8_t order[2][3][3] = {{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}, {{0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  const uint8_t* const corners = order[area > 0 ? 0 : 1][r];
  int32_t top = 0x7FFFFFFF;
  for (int k = 0; k < 3; ++k) {
    const int corner = corners[k];
    const uint8_t* p = rec[corner];
    out->v[k] = index[corner];
    const uint16_t y = load_u16(p + 2);
    out->x[k] = load_u16(p);
    out->y[k] = y;
    top = y < top ? y : top;
    if (nv == 1) {
      out->values[k][0] = load_u16(p + 4);
      out->values[k][1] = out->values[k][2] = 0;
    } else {
      out->values[k][0] = load_u16(p + 4);
      out->values[k][1] = load_u16(p + 6);
      out->values[k][2] = load_u16(p + 8);
    }
    if (z) {
      int32_t* g = &out->gradients[k][0][0];
      for (int i = 0; i < 6; ++i) g[i] = 0;
      for (int ch = 0; ch < nv; ++ch) {
        const uint8_t* q = p + gradients_at(uint32_t(nv)) + 8 * ch;
        g[2 * ch] = int32_t(load_u32(q));
        g[2 * ch + 1] = int32_t(load_u32(q + 4));
      }
    }
  }
  out->flags = flags;
  for (int k = 0; k < 3; ++k) out->tag[k] = tags_ ? tag_of(out->v[k]) : nullptr;
  if (top < previous_row_) return fail(Status::unsorted);
  previous_row_ = top;
  previous_top_ = uint32_t(a);
  previous_picks_ = uint8_t(2 * kind + (hit ? 1 : 0));
  // (a, b, c) has the sign of `area`; (a, c, b) the other.
  add_edge(rec[0], index[1], area > 0);
  add_edge(rec[0], index[2], area < 0);
  add_edge(rec[1], index[2], area > 0);
  ++triangles_;
  return Status::ok;
}

Status LayerDecoderState::finish() {
  if (!layer_) return Status::null_argument;
  if (failed_ != Status::ok) return failed_;
  if (triangles_ != layer_->triangle_count) return Status::bad_params;
  while (decoded_ < layer_->vertex_count) {
    const Status st = decode_position();
    if (st != Status::ok) return st;
  }
  // The values no triangle asked for, of the vertices still in the ring.
  const uint32_t V = layer_->vertex_count, first = V > layer_->window ? V - layer_->window : 0;
  for (uint32_t i = first; i < V; ++i) {
    uint8_t* rec = record(i);
    if (known_byte(rec, blob_->values_per_vertex)) continue;
    const Status st = decode_values(rec, i, nullptr, nullptr);
    if (st != Status::ok) return st;
  }
  if (rc_.overrun) return fail(Status::truncated);
  if (rc_.p != rc_.end) return fail(Status::bad_section);  // bytes after the stream's end
  return Status::ok;
}

static_assert(sizeof(LayerDecoderState) == layer_decoder_bytes,
              "layer_decoder_bytes (compressed_blob.h) must be the size of LayerDecoderState for this target");
static_assert(alignof(LayerDecoderState) == layer_decoder_align, "layer_decoder_align must be its alignment");
static_assert(__is_trivial(LayerDecoderState), "a LayerDecoder lives in caller memory without construction");

LayerDecoderState& LayerDecoder::state() { return *reinterpret_cast<LayerDecoderState*>(state_); }
const LayerDecoderState& LayerDecoder::state() const { return *reinterpret_cast<const LayerDecoderState*>(state_); }

Status LayerDecoder::begin(const CompressedBlob& blob, int layer, void* ring, size_t ring_bytes, VertexSink sink,
                           void* sink_context) {
  return state().begin(blob, layer, ring, ring_bytes, sink, sink_context);
}
void LayerDecoder::keep_tags(uint16_t* tags) { state().keep_tags(tags); }
Status LayerDecoder::next(DecodedTriangle* out) { return state().next(out); }
Status LayerDecoder::finish() { return state().finish(); }
uint32_t LayerDecoder::offset() const { return state().offset(); }

namespace {

// v1 section offsets of one layer (the packer's layout: each section 4-aligned, in this order).
struct V1Layer {
  uint32_t positions, values, gradients, triangles, end;
};

V1Layer v1_layer(const CompressedBlob& blob, const CompressedLayer& l, uint32_t at) {
  V1Layer o;
  const uint32_t nv = blob.values_per_vertex;
  o.positions = at;
  o.values = wire::align_section(o.positions + wire::position::bytes * l.vertex_count);
  o.gradients = wire::align_section(o.values + wire::value::bytes * l.vertex_count * nv);
  o.triangles = blob.method == Method::zienkiewicz ? o.gradients + wire::gradient::bytes * l.vertex_count * nv
                                                   : o.gradients;
  o.end = o.triangles + wire::triangle::bytes * l.triangle_count;
  if (blob.method != Method::zienkiewicz) o.gradients = 0;
  return o;
}

struct ExpandSink {
  uint8_t* out;
  V1Layer layer;
  int per_vertex;
  bool gradients;
};

void expand_vertex(void* context, uint32_t index, uint16_t x, uint16_t y, const uint16_t* values,
                   const int32_t* gradients) {
  const ExpandSink* s = static_cast<const ExpandSink*>(context);
  uint8_t* p = s->out + s->layer.positions + wire::position::bytes * index;
  store_u16(p + wire::position::x, x);
  store_u16(p + wire::position::y, y);
  for (int c = 0; c < s->per_vertex; ++c) {
    const uint32_t k = index * uint32_t(s->per_vertex) + uint32_t(c);
    store_u16(s->out + s->layer.values + wire::value::bytes * k, values[c]);
    if (s->gradients) {
      uint8_t* g = s->out + s->layer.gradients + wire::gradient::bytes * k;
      store_u32(g + wire::gradient::gx, uint32_t(gradients[2 * c]));
      store_u32(g + wire::gradient::gy, uint32_t(gradients[2 * c + 1]));
    }
  }
}

}  // namespace

size_t expanded_blob_size(const CompressedBlob& blob) {
  uint32_t at = wire::header::bytes + wire::v1_layer::bytes * blob.layer_count;
  for (int l = 0; l < blob.layer_count; ++l) at = v1_layer(blob, blob.layers[l], at).end;
  return at;
}

size_t expand_workspace_size(const CompressedBlob& blob) {
  size_t most = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    const size_t n = compressed_ring_bytes(blob, l);
    most = n > most ? n : most;
  }
  return most;
}

Status expand_compressed_blob(const CompressedBlob& blob, void* out, size_t out_bytes, void* workspace,
                              size_t workspace_bytes, BlobError* error) {
  if (!out || !workspace) return Status::null_argument;
  const size_t size = expanded_blob_size(blob);
  if (out_bytes < size) return Status::workspace_too_small;
  // The ring in the workspace is read while the blob is written: they must share no byte.
  const uintptr_t o = reinterpret_cast<uintptr_t>(out), w = reinterpret_cast<uintptr_t>(workspace);
  if (workspace_bytes && (o <= w ? w - o < out_bytes : o - w < workspace_bytes)) return Status::bad_params;
  uint8_t* b = static_cast<uint8_t*>(out);
  for (size_t i = 0; i < size; ++i) b[i] = 0;
  namespace h = wire::header;
  namespace L = wire::v1_layer;
  wire::put_magic(b + h::magic, wire::v1_magic);
  store_u16(b + h::version, blob_version);
  store_u16(b + h::header_size, h::bytes);
  store_u32(b + h::total_size, uint32_t(size));
  for (uint32_t k = h::shared_begin; k < h::shared_end; ++k) b[k] = blob.bytes[k];
  store_u32(b + h::layer_table, h::bytes);
  uint32_t at = h::bytes + L::bytes * blob.layer_count;
  LayerDecoder decoder;  // set by begin
  for (int l = 0; l < blob.layer_count; ++l) {
    const CompressedLayer& cl = blob.layers[l];
    const V1Layer o = v1_layer(blob, cl, at);
    at = o.end;
    uint8_t* e = b + h::bytes + L::bytes * uint32_t(l);
    store_u32(e + L::vertex_count, cl.vertex_count);
    store_u32(e + L::triangle_count, cl.triangle_count);
    store_u32(e + L::positions, o.positions);
    store_u32(e + L::values, o.values);
    store_u32(e + L::gradients, o.gradients);
    store_u32(e + L::triangles, o.triangles);
    ExpandSink sink{b, o, blob.values_per_vertex, blob.method == Method::zienkiewicz};
    Status s = decoder.begin(blob, l, workspace, workspace_bytes, expand_vertex, &sink);
    if (s != Status::ok) return s;
    DecodedTriangle t;
    for (uint32_t k = 0; k < cl.triangle_count; ++k) {
      s = decoder.next(&t);
      if (s != Status::ok) {
        if (error) error->offset = decoder.offset();
        return s;
      }
      uint8_t* p = b + o.triangles + wire::triangle::bytes * k;
      for (uint32_t c = 0; c < 3; ++c) store_u16(p + wire::triangle::corner(c), t.v[c]);
      store_u16(p + wire::triangle::flags, t.flags);
    }
    s = decoder.finish();
    if (s != Status::ok) {
      if (error) error->offset = decoder.offset();
      return s;
    }
  }
  store_u32(b + h::checksum, blob_checksum(b, uint32_t(size)));
  // The decoder's checks are those of open_blob; it confirms them on the result.
  Blob check;
  BlobError where;
  const Status s = open_blob(b, size, &check, &where);
  if (s != Status::ok && error) error->offset = where.offset;
  return s;
}

}  // namespace tristream::core
