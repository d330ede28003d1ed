/* SPDX-License-Identifier: MIT */
#pragma once
// Tests and fuzzers that damage a blob on purpose to reach the checks behind its checksum (field
// ranges, sections, vertices, triangles) and the renderer: the damaged bytes sealed again.
#include <cstddef>
#include <cstdint>

#include "tristream/blob.h"

namespace tristream::testing {

// Writes the checksum of the v1 blob in `bytes` when its header's total size (bytes 8..11) lies in
// [blob_header_size, size], and returns whether it did; otherwise changes nothing.
inline bool seal_blob(std::uint8_t* bytes, std::size_t size) {
  if (size < core::blob_header_size) return false;
  const std::uint32_t total = std::uint32_t(bytes[8]) | std::uint32_t(bytes[9]) << 8 | std::uint32_t(bytes[10]) << 16 |
                              std::uint32_t(bytes[11]) << 24;
  if (total < core::blob_header_size || total > size) return false;
  const std::uint32_t crc = core::blob_checksum(bytes, total);
  for (int k = 0; k < 4; ++k) bytes[core::blob_checksum_offset + k] = std::uint8_t(crc >> (8 * k));
  return true;
}

}  // namespace tristream::testing
