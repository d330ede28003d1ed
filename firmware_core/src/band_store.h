/* SPDX-License-Identifier: MIT */
#pragma once
// The band store of a compressed blob's render: the live triangles of one layer for the current
// band, as a small v1-shaped layer in the caller's workspace (positions, values, gradients,
// triangles with u16 indices, and the active-set bitmap), which the active set, the tile cull and
// the tile renderer read as they read a v1 blob's layer. Each live vertex is stored once: the
// triangles' indices are store slots, found from the decoder's stream indices by a map.
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "output_mapping.h"
#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "tristream/detail/arith.h"
#include "tristream/fixed_point.h"
#include "tristream/status.h"
#include "workspace_layout.h"

namespace tristream::core::detail {
namespace {

// Slots are u16 and 0xFFFF marks a free map entry, so a store holds at most 65,535 vertices: a
// layer's vertex count (blob_max_vertices), so the indices never bound a band. Triangles are
// bounded only by the workspace (the active set counts them in u32).
constexpr uint32_t band_store_max_vertices = 65535;
static_assert(band_store_max_vertices >= blob_max_vertices, "every vertex of a layer fits the u16 slots");
constexpr uint16_t band_store_free = 0xFFFF;

constexpr size_t align4_size(size_t n) { return (n + 3) / 4 * 4; }

// Bytes of `slots` vertex slots: 4 of position, 2 per value, 8 per gradient pair, 2 of stream
// index (the map's key), each array 4-aligned.
inline size_t band_vertex_bytes(uint32_t slots, uint32_t values_per_vertex, bool gradients) {
  const size_t n = slots;
  return 4 * n + align4_size(2 * n * values_per_vertex) + (gradients ? 8 * n * values_per_vertex : 0) +
         align4_size(2 * n);
}

// Bytes a store needs to hold V vertices and C triangles: the vertex slots, 8 per triangle, and
// the larger of the map (2 V u16 entries, used while the band's triangles are taken) and the
// active-set bitmap (C bits in 32-bit words, used while the band is drawn), which share memory.
inline size_t band_store_bytes(uint32_t vertices, uint32_t triangles, uint32_t values_per_vertex, bool gradients) {
  const size_t map = 4 * size_t(vertices), bits = bitmap_bytes(triangles);
  return band_vertex_bytes(vertices, values_per_vertex, gradients) + size_t(blob_triangle_size) * triangles +
         (map > bits ? map : bits);
}

// Last pixel row of a triangle with raw y coordinates y0, y1, y2 (a triangle's end, all that
// dropping it needs).
inline int32_t raw_row_bottom(const Mapping& map, int32_t y0, int32_t y1, int32_t y2) {
  return position_fx::from_raw(map.y(max3(y0, y1, y2))).floor_to_int();
}

// First and last pixel row of such a triangle (as row_extent).
inline void raw_row_extent(const Mapping& map, int32_t y0, int32_t y1, int32_t y2, int32_t* top, int32_t* bottom) {
  *top = position_fx::from_raw(map.y(min3(y0, y1, y2))).ceil_to_int();
  *bottom = raw_row_bottom(map, y0, y1, y2);
}

inline void decoded_row_extent(const Mapping& map, const DecodedTriangle& t, int32_t* top, int32_t* bottom) {
  raw_row_extent(map, t.y[0], t.y[1], t.y[2], top, bottom);
}

// The store in `bytes` of workspace: [vertex slots for `slots` vertices: positions, values,
// gradients, keys][triangles, growing]...[map: 2 slots u16 entries at the end]. Its need is
// band_store_bytes(vertices, triangles) at every moment, whatever the slack: slots grow when a further
// vertex finds none free (the arrays after the positions and the triangles move up), and shrink to
// the vertex count when the triangles or the bitmap would not fit otherwise, so a store of `bytes`
// takes every band whose need is at most `bytes`. Invariant between calls: 4 slots bytes of map fit
// after the triangles.
// Its fields are few (the render's stack holds three stores): the positions are at `base`, the
// other sections' addresses follow from `slots`.
struct BandStore {
  BlobLayer* layer = nullptr;  // the view the tile path reads; triangle_count is the store's count
  uint8_t* base = nullptr;     // 4-aligned; the positions
  size_t bytes = 0;            // a multiple of 4
  uint32_t slots = 0;          // vertex capacity of the current layout
  uint32_t vertices = 0;       // slots in use: [0, vertices)
  uint32_t added = 0;          // vertices added in the current band
  uint16_t* keys = nullptr;    // stream index of each slot
  uint16_t* entries = nullptr;  // 2 slots map entries: a slot, or band_store_free
  uint8_t values_per_vertex = 1;
  bool has_gradients = false;

  void init(uint8_t* at, size_t size, uint32_t per_vertex, bool with_gradients, BlobLayer* view) {
    base = at;
    bytes = size / 4 * 4;
    values_per_vertex = uint8_t(per_vertex);
    has_gradients = with_gradients;
    vertices = added = 0;
    layer = view;
    layer->vertex_count = layer->triangle_count = 0;
    place(0);
    layer->gradients = with_gradients ? gradients() : nullptr;
  }

  uint32_t count() const { return layer->triangle_count; }

  // Starts band [y0, ...]: drops the triangles whose last row is above y0 (keeping the others in
  // order), then the vertices no kept triangle uses (renumbering the kept ones in order), and
  // rebuilds the map with room for about as many added vertices as the band before added.
  void begin_band(const Mapping& map, int32_t y0) {
    drop_ended(map, y0);
    compact_vertices();
    const uint32_t want = vertices + added + added / 4 + 16;
    added = 0;
    const uint32_t fit = most_slots(count());
    relayout(want < fit ? want : fit);  // fit >= vertices: the invariant held for more triangles
  }

  // Appends a triangle (its corners' stream indices looked up, unseen ones stored). Returns
  // workspace_too_small when the band's need passes `bytes`.
  Status append(const DecodedTriangle& t) {
    uint16_t slot[3];
    for (int k = 0; k < 3; ++k) {
      const Status s = vertex_slot(t, k, &slot[k]);
      if (s != Status::ok) return s;
    }
    const uint32_t n = count();
    if (!fits(slots, n + 1, 4 * size_t(slots))) {
      if (slots == vertices) return Status::workspace_too_small;
      relayout(vertices);  // the slack of slots makes room
      if (!fits(slots, n + 1, 4 * size_t(slots))) return Status::workspace_too_small;
    }
    uint8_t* p = triangles() + size_t(blob_triangle_size) * n;
    for (int k = 0; k < 3; ++k) store16(p + 2 * k, slot[k]);
    store16(p + 6, t.flags);
    layer->triangle_count = n + 1;
    return Status::ok;
  }

  // Marks every triangle of the store live in the active-set bitmap, which follows the triangles
  // (over the map, not needed again before the next band's begin_band). Null when it does not fit.
  uint32_t* mark_all_live() {
    const uint32_t n = count();
    if (!fits(slots, n, bitmap_bytes(n))) {
      if (slots == vertices) return nullptr;
      relayout(vertices);
      if (!fits(slots, n, bitmap_bytes(n))) return nullptr;
    }
    uint32_t* words = reinterpret_cast<uint32_t*>(triangles() + size_t(blob_triangle_size) * n);
    for (uint32_t w = 0; w < n / 32; ++w) words[w] = 0xFFFFFFFFu;
    if (n % 32) words[n / 32] = (1u << (n % 32)) - 1;
    return words;
  }

 private:
  uint8_t* values() const { return base + 4 * size_t(slots); }
  uint8_t* gradients() const { return values() + align4_size(2 * size_t(slots) * values_per_vertex); }
  uint8_t* triangles() const { return reinterpret_cast<uint8_t*>(keys) + align4_size(2 * size_t(slots)); }

  // Little-endian (the v1 layout); on a little-endian target one store each.
  static void store16(uint8_t* p, uint16_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    memcpy(p, &v, 2);
#else
    p[0] = uint8_t(v);
    p[1] = uint8_t(v >> 8);
#endif
  }
  static void store32(uint8_t* p, uint32_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    memcpy(p, &v, 4);
#else
    store16(p, uint16_t(v));
    store16(p + 2, uint16_t(v >> 16));
#endif
  }
  static uint16_t load16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }

  // memmove of align4(n) bytes between 4-aligned sections, a word at a time (the C library's
  // memmove on a microcontroller is often a byte loop); the rounding stays inside both sections,
  // which are 4-aligned and at least align4(n) bytes.
  static void move_words(uint8_t* to, const uint8_t* from, size_t n) {
    const size_t words = (n + 3) / 4;
    if (to < from) {
      for (size_t i = 0; i < words; ++i) memcpy(to + 4 * i, from + 4 * i, 4);
    } else if (to > from) {
      for (size_t i = words; i-- > 0;) memcpy(to + 4 * i, from + 4 * i, 4);
    }
  }

  // Whether `cap` slots, n triangles and `tail` bytes after them fit.
  bool fits(uint32_t cap, uint32_t n, size_t tail) const {
    return band_vertex_bytes(cap, values_per_vertex, has_gradients) + size_t(blob_triangle_size) * n + tail <= bytes;
  }
  // The most slots that fit with n triangles and their map.
  uint32_t most_slots(uint32_t n) const {
    const size_t t = size_t(blob_triangle_size) * n;
    if (t >= bytes) return 0;
    const size_t per = 10 + 2 * size_t(values_per_vertex) + (has_gradients ? 8 * size_t(values_per_vertex) : 0);
    size_t c = (bytes - t) / per;  // an upper bound: the sections' rounding only adds
    if (c > band_store_max_vertices) c = band_store_max_vertices;
    while (c > 0 && !fits(uint32_t(c), n, 4 * c)) --c;
    return uint32_t(c);
  }

  // Section addresses for `cap` slots (the map at the end of the store).
  void place(uint32_t cap) {
    const size_t n = cap;
    slots = cap;
    keys = reinterpret_cast<uint16_t*>(gradients() + (has_gradients ? 8 * n * values_per_vertex : 0));
    entries = reinterpret_cast<uint16_t*>(base + bytes - 4 * n);
    layer->positions = base;
    layer->values = values();
    if (has_gradients) layer->gradients = gradients();
    layer->triangles = triangles();
    layer->vertex_count = cap;
  }

  // Moves to a layout of `cap` >= vertices slots (which must fit with the triangles and the map)
  // and rebuilds the map.
  void relayout(uint32_t cap) {
    uint8_t* const old_values = values();
    uint8_t* const old_gradients = gradients();
    uint8_t* const old_keys = reinterpret_cast<uint8_t*>(keys);
    uint8_t* const old_triangles = triangles();
    const size_t nv = vertices, nt = count();
    const size_t value_bytes = 2 * nv * values_per_vertex, gradient_bytes = has_gradients ? 8 * nv * values_per_vertex : 0;
    place(cap);
    uint8_t* const to_values = values();
    uint8_t* const to_gradients = gradients();
    uint8_t* const to_triangles = triangles();
    // The sections after the positions all move the same way: the last first when they move up.
    uint8_t* const to_keys = reinterpret_cast<uint8_t*>(keys);
    if (to_triangles > old_triangles) {
      move_words(to_triangles, old_triangles, size_t(blob_triangle_size) * nt);
      move_words(to_keys, old_keys, 2 * nv);
      if (gradient_bytes) move_words(to_gradients, old_gradients, gradient_bytes);
      move_words(to_values, old_values, value_bytes);
    } else if (to_triangles < old_triangles) {
      move_words(to_values, old_values, value_bytes);
      if (gradient_bytes) move_words(to_gradients, old_gradients, gradient_bytes);
      move_words(to_keys, old_keys, 2 * nv);
      move_words(to_triangles, old_triangles, size_t(blob_triangle_size) * nt);
    }
    rebuild_map();
  }

  // Map entries: 2 slots of them, open addressing with linear probing from a multiplicative hash
  // of the stream index scaled to [0, 2 slots) (a multiply, no division); at most half full, so a
  // probe ends.
  uint32_t home(uint16_t key) const {
    return uint32_t((uint64_t(uint32_t(key) * 0x9E3779B1u) * (2 * uint64_t(slots))) >> 32);
  }
  uint32_t free_entry(uint16_t key) const {
    const uint32_t h_end = 2 * slots;
    uint32_t h = home(key);
    while (entries[h] != band_store_free)
      if (++h == h_end) h = 0;
    return h;
  }
  void rebuild_map() {
    for (uint32_t h = 0; h < 2 * slots; ++h) entries[h] = band_store_free;
    for (uint32_t s = 0; s < vertices; ++s) entries[free_entry(keys[s])] = uint16_t(s);
  }

  // The slot of corner k of t: found in the map, or a free slot (more slots if none is free).
  Status vertex_slot(const DecodedTriangle& t, int k, uint16_t* out) {
    if (t.v[k] >= band_store_max_vertices) return Status::bad_index;  // never from a decoder (< vertex count)
    const uint16_t key = uint16_t(t.v[k]);
    if (slots) {
      const uint32_t h_end = 2 * slots;
      uint32_t h = home(key);
      for (uint16_t e; (e = entries[h]) != band_store_free;) {
        if (keys[e] == key) {
          *out = e;
          return Status::ok;
        }
        if (++h == h_end) h = 0;
      }
    }
    if (vertices == slots) {
      // Up to half of the slots that fit, so that the triangles keep room and a band near the
      // store's end does not move the arrays for every vertex.
      const uint32_t fit = most_slots(count());
      if (fit <= vertices) return Status::workspace_too_small;
      const uint32_t half = (fit - vertices + 1) / 2, step = vertices / 2 + 16;
      relayout(vertices + (step < half ? step : half));
    }
    const uint32_t s = vertices++;
    ++added;
    entries[free_entry(key)] = uint16_t(s);
    keys[s] = key;
    store16(base + 4 * size_t(s), t.x[k]);
    store16(base + 4 * size_t(s) + 2, t.y[k]);
    uint8_t* const v = values();
    uint8_t* const g = gradients();
    for (uint32_t c = 0; c < values_per_vertex; ++c) {
      const size_t i = size_t(s) * values_per_vertex + c;
      store16(v + 2 * i, t.values[k][c]);
      if (has_gradients) {
        store32(g + 8 * i, uint32_t(t.gradients[k][c][0]));
        store32(g + 8 * i + 4, uint32_t(t.gradients[k][c][1]));
      }
    }
    *out = uint16_t(s);
    return Status::ok;
  }

  void drop_ended(const Mapping& map, int32_t y0) {
    const uint32_t n = count();
    uint8_t* const tri = triangles();
    const uint8_t* const pos = base;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n; ++i) {
      const uint8_t* p = tri + size_t(blob_triangle_size) * i;
      const int32_t bottom = raw_row_bottom(map, load16(pos + 4 * size_t(load16(p)) + 2),
                                            load16(pos + 4 * size_t(load16(p + 2)) + 2),
                                            load16(pos + 4 * size_t(load16(p + 4)) + 2));
      if (bottom < y0) continue;
      if (kept != i) memcpy(tri + size_t(blob_triangle_size) * kept, p, blob_triangle_size);
      ++kept;
    }
    layer->triangle_count = kept;
  }

  // Keeps the vertices the triangles use, in slot order; the map's entries (2 slots >= vertices)
  // serve as the slot renumbering table. The map is rebuilt after.
  void compact_vertices() {
    const uint32_t n = count(), nv = vertices;
    uint8_t* const tri = triangles();
    uint8_t* const v = values();
    uint8_t* const g = gradients();
    uint16_t* const renumber = entries;
    for (uint32_t s = 0; s < nv; ++s) renumber[s] = band_store_free;
    for (uint32_t i = 0; i < n; ++i) {
      const uint8_t* p = tri + size_t(blob_triangle_size) * i;
      for (int k = 0; k < 3; ++k) renumber[load16(p + 2 * k)] = 0;
    }
    uint32_t kept = 0;
    for (uint32_t s = 0; s < nv; ++s) {
      if (renumber[s] == band_store_free) continue;
      renumber[s] = uint16_t(kept);
      if (kept != s) {
        // Copies of constant sizes, which compilers inline (a call per vertex costs more).
        memcpy(base + 4 * size_t(kept), base + 4 * size_t(s), 4);
        if (values_per_vertex == 1) {
          memcpy(v + 2 * size_t(kept), v + 2 * size_t(s), 2);
          if (has_gradients) memcpy(g + 8 * size_t(kept), g + 8 * size_t(s), 8);
        } else {
          memcpy(v + 6 * size_t(kept), v + 6 * size_t(s), 6);
          if (has_gradients) memcpy(g + 24 * size_t(kept), g + 24 * size_t(s), 24);
        }
        keys[kept] = keys[s];
      }
      ++kept;
    }
    for (uint32_t i = 0; i < n; ++i) {
      uint8_t* p = tri + size_t(blob_triangle_size) * i;
      for (int k = 0; k < 3; ++k) store16(p + 2 * k, renumber[load16(p + 2 * k)]);
    }
    vertices = kept;
  }
};

}  // namespace
}  // namespace tristream::core::detail
