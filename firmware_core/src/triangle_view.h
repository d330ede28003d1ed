/* SPDX-License-Identifier: MIT */
#pragma once
// Reading triangles and vertex values from a validated blob layer: a triangle's vertices in
// output positions, its rows, and the values of a vertex.
#include <stddef.h>
#include <stdint.h>

#include "output_mapping.h"
#include "triangle_records.h"
#include "tristream/blob.h"
#include "arith.h"
#include "bytes.h"
#include "tuning.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

// A triangle of a layer with its vertices in output position_fx.
struct TriangleView {
  uint16_t v[3];
  uint16_t flags;
  int32_t x[4], y[4];  // x[3], y[3]: 0 (whole vectors for SSE2)
};

// Triangle t of the layer, whose records are laid out as Records (triangle_records.h).
template <typename Records>
inline void load_triangle(const BlobLayer& layer, uint32_t t, const Mapping& map, TriangleView* tv) {
  const uint8_t* p = layer.triangles + size_t(t) * Records::stride;
  TS_UNROLL
  for (int k = 0; k < 3; ++k) {
    tv->v[k] = uint16_t(Records::vertex(p, k));
    const uint8_t* pos = layer.positions + 4 * size_t(tv->v[k]);
    tv->x[k] = map.x(load_u16_even(pos));
    tv->y[k] = map.y(load_u16_even(pos + 2));
  }
  tv->flags = Records::flags(p);
  tv->x[3] = tv->y[3] = 0;
}

// The domain (unmapped) y of triangle t's vertices (of a v1 blob's layer).
TS_INLINE inline void raw_ys(const BlobLayer& layer, uint32_t t, int32_t y[3]) {
  const uint8_t* p = layer.triangles + size_t(t) * blob_triangle_size;
  y[0] = load_u16_even(layer.positions + 4 * size_t(load_u16_even(p)) + 2);
  y[1] = load_u16_even(layer.positions + 4 * size_t(load_u16_even(p + 2)) + 2);
  y[2] = load_u16_even(layer.positions + 4 * size_t(load_u16_even(p + 4)) + 2);
}

// First and last pixel row whose sample points may lie in the triangle.
inline void row_extent(const BlobLayer& layer, uint32_t t, const Mapping& map, int32_t* top, int32_t* bottom) {
  int32_t y[3];
  raw_ys(layer, t, y);
  *top = position_fx::from_raw(map.y(min3(y[0], y[1], y[2]))).ceil_to_int();
  *bottom = position_fx::from_raw(map.y(max3(y[0], y[1], y[2]))).floor_to_int();
}

// The largest domain y of triangle t's vertices: its last row is at or below row y exactly when
// this is at least map.first_y_at_least(y * 2^S).
inline int32_t raw_max_y(const BlobLayer& layer, uint32_t t) {
  int32_t y[3];
  raw_ys(layer, t, y);
  return max3(y[0], y[1], y[2]);
}

// Values of vertex v for `channels` channels starting at `first` (q8_8).
inline void vertex_values(const BlobLayer& layer, int per_vertex, int first, int channels, uint16_t v, int32_t* out) {
  const uint8_t* p = layer.values + 2 * (size_t(v) * per_vertex + first);
  for (int c = 0; c < channels; ++c) out[c] = load_u16_even(p + 2 * c);
}

}  // namespace
}  // namespace tristream::core::detail
