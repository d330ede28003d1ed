/* SPDX-License-Identifier: MIT */
#pragma once
// The C form of a blob (tripack -o x.c): x.c holds the bytes and a ts_blob_descriptor, x.h
// declares it, refuses to compile against a core that cannot render it, and gives compile-time
// upper bounds of the buffers.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tristream/blob.h"
#include "tristream/pixel_format.h"

namespace tristream {

// Whether `name` can be the descriptor's C symbol: an identifier of C and C++, not a keyword of
// either (C89 to C23, C++98 to C++20), not reserved (a leading underscore followed by an upper-case
// letter or another underscore), not main and not in the C API's ts_ / TS_ space.
bool is_blob_symbol(std::string_view name);

// A symbol from an output path: its stem, each character outside [A-Za-z0-9_] replaced by '_',
// prefixed with "blob_" when that is not yet a valid symbol ("int.c" -> blob_int, "7.c" -> blob_7).
std::string blob_symbol_of(std::string_view path);

// Buffer sizes that suffice for every render of `blob` in `format` with an output of at most
// width x height, any fit (stretch, inside, fill) and viewport of it and tiles of at most
// tile_width x tile_height (0: the viewport's width or height). Mirrors the layout of firmware_core's
// workspace (src/workspace_layout.h, src/render.cpp): alignment padding, the channel scratch of layered
// blobs (6 bytes per tile pixel), and per layer an active-set bitmap, here for all of the layer's
// triangles (the window is never longer, whatever the mapping): none of it depends on the fit.
struct BufferBounds {
  std::size_t tile_buffer_bytes = 0;
  std::size_t workspace_bytes = 0;
};
BufferBounds buffer_upper_bounds(const core::Blob& blob, core::PixelFormat format, int width, int height,
                                 int tile_width, int tile_height);
// The same for the compressed blob of `blob` rendered from its streams (render.h): alignment
// padding, the channel scratch, `decoder_bytes` (CompressedWorkspace::decoders, which no output
// changes) and per layer a band store (render.h's need(V, C, F)) for all of the largest layer's
// vertices, triangles and flagged triangles (no band holds more).
BufferBounds compressed_buffer_upper_bounds(const core::Blob& blob, std::size_t decoder_bytes,
                                            core::PixelFormat format, int width, int height, int tile_width,
                                            int tile_height);

// The C value of a format (tristream.h: TS_L8 = 1 ... TS_XRGB8888 = 5); coverage8 has none
// (throws UsageError).
int c_format(core::PixelFormat format);

struct CBlobSpec {
  std::string symbol;       // is_blob_symbol
  std::string source_name;  // for the comment at the top
  core::PixelFormat format = core::PixelFormat::rgb565_be;
  int output_width = 0, output_height = 0;  // what the descriptor's figures are for
  int tile_width = 0, tile_height = 0;
  std::size_t tile_buffer_bytes = 0, workspace_bytes = 0;  // measured for exactly that
};

std::string blob_c_source(const std::vector<std::uint8_t>& bytes, const core::Blob& blob, const CBlobSpec& spec);
std::string blob_c_header(const core::Blob& blob, const CBlobSpec& spec);

// A header and its source, as tripack writes them (io/atomic_pair.h: both or neither).
struct CPair {
  std::string header, source;
};
// Ties a pair together: the header gets <SYMBOL>_PAIR_HASH, the CRC-32 of both texts as generated
// (the blob's bytes, the descriptor, the bounds: anything that differs between two runs), and the
// source includes the header by `header_name` (the file beside it) and stops with an #error unless
// that hash is its own. A header left from another blob or other options therefore fails the
// source's compilation instead of sizing buffers for something else. A `header_name` that cannot
// be spelled in an #include (is_includable_name) gets no include and no check: a comment says so.
void tie_c_pair(CPair& pair, const std::string& symbol, const std::string& header_name);
// Printable ASCII without what an #include "..." leaves undefined or changes: a double quote, a
// backslash, an apostrophe, "//", "/*" and "??" (trigraphs in C89).
bool is_includable_name(std::string_view name);

// Pieces both C forms (v1 and compressed) share.
// The compile-time refusals: a core of another precision, without the blob's method, colour space
// or layering, or without the descriptor's format.
std::string blob_c_guard(core::Method method, core::ColorSpace space, int layer_count, const CBlobSpec& spec);
// A header's opening: its include guard (the symbol's own case, `prefix` + symbol + "_H"), the C
// API's include, and an #error when <SYMBOL>_BYTES is defined already (a header of another blob
// whose symbol differs only in case: the macros, in capitals, would clash).
std::string blob_c_header_opening(const std::string& prefix, const std::string& symbol);
// `static const uint8_t <name>[N] TS_BLOB_ATTRIBUTES = {...};` with the placement macros before it.
std::string blob_c_bytes(const std::vector<std::uint8_t>& bytes, const std::string& name);
// The definition of the ts_blob_descriptor spec.symbol over <symbol>_bytes (`blob`: width, height).
std::string blob_c_descriptor(const core::Blob& blob, const CBlobSpec& spec);
// "W x H" of the tiles, "viewport-wide" / "viewport-high" for 0.
std::string blob_c_tiles(const CBlobSpec& spec);
// Upper case; text for a C comment (no "*/", printable ASCII only).
std::string c_upper(std::string s);
std::string c_comment_safe(std::string s);

}  // namespace tristream
