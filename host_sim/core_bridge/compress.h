/* SPDX-License-Identifier: MIT */
#pragma once
// The host encoder of compressed blobs (firmware_core/include/tristream/compressed_blob.h,
// docs/COMPRESSED_BLOB.md): a packed v1 blob to the same meshes as one range-coded stream per
// layer. Lossless for every blob open_blob accepts.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace tristream {

// Where the bits of a compressed blob go (estimated from the coder's probabilities, which sum to
// the stream bytes within a few bytes per layer).
struct CompressStats {
  std::size_t v1_bytes = 0;
  std::size_t bytes = 0;
  std::uint64_t vertices = 0, triangles = 0;  // over all layers
  double position_bits = 0, value_bits = 0, gradient_bits = 0, connectivity_bits = 0, flag_bits = 0;
  std::uint32_t window = 0;  // the largest layer's vertex window
  std::vector<std::uint32_t> gradient_step_bits;  // per layer: gradients coded in units of 2^this (0 bilinear)
};

// Compresses a v1 blob; throws DataError ("<name>: byte N: ...") when open_blob refuses it.
std::vector<std::uint8_t> compress_blob(const std::vector<std::uint8_t>& v1, std::string_view name = "input",
                                        CompressStats* stats = nullptr);

}  // namespace tristream
