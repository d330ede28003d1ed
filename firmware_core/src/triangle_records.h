/* SPDX-License-Identifier: MIT */
#pragma once
// The two layouts of triangle records the tile path reads (its functions take one as a template
// parameter): a v1 blob's, and the band store's of a compressed blob's render, which is 2 bytes a
// triangle shorter because few triangles have flags.
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/detail/bytes.h"

namespace tristream::core::detail {
namespace {

// A v1 blob's (blob.h): u16 v0, v1, v2, u16 flags.
struct BlobRecords {
  static constexpr uint32_t stride = blob_triangle_size;
  // Whether some records in the array are not triangles (their vertex indices not valid).
  static constexpr bool has_flag_records = false;
  static uint16_t flags(const uint8_t* p) { return load_u16(p + 6); }
};

// The band store's: u16 v0, v1, v2 in store slots. A triangle with flags is followed by a flag
// record, u16 store_flag_marker, u16 flags, u16 0, never live in the active set (so the cull and
// the tile renderer never take it for a triangle; a slot is at most 0xFFFE). The records are
// followed by a u16 guard (0), so that the first u16 after a triangle's record is always there.
constexpr uint16_t store_flag_marker = 0xFFFF;
struct StoreRecords {
  static constexpr uint32_t stride = 6;
  static constexpr bool has_flag_records = true;
  static bool is_flag_record(const uint8_t* p) { return load_u16(p) == store_flag_marker; }
  static uint16_t flags(const uint8_t* p) { return is_flag_record(p + stride) ? load_u16(p + stride + 2) : 0; }
};

}  // namespace
}  // namespace tristream::core::detail
