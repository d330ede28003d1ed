/* SPDX-License-Identifier: MIT */
#pragma once
// The band store of a compressed blob's render: the live triangles of one layer for the current
// band, as a small v1-shaped layer in the caller's workspace (positions, values, gradients,
// triangles with u16 indices, and the active-set bitmap), which the active set, the tile cull and
// the tile renderer read as they read a v1 blob's layer.
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "output_mapping.h"
#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "tristream/detail/arith.h"
#include "tristream/fixed_point.h"
#include "workspace_layout.h"

namespace tristream::core::detail {
namespace {

// Self-contained records: triangle i owns vertices 3i, 3i + 1, 3i + 2 (its corners in v1 order),
// so the store needs no map from stream indices to its own and a triangle moves as one block. The
// u16 indices bound a band to 21,845 live triangles.
constexpr uint32_t band_store_max_triangles = 65535 / 3;

constexpr size_t align4_size(size_t n) { return (n + 3) / 4 * 4; }

// Bytes of a store of `capacity` triangles: 4 bytes of position, 2 per value and 8 per gradient
// pair for each of the 3 capacity vertices, 8 per triangle, one bit per triangle in 32-bit words;
// each section 4-aligned.
inline size_t band_store_bytes(uint32_t capacity, uint32_t values_per_vertex, bool gradients) {
  const size_t v = size_t(3) * capacity;
  return 4 * v + align4_size(2 * v * values_per_vertex) + (gradients ? 8 * v * values_per_vertex : 0) +
         size_t(blob_triangle_size) * capacity + bitmap_bytes(capacity);
}

// The most triangles a store of `bytes` holds (at most band_store_max_triangles).
inline uint32_t band_store_capacity(size_t bytes, uint32_t values_per_vertex, bool gradients) {
  const size_t per = 12 + 6 * values_per_vertex + (gradients ? 24 * values_per_vertex : 0) + blob_triangle_size;
  size_t c = bytes / per;  // band_store_bytes(c) >= per * c: an upper bound, a few too many at most
  if (c > band_store_max_triangles) c = band_store_max_triangles;
  while (c > 0 && band_store_bytes(uint32_t(c), values_per_vertex, gradients) > bytes) --c;
  return uint32_t(c);
}

// First and last pixel row of a triangle with raw y coordinates y0, y1, y2 (as row_extent).
inline void raw_row_extent(const Mapping& map, int32_t y0, int32_t y1, int32_t y2, int32_t* top, int32_t* bottom) {
  *top = position_fx::from_raw(map.y(min3(y0, y1, y2))).ceil_to_int();
  *bottom = position_fx::from_raw(map.y(max3(y0, y1, y2))).floor_to_int();
}

inline void decoded_row_extent(const Mapping& map, const DecodedTriangle& t, int32_t* top, int32_t* bottom) {
  raw_row_extent(map, t.y[0], t.y[1], t.y[2], top, bottom);
}

struct BandStore {
  BlobLayer* layer = nullptr;  // the view the tile path reads; triangle_count is the store's count
  uint32_t capacity = 0;
  uint32_t values_per_vertex = 1;
  bool has_gradients = false;
  uint8_t* positions = nullptr;
  uint8_t* values = nullptr;
  uint8_t* gradients = nullptr;
  uint8_t* triangles = nullptr;
  uint32_t* words = nullptr;  // bitmap_bytes(capacity) bytes

  // `at` is 4-aligned and holds band_store_bytes(capacity, ...) bytes.
  void init(uint8_t* at, uint32_t cap, uint32_t per_vertex, bool with_gradients, BlobLayer* view) {
    capacity = cap;
    values_per_vertex = per_vertex;
    has_gradients = with_gradients;
    const size_t v = size_t(3) * cap;
    positions = at;
    values = positions + 4 * v;
    gradients = values + align4_size(2 * v * per_vertex);
    triangles = gradients + (with_gradients ? 8 * v * per_vertex : 0);
    words = reinterpret_cast<uint32_t*>(triangles + size_t(blob_triangle_size) * cap);
    layer = view;
    layer->vertex_count = layer->triangle_count = 0;
    layer->positions = positions;
    layer->values = values;
    layer->gradients = with_gradients ? gradients : nullptr;
    layer->triangles = triangles;
  }

  uint32_t count() const { return layer->triangle_count; }
  void set_count(uint32_t n) {
    layer->triangle_count = n;
    layer->vertex_count = 3 * n;
  }

  // Appends a triangle (count() < capacity).
  void append(const DecodedTriangle& t) {
    const uint32_t i = count();
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(3) * i + size_t(k);
      store16(positions + 4 * v, t.x[k]);
      store16(positions + 4 * v + 2, t.y[k]);
      for (uint32_t c = 0; c < values_per_vertex; ++c) {
        store16(values + 2 * (v * values_per_vertex + c), t.values[k][c]);
        if (has_gradients) {
          uint8_t* g = gradients + 8 * (v * values_per_vertex + c);
          store32(g, uint32_t(t.gradients[k][c][0]));
          store32(g + 4, uint32_t(t.gradients[k][c][1]));
        }
      }
    }
    write_triangle(i, t.flags);
    set_count(i + 1);
  }

  // Drops the triangles whose last row is above y0, keeping the others in order.
  void drop_ended(const Mapping& map, int32_t y0) {
    const uint32_t n = count();
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n; ++i) {
      const uint8_t* p = positions + 12 * size_t(i);
      int32_t top, bottom;
      raw_row_extent(map, load16(p + 2), load16(p + 6), load16(p + 10), &top, &bottom);
      if (bottom < y0) continue;
      if (kept != i) move(i, kept);
      ++kept;
    }
    set_count(kept);
  }

  // Marks every triangle of the store live in the active-set bitmap.
  void mark_all_live() {
    const uint32_t n = count();
    for (uint32_t w = 0; w < n / 32; ++w) words[w] = 0xFFFFFFFFu;
    if (n % 32) words[n / 32] = (1u << (n % 32)) - 1;
  }

 private:
  static void store16(uint8_t* p, uint16_t v) {
    p[0] = uint8_t(v);
    p[1] = uint8_t(v >> 8);
  }
  static void store32(uint8_t* p, uint32_t v) {
    store16(p, uint16_t(v));
    store16(p + 2, uint16_t(v >> 16));
  }
  static int32_t load16(const uint8_t* p) { return int32_t(p[0] | (p[1] << 8)); }

  void write_triangle(uint32_t i, uint16_t flags) {
    uint8_t* p = triangles + size_t(blob_triangle_size) * i;
    for (uint32_t k = 0; k < 3; ++k) store16(p + 2 * k, uint16_t(3 * i + k));
    store16(p + 6, flags);
  }

  // Moves triangle `from` to slot `to` < from (the slots do not overlap).
  void move(uint32_t from, uint32_t to) {
    // Copies of constant sizes, which compilers inline (a call per block costs more than its bytes).
    memcpy(positions + 12 * size_t(to), positions + 12 * size_t(from), 12);
    if (values_per_vertex == 1) {
      memcpy(values + 6 * size_t(to), values + 6 * size_t(from), 6);
      if (has_gradients) memcpy(gradients + 24 * size_t(to), gradients + 24 * size_t(from), 24);
    } else {
      memcpy(values + 18 * size_t(to), values + 18 * size_t(from), 18);
      if (has_gradients) memcpy(gradients + 72 * size_t(to), gradients + 72 * size_t(from), 72);
    }
    const uint8_t* f = triangles + size_t(blob_triangle_size) * from;
    write_triangle(to, uint16_t(f[6] | (f[7] << 8)));
  }
};

}  // namespace
}  // namespace tristream::core::detail
