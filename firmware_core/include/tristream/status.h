/* SPDX-License-Identifier: MIT */
#pragma once
// Result of every fallible core call. Host tools turn these into messages. Each value has a C
// name in tristream.h (TS_ plus the enumerator in capitals; c_api.cpp checks them): a status added
// here needs one there and a text in status_text.
#include <stdint.h>

namespace tristream::core {

enum class [[nodiscard]] Status : uint8_t {
  ok = 0,
  null_argument,        // a required pointer was null
  truncated,            // the blob is shorter than its header or a section says
  bad_magic,            // the first four bytes are not "TSTB"
  bad_version,          // format version not supported by this core (a v1 blob of version 1: no checksum)
  config_mismatch,      // packed for another sub-pixel or gradient precision
  bad_header,           // sizes, colour space, method, layer layout or reserved fields invalid
  bad_section,          // a section offset is misaligned, overlaps the header or runs past the end
  too_large,            // a size or count beyond the documented limits
  coordinate_out_of_range,  // a vertex outside the domain [0, W-1] x [0, H-1]
  value_out_of_range,       // a vertex value above 255 or a gradient beyond TS_MAX_GRADIENT
  bad_index,            // a triangle refers to a vertex that does not exist, or repeats one
  bad_triangle,         // a triangle with zero or negative area, or unknown flag bits
  unsorted,             // triangles not sorted by their top row
  bad_params,           // render parameters invalid (size, viewport, tile, format)
  tile_buffer_too_small,  // tile buffer smaller than tile_buffer_size() says
  not_compiled,         // pixel format, method, colour space or layering left out of this build (config.h)
  workspace_too_small,  // workspace smaller than workspace_size() says (checked before the first tile)
  stopped,              // the sink stopped the frame (FrameSink returned false)
  bad_checksum,         // the blob's bytes do not match the CRC-32 in its header: damaged
};

// A short English description, for logs.
const char* status_text(Status s);

}  // namespace tristream::core
