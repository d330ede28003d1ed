/* SPDX-License-Identifier: MIT */
#pragma once
// The layouts of triangle records the tile path reads (its functions take one as a template
// parameter): a v1 blob's, and the two of the band store of a compressed blob's render, which are
// 2 and 4 bytes a triangle shorter because few triangles have flags and, in the packed one, a
// band's vertex slots fit 10 bits.
#include <stdint.h>

#include "tuning.h"
#include "tristream/blob.h"
#include "bytes.h"

namespace tristream::core::detail {
namespace {

// A v1 blob's (blob.h): u16 v0, v1, v2, u16 flags.
struct BlobRecords {
  static constexpr uint32_t stride = blob_triangle_size;
  // Whether some records in the array are not triangles (their vertex indices not valid).
  static constexpr bool has_flag_records = false;
  static uint32_t vertex(const uint8_t* p, int k) { return load_u16_even(p + 2 * k); }
  static uint16_t flags(const uint8_t* p) { return load_u16_even(p + 6); }
};

// The band store's with more than store_packed_slots slots (its layer's vertex_count): u16 v0,
// v1, v2 in store slots. A triangle with flags is followed by a flag record, u16
// store_flag_marker, u16 flags, u16 0, never live in the active set (so the cull and the tile
// renderer never take it for a triangle; a slot is at most 0xFFFE). The records are followed by a
// u16 guard (0), so that the first u16 after a triangle's record is always there.
constexpr uint16_t store_flag_marker = 0xFFFF;
struct StoreRecords {
  static constexpr uint32_t stride = 6;
  static constexpr uint32_t guard_bytes = 2;
  static constexpr bool has_flag_records = true;
  // Inlined where the code is optimized for size too (as PackedStoreRecords').
  TS_INLINE static uint32_t vertex(const uint8_t* p, int k) { return load_u16_even(p + 2 * k); }
  TS_INLINE static bool is_flag_record(const uint8_t* p) {
    return load_u16_even(p) == store_flag_marker;
  }
  TS_INLINE static uint16_t flags(const uint8_t* p) {
    return is_flag_record(p + stride) ? load_u16_even(p + stride + 2) : 0;
  }
};

// The band store's with at most store_packed_slots slots (its layer's vertex_count): one u32
// v0 | v1 << 10 | v2 << 20 (its two top bits 0). A triangle with flags is followed by a flag
// record, u32 packed_flag_marker | flags (its two top bits 1), and the records by a u32 guard (0).
constexpr uint32_t store_packed_slots = 1024;
constexpr uint32_t packed_flag_marker = 0xC0000000u;
struct PackedStoreRecords {
  static constexpr uint32_t stride = 4;
  static constexpr uint32_t guard_bytes = 4;
  static constexpr int slot_bits = 10;
  static constexpr bool has_flag_records = true;
  static_assert(store_packed_slots == 1u << slot_bits, "a slot in 10 bits");
  static uint32_t pack(uint32_t v0, uint32_t v1, uint32_t v2) { return v0 | v1 << slot_bits | v2 << 2 * slot_bits; }
  // The readers inlined where the code is optimized for size too (-Os would call them, once per
  // vertex read of a compressed blob's render).
  TS_INLINE static uint32_t word(const uint8_t* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
  }
  TS_INLINE static uint32_t vertex(const uint8_t* p, int k) {
    return (word(p) >> (slot_bits * k)) & (store_packed_slots - 1);
  }
  TS_INLINE static bool is_flag_record(const uint8_t* p) { return word(p) >= packed_flag_marker; }
  TS_INLINE static uint16_t flags(const uint8_t* p) {
    const uint32_t next = word(p + stride);
    return next >= packed_flag_marker ? uint16_t(next) : 0;  // flags fit 16 bits (blob.h: 9 defined)
  }
};

// The band store's records in the layout its slots give (BandStore): PackedStoreRecords while the
// layer's vertex_count (the store's slots) is at most store_packed_slots, else StoreRecords.
struct BandStoreRecords {};
template <typename Records>
struct IsBandStore {
  static constexpr bool value = false;
};
template <>
struct IsBandStore<BandStoreRecords> {
  static constexpr bool value = true;
};

}  // namespace
}  // namespace tristream::core::detail
