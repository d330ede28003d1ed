/* SPDX-License-Identifier: MIT */
#pragma once
// The C form of a compressed blob (tripack --compress -o x.c): x.c holds the bytes as
// `const uint8_t <symbol>[]`, x.h declares them with their size and the decoder's RAM
// (<SYMBOL>_BYTES, <SYMBOL>_DECODER_RING_BYTES) and refuses a core of another precision.
// The core renders it after expand_compressed_blob (tristream/compressed_blob.h).
#include <cstdint>
#include <string>
#include <vector>

#include "tristream/compressed_blob.h"

namespace tristream {

struct CCompressedSpec {
  std::string symbol;       // is_blob_symbol
  std::string source_name;  // for the comment at the top
};

std::string compressed_c_source(const std::vector<std::uint8_t>& bytes, const CCompressedSpec& spec);
std::string compressed_c_header(const core::CompressedBlob& blob, const CCompressedSpec& spec);

}  // namespace tristream
