/* SPDX-License-Identifier: MIT */
#pragma once
// The byte layout of both blob forms, named once: where each field lies and how many bytes it
// takes. The core's readers (blob_header.h, blob.cpp, compressed_blob.cpp) and the host's writers
// and readers (host_sim/core_bridge: pack, compress, unpack, blob_error) all use these names with
// the loads and stores of bytes.h. docs/FORMAT.md and docs/COMPRESSED_BLOB.md say what each field
// means; the sizes the public API states (blob.h, compressed_blob.h) are used, not repeated.
// Every field is little-endian; offsets are from the first byte of the record they name.
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/compressed_blob.h"

namespace tristream::core::wire {

// The four bytes each form starts with.
inline constexpr char v1_magic[4] = {'T', 'S', 'T', 'B'};
inline constexpr char compressed_magic[4] = {'T', 'S', 'T', 'C'};

// Whether b (at least 4 bytes) starts with `magic`.
inline bool has_magic(const uint8_t* b, const char (&magic)[4]) {
  return b[0] == uint8_t(magic[0]) && b[1] == uint8_t(magic[1]) && b[2] == uint8_t(magic[2]) &&
         b[3] == uint8_t(magic[3]);
}
inline void put_magic(uint8_t* b, const char (&magic)[4]) {
  for (int k = 0; k < 4; ++k) b[k] = uint8_t(magic[k]);
}

// The header: 64 bytes in both forms, the same fields at the same offsets up to `checksum`.
namespace header {
inline constexpr uint32_t magic = 0;                // char[4]
inline constexpr uint32_t version = 4;              // u16
inline constexpr uint32_t header_size = 6;          // u16
inline constexpr uint32_t total_size = 8;           // u32
inline constexpr uint32_t width = 12;               // u16
inline constexpr uint32_t height = 14;              // u16
inline constexpr uint32_t color_space = 16;         // u8
inline constexpr uint32_t method = 17;              // u8
inline constexpr uint32_t layer_count = 18;         // u8
inline constexpr uint32_t values_per_vertex = 19;   // u8
inline constexpr uint32_t subpixel_bits = 20;       // u8
inline constexpr uint32_t gradient_frac_bits = 21;  // u8
inline constexpr uint32_t flags = 22;               // u16, zero
inline constexpr uint32_t config_hash = 24;         // u32
inline constexpr uint32_t layer_table = 28;         // u32
inline constexpr uint32_t max_triangle_height = 32; // u32, informative
// v1: the CRC-32 (u32), then zero bytes to the end of the header. Compressed: zero bytes from here.
inline constexpr uint32_t checksum = blob_checksum_offset;
inline constexpr uint32_t v1_reserved = checksum + 4;
inline constexpr uint32_t compressed_reserved = checksum;
inline constexpr uint32_t bytes = blob_header_size;
// [shared_begin, shared_end): the fields a compressed blob copies from the v1 blob it was made of
// and gives back when expanded (size and version fields excepted, the layer table's offset
// rewritten).
inline constexpr uint32_t shared_begin = width;
inline constexpr uint32_t shared_end = checksum;
}  // namespace header
static_assert(compressed_header_size == header::bytes, "both forms have one header size");

// Every v1 section starts at a multiple of 4.
inline constexpr uint32_t section_alignment = 4;
constexpr uint32_t align_section(uint32_t n) { return (n + section_alignment - 1) & ~(section_alignment - 1); }

// An entry of the v1 layer table (at header::layer_table): counts and the offsets of the sections.
namespace v1_layer {
inline constexpr uint32_t vertex_count = 0;    // u32
inline constexpr uint32_t triangle_count = 4;  // u32
inline constexpr uint32_t positions = 8;       // u32 offset
inline constexpr uint32_t values = 12;         // u32 offset
inline constexpr uint32_t gradients = 16;      // u32 offset, 0 unless zienkiewicz
inline constexpr uint32_t triangles = 20;      // u32 offset
inline constexpr uint32_t reserved = 24;       // zero to the end of the entry
inline constexpr uint32_t bytes = blob_layer_entry_size;
}  // namespace v1_layer

// A vertex position: u16 x, u16 y in position_fx.
namespace position {
inline constexpr uint32_t x = 0;
inline constexpr uint32_t y = 2;
inline constexpr uint32_t bytes = 4;
}  // namespace position

// A vertex value: u16 in q8_8, values_per_vertex of them per vertex.
namespace value {
inline constexpr uint32_t bytes = 2;
}  // namespace value

// A gradient, per vertex and value: i32 gx, i32 gy in q19_12.
namespace gradient {
inline constexpr uint32_t gx = 0;
inline constexpr uint32_t gy = 4;
inline constexpr uint32_t bytes = 8;
}  // namespace gradient

// A triangle: u16 vertex index per corner k at corner(k), then u16 flags (TriangleFlag).
namespace triangle {
constexpr uint32_t corner(uint32_t k) { return 2 * k; }
inline constexpr uint32_t flags = 6;
inline constexpr uint32_t bytes = blob_triangle_size;
}  // namespace triangle

// An entry of the compressed layer table (right after the header).
namespace compressed_layer {
inline constexpr uint32_t vertex_count = 0;    // u32
inline constexpr uint32_t triangle_count = 4;  // u32
inline constexpr uint32_t stream_offset = 8;   // u32
inline constexpr uint32_t stream_bytes = 12;   // u32
inline constexpr uint32_t window = 16;         // u32
inline constexpr uint32_t pinned = 20;         // u32
inline constexpr uint32_t gradient_step = 24;  // u8: gradient components coded in units of 2^this
inline constexpr uint32_t reserved = 25;       // zero to the end of the entry
inline constexpr uint32_t bytes = compressed_layer_entry_size;
}  // namespace compressed_layer

}  // namespace tristream::core::wire
