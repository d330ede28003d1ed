/* SPDX-License-Identifier: MIT */
#pragma once
// What tripack reports about one packing: the figures, computed once (PackReport), and the two
// forms they are printed in, text for people and JSON for machines.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "core_bridge/c_source.h"
#include "core_bridge/compress.h"
#include "tristream/render.h"

namespace tristream::tripack {

// The compressed blob (--compress): its size and bits, its expansion, and its render from the
// streams at the same options.
struct CompressedReport {
  std::size_t bytes = 0;
  CompressStats stats;
  std::size_t expanded_bytes = 0;       // core::expanded_blob_size
  std::size_t decoder_ring_bytes = 0;   // core::expand_workspace_size
  std::size_t decoder_state_bytes = 0;  // sizeof(core::LayerDecoder)
  int layer_count = 0;
  std::size_t tile_buffer_bytes = 0;  // the render from the streams
  core::CompressedWorkspace workspace;
  std::size_t stack_bytes = 0;  // core_compressed_stack_bytes
  std::size_t ram_bytes() const { return tile_buffer_bytes + workspace.bytes + stack_bytes; }
};

struct PackReport {
  std::string output, method, format;  // as given on the command line
  int tile = 0;                        // --tile as given
  int tile_width = 0, tile_height = 0;  // the tiling the figures are for (0: the viewport's side)
  std::size_t v1_bytes = 0;             // the v1 blob
  // A render of the v1 blob, read in place, at these options; the stack is the Cortex-M4 figure
  // make bench-mcu measured (core_bridge/core_stack.h).
  std::size_t tile_buffer_bytes = 0, workspace_bytes = 0, stack_bytes = 0;
  int output_width = 0, output_height = 0;  // the largest output the bound is for
  BufferBounds bound;                       // any viewport and tile up to the tiling's
  std::optional<CompressedReport> compressed;
  std::size_t ram_bytes() const { return tile_buffer_bytes + workspace_bytes + stack_bytes; }
};

// Both print to stdout.
void print_text(const PackReport& r);
void print_json(const PackReport& r);

}  // namespace tristream::tripack
