/* SPDX-License-Identifier: MIT */
#pragma once
// The band store of a compressed blob's render: the live triangles of one layer for the current
// band, as a small v1-shaped layer in the caller's workspace (positions, values, gradients,
// triangle records in one of the store's layouts, PackedStoreRecords with at most
// store_packed_slots vertex slots, else StoreRecords, and the active-set bitmap), which the tile
// cull and the tile renderer read as they read a v1 blob's layer. Each live vertex is stored once:
// the triangles' indices are store slots, which the decoder's tags (LayerDecoder::keep_tags) hold
// for the vertices still in its ring, so a corner's slot is found without a map.
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "bytes.h"
#include "output_mapping.h"
#include "triangle_records.h"
#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "arith.h"
#include "tristream/fixed_point.h"
#include "tristream/status.h"
#include "workspace_layout.h"

namespace tristream::core::detail {
namespace {

// Slots are u16 and 0xFFFF (compressed_tag_none, and store_flag_marker in a record) is no slot, so
// a store holds at most 65,535 vertices: a layer's vertex count (blob_max_vertices), so the
// indices never bound a band.
// Triangles are bounded only by the workspace (the active set counts them in u32).
constexpr uint32_t band_store_max_vertices = 65535;
static_assert(band_store_max_vertices >= blob_max_vertices, "every vertex of a layer fits the u16 slots");
static_assert(band_store_max_vertices - 1 < store_flag_marker, "no slot is the flag records' marker");
constexpr uint16_t band_store_free = compressed_tag_none;

constexpr size_t align4_size(size_t n) { return (n + 3) / 4 * 4; }

// Bytes of `slots` vertex slots: 4 of position, 2 per value, 8 per gradient pair, each array
// 4-aligned.
inline size_t band_vertex_bytes(uint32_t slots, uint32_t values_per_vertex, bool gradients) {
  const size_t n = slots;
  return 4 * n + align4_size(2 * n * values_per_vertex) + (gradients ? 8 * n * values_per_vertex : 0);
}

// Bytes of the table that renumbers `slots` slots when a band starts: a bit per slot (kept or
// not) in 32-bit words and a u16 per word (the kept slots before it), 4-aligned.
inline size_t rank_table_bytes(uint32_t slots) { return align4_size(6 * ((size_t(slots) + 31) / 32)); }

// Bytes of `records` triangle and flag records and their guard, 4-aligned (none without records):
// packed (PackedStoreRecords) or not (StoreRecords).
inline size_t store_record_bytes(uint32_t records, bool packed) {
  if (!records) return 0;
  return packed ? size_t(PackedStoreRecords::stride) * records + PackedStoreRecords::guard_bytes
                : align4_size(size_t(StoreRecords::stride) * records + StoreRecords::guard_bytes);
}

// Whether a store of `slots` slots lays its records out packed (BandStoreRecords).
inline bool packed_store(uint32_t slots) { return slots <= store_packed_slots; }

// Bytes a store needs to hold V vertices and C triangles of which F have flags: the vertex slots,
// the C + F records (packed when V <= store_packed_slots), and the larger of the
// renumbering table (rank_table_bytes, used when a band starts) and the active-set bitmap (C + F
// bits in 32-bit words, used while the band is drawn), which share memory.
inline size_t band_store_bytes(uint32_t vertices, uint32_t triangles, uint32_t flagged, uint32_t values_per_vertex,
                               bool gradients) {
  const uint32_t records = triangles + flagged;
  const size_t renumber = rank_table_bytes(vertices), bits = bitmap_bytes(records);
  return band_vertex_bytes(vertices, values_per_vertex, gradients) +
         store_record_bytes(records, packed_store(vertices)) + (renumber > bits ? renumber : bits);
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

// The store's other layout of records.
template <typename R>
struct OtherLayout {
  using type = PackedStoreRecords;
};
template <>
struct OtherLayout<PackedStoreRecords> {
  using type = StoreRecords;
};

// The store in `bytes` of workspace: [vertex slots for `slots` vertices: positions, values,
// gradients][records, growing, and their guard]...[renumbering table of `slots` at the end]. Its
// need is band_store_bytes(vertices, triangles, flagged) at every moment, whatever the slack:
// slots grow when a further vertex finds none free (the arrays after the positions and the records
// move up), and shrink to the vertex count when the records or the bitmap would not fit otherwise,
// so a store of `bytes` takes every band whose need is at most `bytes`. The records' layout follows
// the slots (packed_store): a relayout across store_packed_slots rewrites them in the other one.
// Invariant between calls: rank_table_bytes(slots) fit after the records.
// The decoder's tags (`tags`, tag_count of them) hold the slot of each vertex of its ring that is
// in the store, else band_store_free: a corner's tag finds its slot, and a vertex out of the ring
// is never a corner again.
// Its fields are few (the render's stack holds three stores): the positions are at `base`, the
// other sections' addresses follow from `slots`.
struct BandStore {
  BlobLayer* layer = nullptr;  // the view the tile path reads; triangle_count is the store's records
  uint8_t* base = nullptr;     // 4-aligned; the positions
  size_t bytes = 0;            // a multiple of 4
  uint32_t slots = 0;          // vertex capacity of the current layout
  uint32_t vertices = 0;       // slots in use: [0, vertices)
  uint32_t added = 0;          // vertices added in the current band
  uint32_t record_room = 0;    // the most records that fit with `slots` and the renumbering table
  uint16_t* tags = nullptr;    // the decoder's (keep_tags): a slot, or band_store_free
  uint32_t tag_count = 0;
  uint8_t values_per_vertex = 1;
  bool has_gradients = false;
  // The records are PackedStoreRecords (else StoreRecords): packed_store(slots), set with the slots
  // by place(). Kept, not derived where used (deriving it costs the compressed render a test per use).
  bool packed = false;

  void init(uint8_t* at, size_t size, uint32_t per_vertex, bool with_gradients, BlobLayer* view,
            uint16_t* decoder_tags, uint32_t decoder_tag_count) {
    tags = decoder_tags;
    tag_count = decoder_tag_count;
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

  // Records (triangles and flag records).
  uint32_t count() const { return layer->triangle_count; }

  // Starts band [y0, ...]: drops the triangles whose last row is above y0 (keeping the others in
  // order), then the vertices no kept triangle uses (renumbering the kept ones in order, in the
  // triangles and the tags), with room for about as many added vertices as the band before added.
  void begin_band(const Mapping& map, int32_t y0) {
    drop_ended(map, y0);
    compact_vertices();
    const uint32_t want = vertices + added + added / 4 + 16;
    added = 0;
    const uint32_t fit = most_slots(count());
    relayout(want < fit ? want : fit);  // fit >= vertices: the invariant held for more triangles
  }

  // Appends a triangle (its corners' slots found by their tags, unseen ones stored), and its flag
  // record if it has flags. Returns workspace_too_small when the band's need passes `bytes`.
  Status append(const DecodedTriangle& t) {
    uint16_t slot[3];
    for (int k = 0; k < 3; ++k) {
      const Status s = vertex_slot(t, k, &slot[k]);
      if (s != Status::ok) return s;
    }
    const uint32_t n = count(), records = t.flags ? 2 : 1;
    if (n + records > record_room) {
      if (slots == vertices) return Status::workspace_too_small;
      relayout(vertices);  // the slack of slots makes room
      if (n + records > record_room) return Status::workspace_too_small;
    }
    with_layout([&](auto r) {
      using R = decltype(r);
      uint8_t* const p = triangles() + size_t(R::stride) * n;
      write_triangle<R>(p, slot[0], slot[1], slot[2]);
      if (t.flags) write_flags<R>(p + R::stride, t.flags);
      write_guard<R>(p + R::stride * records);
    });
    layer->triangle_count = n + records;
    return Status::ok;
  }

  // Marks every triangle of the store live in the active-set bitmap (a bit per record; those of
  // flag records clear), which follows the records (over the table, not needed again before the
  // next band's begin_band). Null when it does not fit.
  uint32_t* mark_all_live() {
    const uint32_t n = count();
    if (!fits(slots, n, bitmap_bytes(n))) {
      if (slots == vertices) return nullptr;
      relayout(vertices);
      if (!fits(slots, n, bitmap_bytes(n))) return nullptr;
    }
    uint32_t* words = reinterpret_cast<uint32_t*>(triangles() + store_record_bytes(n, packed));
    for (uint32_t w = 0; w < n / 32; ++w) words[w] = 0xFFFFFFFFu;
    if (n % 32) words[n / 32] = (1u << (n % 32)) - 1;
    const uint8_t* const tri = triangles();
    with_layout([&](auto r) {
      using R = decltype(r);
      for (uint32_t i = 1; i < n; ++i)  // (a flag record follows its triangle: never the first)
        if (R::is_flag_record(tri + size_t(R::stride) * i)) words[i / 32] &= ~(1u << (i % 32));
    });
    return words;
  }

 private:
  uint8_t* values() const { return base + 4 * size_t(slots); }
  uint8_t* gradients() const { return values() + align4_size(2 * size_t(slots) * values_per_vertex); }
  uint8_t* triangles() const {
    return gradients() + (has_gradients ? 8 * size_t(slots) * values_per_vertex : 0);
  }

  // f(R{}) with R the layout of the records (PackedStoreRecords or StoreRecords): one test a pass.
  template <typename F>
  void with_layout(F&& f) const {
    if (packed) {
      f(PackedStoreRecords{});
    } else {
      f(StoreRecords{});
    }
  }
  uint32_t stride() const { return packed ? PackedStoreRecords::stride : StoreRecords::stride; }
  // A triangle's record, a flag record (StoreRecords: marker, flags, 0; PackedStoreRecords: marker
  // | flags) and the guard (0), in layout R.
  template <typename R>
  static void write_triangle(uint8_t* p, uint32_t s0, uint32_t s1, uint32_t s2) {
    if constexpr (R::stride == PackedStoreRecords::stride) {
      store32(p, PackedStoreRecords::pack(s0, s1, s2));
    } else {
      store16(p, uint16_t(s0));
      store16(p + 2, uint16_t(s1));
      store16(p + 4, uint16_t(s2));
    }
  }
  template <typename R>
  static void write_flags(uint8_t* p, uint16_t flags) {
    if constexpr (R::stride == PackedStoreRecords::stride) {
      store32(p, packed_flag_marker | flags);
    } else {
      store16(p, store_flag_marker);
      store16(p + 2, flags);
      store16(p + 4, 0);
    }
  }
  template <typename R>
  static void write_guard(uint8_t* p) {
    if constexpr (R::guard_bytes == 4) {
      store32(p, 0);
    } else {
      store16(p, 0);
    }
  }

  // Little-endian (the v1 layout); on a little-endian target with unaligned stores one store
  // each, else byte stores (TS_UNALIGNED_STORES: a memcpy would be a call).
  static void store16(uint8_t* p, uint16_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
    memcpy(p, &v, 2);
#else
    p[0] = uint8_t(v);
    p[1] = uint8_t(v >> 8);
#endif
  }
  static void store32(uint8_t* p, uint32_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
    memcpy(p, &v, 4);
#else
    store16(p, uint16_t(v));
    store16(p + 2, uint16_t(v >> 16));
#endif
  }
  static uint16_t load16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }

  // A section's start, 4-aligned, with that alignment told to the compiler where a halfword or
  // word access must be aligned (TS_UNALIGNED_STORES 0): else it makes each copy of constant size
  // from or to the section a call of memcpy.
  static uint8_t* aligned4(uint8_t* p) {
#if TS_UNALIGNED_STORES
    return p;
#else
    return static_cast<uint8_t*>(__builtin_assume_aligned(p, 4));
#endif
  }

  // memmove of align4(n) bytes between 4-aligned sections, a word at a time (the C library's
  // memmove on a microcontroller is often a byte loop); the rounding stays inside both sections,
  // which are 4-aligned and at least align4(n) bytes.
  static void move_words(uint8_t* to, const uint8_t* from, size_t n) {
    const size_t words = (n + 3) / 4;
    to = aligned4(to);
    from = aligned4(const_cast<uint8_t*>(from));
    if (to < from) {
      for (size_t i = 0; i < words; ++i) memcpy(to + 4 * i, from + 4 * i, 4);
    } else if (to > from) {
      for (size_t i = words; i-- > 0;) memcpy(to + 4 * i, from + 4 * i, 4);
    }
  }

  // Whether `cap` slots, n records in cap's layout and `tail` bytes after them fit.
  bool fits(uint32_t cap, uint32_t n, size_t tail) const {
    return band_vertex_bytes(cap, values_per_vertex, has_gradients) +
               store_record_bytes(n, packed_store(cap)) + tail <=
           bytes;
  }
  // The most slots that fit with n records and their renumbering table: the most with records not
  // packed when that passes store_packed_slots, else the most with packed ones (up to that).
  uint32_t most_slots(uint32_t n) const {
    const uint32_t wide = most_slots_in(n, false, store_packed_slots, band_store_max_vertices);
    return wide > store_packed_slots ? wide : most_slots_in(n, true, 0, store_packed_slots);
  }
  // The most slots in (low, high] that fit with n records laid out packed or not (low if none).
  uint32_t most_slots_in(uint32_t n, bool packed_records, uint32_t low, uint32_t high) const {
    const size_t t = store_record_bytes(n, packed_records);
    if (t >= bytes) return low;
    const size_t per = 4 + 2 * size_t(values_per_vertex) + (has_gradients ? 8 * size_t(values_per_vertex) : 0);
    // An upper bound: a slot costs per bytes and 6 / 32 of the table; the sections' rounding only adds.
    size_t c = 32 * (bytes - t) / (32 * per + 6);
    if (c > high) c = high;
    while (c > low && !fits(uint32_t(c), n, rank_table_bytes(uint32_t(c)))) --c;
    return uint32_t(c > low ? c : low);
  }

  // Section addresses for `cap` slots.
  void place(uint32_t cap) {
    slots = cap;
    packed = packed_store(cap);
    // fits(cap, n, rank_table_bytes(cap)) for n <= record_room: the room is a multiple of 4, so
    // the records' stride n + guard bytes, rounded up to 4, fit in it exactly when they do unrounded.
    const size_t used = band_vertex_bytes(cap, values_per_vertex, has_gradients) + rank_table_bytes(cap);
    const size_t room = used < bytes ? bytes - used : 0;
    const size_t guard = packed ? PackedStoreRecords::guard_bytes : StoreRecords::guard_bytes;
    const size_t most = room >= guard ? (room - guard) / stride() : 0;
    record_room = most < 0xFFFFFFFFu ? uint32_t(most) : 0xFFFFFFFFu;
    layer->positions = base;
    layer->values = values();
    if (has_gradients) layer->gradients = gradients();
    layer->triangles = triangles();
    layer->vertex_count = cap;
  }

  // Moves to a layout of `cap` >= vertices slots (which must fit with the records and the
  // renumbering table).
  void relayout(uint32_t cap) {
    uint8_t* const old_values = values();
    uint8_t* const old_gradients = gradients();
    uint8_t* const old_triangles = triangles();
    const bool old_packed = packed;
    const size_t nv = vertices, nt = count();
    const size_t value_bytes = 2 * nv * values_per_vertex;
    const size_t gradient_bytes = has_gradients ? 8 * nv * values_per_vertex : 0;
    place(cap);
    uint8_t* const to_values = values();
    uint8_t* const to_gradients = gradients();
    uint8_t* const to_triangles = triangles();
    // The sections after the positions all move the same way: the last first when they move up.
    // More slots never lay the records out packed when fewer did not, so the records grow only
    // when they move up and shrink only when they move down.
    if (to_triangles > old_triangles) {
      move_records(to_triangles, old_triangles, uint32_t(nt), old_packed);
      if (gradient_bytes) move_words(to_gradients, old_gradients, gradient_bytes);
      move_words(to_values, old_values, value_bytes);
    } else if (to_triangles < old_triangles) {
      move_words(to_values, old_values, value_bytes);
      if (gradient_bytes) move_words(to_gradients, old_gradients, gradient_bytes);
      move_records(to_triangles, old_triangles, uint32_t(nt), old_packed);
    }
  }
  // The n records at `from` (packed as `from_packed`) to `to` in the current layout, with their
  // guard. In one layout a move of words; across layouts record by record, the last first when
  // they grow (up: unpacked from packed, each written at or above where it was read, past the
  // records before it), the first first when they shrink (down).
  void move_records(uint8_t* to, const uint8_t* from, uint32_t n, bool from_packed) {
    if (from_packed == packed) {
      move_words(to, from, store_record_bytes(n, packed));
      return;
    }
    if (!n) return;
    // From R to the other layout, record i.
    auto convert = [&](auto r, uint32_t i) {
      using R = decltype(r);
      using To = typename OtherLayout<R>::type;
      const uint8_t* p = from + size_t(R::stride) * i;
      uint8_t* q = to + size_t(To::stride) * i;
      if (R::is_flag_record(p)) {
        write_flags<To>(q, R::stride == PackedStoreRecords::stride ? uint16_t(load_u32(p)) : load16(p + 2));
      } else {
        write_triangle<To>(q, R::vertex(p, 0), R::vertex(p, 1), R::vertex(p, 2));
      }
    };
    if (packed) {
      for (uint32_t i = 0; i < n; ++i) convert(StoreRecords{}, i);
      write_guard<PackedStoreRecords>(to + size_t(PackedStoreRecords::stride) * n);
    } else {
      for (uint32_t i = n; i-- > 0;) convert(PackedStoreRecords{}, i);
      write_guard<StoreRecords>(to + size_t(StoreRecords::stride) * n);
    }
  }

  // The slot of corner k of t: its tag, or a free slot (more slots if none is free), which the
  // tag then holds.
  Status vertex_slot(const DecodedTriangle& t, int k, uint16_t* out) {
    uint16_t* const tag = t.tag[k];
    if (!tag) return Status::bad_index;  // never from a decoder given tags
    if (*tag < vertices) {
      *out = *tag;
      return Status::ok;
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
    *tag = uint16_t(s);
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

  // Drops the triangles whose last row is above y0 with their flag records, keeping the others
  // in order.
  void drop_ended(const Mapping& map, int32_t y0) {
    with_layout([&](auto r) { drop_ended_as<decltype(r)>(map, y0); });
  }
  template <typename R>
  void drop_ended_as(const Mapping& map, int32_t y0) {
    constexpr size_t stride = R::stride;
    const uint32_t n = count();
    uint8_t* const tri = aligned4(triangles());
    const uint8_t* const pos = base;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < n;) {
      const uint8_t* p = tri + stride * i;
      // A triangle's record, and the next one its flag record or not (the guard after the last).
      const bool flagged = R::is_flag_record(p + stride);
      const int32_t bottom = raw_row_bottom(map, load16(pos + 4 * size_t(R::vertex(p, 0)) + 2),
                                            load16(pos + 4 * size_t(R::vertex(p, 1)) + 2),
                                            load16(pos + 4 * size_t(R::vertex(p, 2)) + 2));
      if (bottom >= y0) {
        // Records of constant size, at least one record apart when they move: no overlap.
        if (kept != i) {
          memcpy(tri + stride * kept, p, stride);
          if (flagged) memcpy(tri + stride * (kept + 1), p + stride, stride);
        }
        kept += flagged ? 2 : 1;
      }
      i += flagged ? 2 : 1;
    }
    if (kept) write_guard<R>(tri + stride * kept);
    layer->triangle_count = kept;
  }

  // Ones in a word (no popcount instruction on a Cortex-M4).
  static uint32_t ones(uint32_t x) {
    x = x - ((x >> 1) & 0x55555555u);
    x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
    x = (x + (x >> 4)) & 0x0F0F0F0Fu;
    return (x * 0x01010101u) >> 24;
  }

  // Keeps the vertices the triangles use, in slot order, and renumbers them in the triangles'
  // records (not the flag records) and the decoder's tags (a dropped vertex's tag is
  // band_store_free). The table at the store's end (rank_table_bytes(slots), slots >= vertices)
  // marks the kept slots, a bit each, and counts the kept slots before each word: a kept slot's new
  // number is that count plus the kept ones below it in its word.
  void compact_vertices() {
    const uint32_t n = count(), nv = vertices, words_n = (nv + 31) / 32;
    uint8_t* const tri = triangles();
    uint8_t* const v = aligned4(values());
    uint8_t* const g = aligned4(gradients());
    uint32_t* const marks = reinterpret_cast<uint32_t*>(base + bytes - rank_table_bytes(slots));
    uint16_t* const before = reinterpret_cast<uint16_t*>(marks + (slots + 31) / 32);
    for (uint32_t w = 0; w < words_n; ++w) marks[w] = 0;
    with_layout([&](auto r) {
      using R = decltype(r);
      for (uint32_t i = 0; i < n; ++i) {
        const uint8_t* p = tri + size_t(R::stride) * i;
        if (R::is_flag_record(p)) continue;
        for (int k = 0; k < 3; ++k) {
          const uint32_t s = R::vertex(p, k);
          marks[s >> 5] |= 1u << (s & 31);
        }
      }
    });
    uint32_t kept = 0;
    for (uint32_t w = 0; w < words_n; ++w) {
      before[w] = uint16_t(kept);
      kept += ones(marks[w]);
    }
    auto is_kept = [&](uint32_t s) { return ((marks[s >> 5] >> (s & 31)) & 1u) != 0; };
    kept = 0;
    for (uint32_t s = 0; s < nv; ++s) {
      if (!is_kept(s)) continue;
      if (kept != s) {
        // Copies of constant sizes, which compilers inline (a call per vertex costs more).
        memcpy(aligned4(base) + 4 * size_t(kept), aligned4(base) + 4 * size_t(s), 4);
        if (values_per_vertex == 1) {
          memcpy(v + 2 * size_t(kept), v + 2 * size_t(s), 2);
          if (has_gradients) memcpy(g + 8 * size_t(kept), g + 8 * size_t(s), 8);
        } else {
          memcpy(v + 6 * size_t(kept), v + 6 * size_t(s), 6);
          if (has_gradients) memcpy(g + 24 * size_t(kept), g + 24 * size_t(s), 24);
        }
      }
      ++kept;
    }
    // A kept slot's new number (every slot of a triangle is kept).
    auto rank = [&](uint32_t s) {
      const uint32_t w = s >> 5, below = (1u << (s & 31)) - 1;
      return uint16_t(before[w] + ones(marks[w] & below));
    };
    with_layout([&](auto r) {
      using R = decltype(r);
      for (uint32_t i = 0; i < n; ++i) {
        uint8_t* p = tri + size_t(R::stride) * i;
        if (R::is_flag_record(p)) continue;
        write_triangle<R>(p, rank(R::vertex(p, 0)), rank(R::vertex(p, 1)), rank(R::vertex(p, 2)));
      }
    });
    for (uint32_t i = 0; i < tag_count; ++i) {
      const uint32_t s = tags[i];
      if (s < nv) tags[i] = is_kept(s) ? rank(s) : band_store_free;  // (past nv: none)
    }
    vertices = kept;
  }
};

}  // namespace
}  // namespace tristream::core::detail
