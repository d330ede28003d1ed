// SPDX-License-Identifier: MIT
#include "report.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "common/json_name.h"

namespace tristream::tripack {

namespace {

// "tiles 32x32", "bands of 16 rows" or "full frame".
std::string tiling_text(const PackReport& r) {
  const std::string w = r.tile_width ? std::to_string(r.tile_width) : std::string("full-width");
  const std::string h = r.tile_height ? std::to_string(r.tile_height) : std::string("full-height");
  return r.tile_width == 0 && r.tile_height == 0 ? std::string("full frame")
         : r.tile_width == 0                     ? "bands of " + h + " rows"
                                                 : "tiles " + w + "x" + h;
}

void print_compressed_text(const PackReport& r, const std::string& tiles) {
  const CompressedReport& c = *r.compressed;
  const CompressStats& s = c.stats;
  const double n = double(s.vertices);
  std::printf("%s: compressed blob %zu bytes (%s), v1 %zu bytes (%.2fx)\n", r.output.c_str(), c.bytes,
              r.method.c_str(), r.v1_bytes, double(r.v1_bytes) / double(c.bytes));
  std::printf("bits per vertex (%llu vertices, %llu triangles): positions %.2f + values %.2f + gradients %.2f + "
              "connectivity %.2f + flags %.2f = %.2f\n",
              static_cast<unsigned long long>(s.vertices), static_cast<unsigned long long>(s.triangles),
              s.position_bits / n, s.value_bits / n, s.gradient_bits / n, s.connectivity_bits / n, s.flag_bits / n,
              8.0 * double(c.bytes) / n);
  if (r.method == "zienkiewicz") {
    std::string steps;
    for (std::uint32_t b : s.gradient_step_bits) steps += (steps.empty() ? "" : ", ") + std::to_string(b);
    std::printf("gradient step bits per layer (each gradient component coded in units of 2^bits): %s\n", steps.c_str());
  }
  std::printf("decoder RAM: ring %zu + state %zu bytes; expanded v1 blob %zu bytes\n", c.decoder_ring_bytes,
              c.decoder_state_bytes, c.expanded_bytes);
  const core::CompressedWorkspace& f = c.workspace;
  std::printf("RAM rendered from the stream for %s, %s: tile buffer %zu + workspace %zu (8 + channel scratch %zu "
              "+ decoders and rings %zu + %d x band store %zu for at most %u live triangles and %u live "
              "vertices in a band) + stack %zu (Cortex-M4) = %zu bytes\n",
              r.format.c_str(), tiles.c_str(), c.tile_buffer_bytes, f.bytes, f.channel_scratch, f.decoders,
              c.layer_count, f.band_store, unsigned(f.live_triangles), unsigned(f.live_vertices), c.stack_bytes,
              c.ram_bytes());
  std::printf("RAM of its v1 blob (read in place from flash, %zu bytes):\n", r.v1_bytes);
}

nlohmann::json compressed_json(const CompressedReport& c) {
  const CompressStats& s = c.stats;
  const double n = double(s.vertices);
  const core::CompressedWorkspace& f = c.workspace;
  nlohmann::json j;
  j["expanded_bytes"] = c.expanded_bytes;
  j["decoder_ring_bytes"] = c.decoder_ring_bytes;
  j["decoder_state_bytes"] = c.decoder_state_bytes;
  j["stream_render"] = {{"tile_buffer_bytes", c.tile_buffer_bytes},
                        {"workspace_bytes", f.bytes},
                        {"decoders_bytes", f.decoders},
                        {"band_store_bytes", f.band_store},
                        {"live_triangles", f.live_triangles},
                        {"live_vertices", f.live_vertices},
                        {"channel_scratch_bytes", f.channel_scratch},
                        {"stack_bytes", c.stack_bytes},
                        {"ram_bytes", c.ram_bytes()}};
  j["vertices"] = s.vertices;
  j["triangles"] = s.triangles;
  j["bits_per_vertex"] = {{"positions", s.position_bits / n},
                          {"values", s.value_bits / n},
                          {"gradients", s.gradient_bits / n},
                          {"connectivity", s.connectivity_bits / n},
                          {"flags", s.flag_bits / n},
                          {"total", 8.0 * double(c.bytes) / n}};
  j["gradient_step_bits"] = s.gradient_step_bits;
  return j;
}

}  // namespace

void print_text(const PackReport& r) {
  const std::string tiles = tiling_text(r);
  if (r.compressed) print_compressed_text(r, tiles);
  else std::printf("%s: blob %zu bytes (%s)\n", r.output.c_str(), r.v1_bytes, r.method.c_str());
  std::printf("RAM for %s, %s: tile buffer %zu + workspace %zu + stack %zu (Cortex-M4) = %zu bytes\n",
              r.format.c_str(), tiles.c_str(), r.tile_buffer_bytes, r.workspace_bytes, r.stack_bytes, r.ram_bytes());
  std::printf("upper bound for outputs up to %dx%d, any viewport, %s at most: tile buffer %zu + workspace %zu + "
              "stack %zu = %zu bytes\n",
              r.output_width, r.output_height, tiles.c_str(), r.bound.tile_buffer_bytes, r.bound.workspace_bytes,
              r.stack_bytes, r.bound.tile_buffer_bytes + r.bound.workspace_bytes + r.stack_bytes);
}

// One object (keys in name order); with --compress blob_bytes is the compressed blob's and
// v1_bytes the v1 blob's.
void print_json(const PackReport& r) {
  nlohmann::json j = r.compressed ? compressed_json(*r.compressed) : nlohmann::json::object();
  j["output"] = json_file_name(r.output);
  j["method"] = r.method;
  j["format"] = r.format;
  j["tile"] = r.tile;
  j["tile_width"] = r.tile_width;
  j["tile_height"] = r.tile_height;
  j["blob_bytes"] = r.compressed ? r.compressed->bytes : r.v1_bytes;
  if (r.compressed) j["v1_bytes"] = r.v1_bytes;
  j["tile_buffer_bytes"] = r.tile_buffer_bytes;
  j["workspace_bytes"] = r.workspace_bytes;
  j["stack_bytes"] = r.stack_bytes;
  j["ram_bytes"] = r.ram_bytes();
  j["tile_buffer_max_bytes"] = r.bound.tile_buffer_bytes;
  j["workspace_max_bytes"] = r.bound.workspace_bytes;
  std::printf("%s\n", j.dump(2).c_str());
}

}  // namespace tristream::tripack
