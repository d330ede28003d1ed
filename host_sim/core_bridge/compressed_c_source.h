/* SPDX-License-Identifier: MIT */
#pragma once
// The C form of a compressed blob (tripack --compress -o x.c), shaped as the v1 form
// (c_source.h): x.c holds the bytes as <symbol>_bytes and a ts_blob_descriptor <symbol> over them
// (ts_open_compressed(d.bytes, d.size, ...), then ts_render_compressed with the descriptor's
// figures), x.h declares it, refuses to compile against a core that cannot render it, and defines
// <SYMBOL>_BYTES, the bounds <SYMBOL>_TILE_BUFFER_MAX_BYTES and <SYMBOL>_WORKSPACE_MAX_BYTES of
// the render from the streams, and for C++'s expand_compressed_blob <SYMBOL>_EXPANDED_BYTES and
// <SYMBOL>_DECODER_RING_BYTES.
#include <cstdint>
#include <string>
#include <vector>

#include "core_bridge/c_source.h"
#include "tristream/compressed_blob.h"

namespace tristream {

// `v1` is the blob the compressed one was made from (its counts bound the band stores) and
// `decoder_bytes` CompressedWorkspace::decoders; the spec's figures are those of the render from
// the streams.
std::string compressed_c_source(const std::vector<std::uint8_t>& bytes, const core::Blob& v1, const CBlobSpec& spec);
std::string compressed_c_header(const core::CompressedBlob& blob, const core::Blob& v1, std::size_t decoder_bytes,
                                const CBlobSpec& spec);

}  // namespace tristream
