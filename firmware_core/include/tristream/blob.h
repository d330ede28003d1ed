/* SPDX-License-Identifier: MIT */
#pragma once
// The packed triangulation ("blob"): a versioned little-endian byte layout made by the host packer
// (tripack) and read in place by the core. Layout (all offsets from the blob's first byte,
// every section 4-byte aligned):
//
//   header, 64 bytes
//     0  char[4] magic "TSTB"        4  u16 version (2)         6  u16 header size (64)
//     8  u32 total size             12  u16 width  14 u16 height (domain [0,W-1] x [0,H-1])
//    16  u8 colour space (0 grey, 1 rgb, 2 ycbcr)   17 u8 method (0 bilinear, 1 zienkiewicz)
//    18  u8 layer count (1, or 3 for one mesh per channel)   19 u8 values per vertex (1 or 3)
//    20  u8 sub-pixel bits   21 u8 gradient fraction bits   22 u16 flags (0)
//    24  u32 config hash (blob_config_hash())   28 u32 layer table offset
//    32  u32 max triangle height in rows (informative)
//    36  u32 checksum: CRC-32 (ISO-HDLC, as zlib) of bytes 0..35 and 40..total size - 1
//    40..63 reserved, zero
//   layer table: layer count entries of 32 bytes
//     0 u32 vertex count   4 u32 triangle count   8 u32 positions offset   12 u32 values offset
//    16 u32 gradients offset (0 unless zienkiewicz)  20 u32 triangles offset  24..31 reserved, zero
//   positions: per vertex u16 x, u16 y in position_fx (sub-pixel fixed point)
//   values: per vertex and value, u16 in q8_8 (0 .. 255 * 256)
//   gradients: per vertex and value, i32 gx, i32 gy in q19_12 (value units per domain pixel)
//   triangles: per triangle u16 v0, v1, v2, u16 flags, sorted by top row (smallest y) ascending;
//     each triangle has positive doubled area (clockwise on screen, y down).
//     flags bit e (0..2): edge e (v[e] -> v[(e+1)%3]) is on the domain boundary (inclusive);
//     bit 3+k: corner k is a boundary vertex whose pixel has an explicit owner;
//     bit 6+k: this triangle owns the pixel of corner k (meaningful only with bit 3+k).
//
// Version 1 was this layout without the checksum (bytes 36..39 zero); open_blob refuses it with
// Status::bad_version (docs/FORMAT.md, "The blob": the checksum, the versions, the cost).
#include <stddef.h>
#include <stdint.h>

#include "tristream/config.h"
#include "tristream/status.h"

namespace tristream::core {

inline constexpr uint16_t blob_version = 2;
inline constexpr uint32_t blob_header_size = 64;
inline constexpr uint32_t blob_checksum_offset = 36;
inline constexpr uint32_t blob_layer_entry_size = 32;
inline constexpr uint32_t blob_triangle_size = 8;
inline constexpr uint32_t blob_max_vertices = 65535;
inline constexpr uint32_t blob_max_triangles = 1u << 20;  // a 65535-vertex mesh has fewer than 2^17

enum class ColorSpace : uint8_t { grey = 0, rgb = 1, ycbcr = 2 };
enum class Method : uint8_t { bilinear = 0, zienkiewicz = 1 };

enum TriangleFlag : uint16_t {
  boundary_edge0 = 1u << 0,
  corner_explicit0 = 1u << 3,
  corner_owned0 = 1u << 6,
  triangle_flags_mask = 0x1FF,
};

// Hash of the configuration values that change how a blob is read; recorded in the header of both
// blob forms. Its constant does not follow the version field (checked on its own): one value for
// every version, so a compressed blob's hash stays what it was.
constexpr uint32_t blob_config_hash() {
  return 0x54530001u ^ (uint32_t(config::subpixel_bits) << 8) ^ (uint32_t(config::gradient_frac_bits) << 12);
}

// The checksum a blob of `total` bytes (at least blob_header_size) records at blob_checksum_offset:
// the CRC-32 of all its bytes but the four of that field. Reads bytes [0, total) only.
uint32_t blob_checksum(const void* bytes, uint32_t total);

struct BlobLayer {
  uint32_t vertex_count = 0;
  uint32_t triangle_count = 0;
  const uint8_t* positions = nullptr;  // 4 bytes per vertex
  const uint8_t* values = nullptr;     // 2 bytes per vertex and value
  const uint8_t* gradients = nullptr;  // 8 bytes per vertex and value, or null
  const uint8_t* triangles = nullptr;  // blob_triangle_size bytes per triangle
};

// The header fields both blob forms have (Blob, CompressedBlob): a view of the caller's bytes,
// which must outlive it, and the total size its header records.
struct BlobInfo {
  const uint8_t* bytes = nullptr;
  uint32_t size = 0;
  uint16_t width = 0;
  uint16_t height = 0;
  ColorSpace space = ColorSpace::grey;
  Method method = Method::bilinear;
  uint8_t layer_count = 0;
  uint8_t values_per_vertex = 0;
};

// A validated blob; a view of the caller's bytes, which must outlive it.
struct Blob : BlobInfo {
  BlobLayer layers[3];
};

// Where validation failed: the byte offset of the offending field or record (for host messages).
struct BlobError {
  uint32_t offset = 0;
};

// Checks everything (header, checksum, table, sections, every vertex and triangle) and fills `out`.
// Never reads outside [bytes, bytes + size), nor past the header's total size, which may be less
// than `size` (a blob in a larger flash section). Returns Status::ok or the first problem found;
// `error`, when not null, receives its byte offset. The order: the magic (bad_magic, offset 0),
// the version (bad_version, 4), the header size (bad_header, 6) and the total size (truncated, 8),
// which locate the checksum; then the checksum over [0, total size) (bad_checksum, offset
// blob_checksum_offset); then every other field. So a damaged blob is reported as damaged, and the
// field checks see only bytes whose checksum matches (a packer's, or damage sealed again).
Status open_blob(const void* bytes, size_t size, Blob* out, BlobError* error = nullptr);

}  // namespace tristream::core
