/* SPDX-License-Identifier: MIT */
#pragma once
// The tables bench_mcu run prints after its JSON lines: cycles per pixel side by side with the
// ratios between configurations, the cost of ts_open, compressed blobs against v1, and the largest
// stack of each method against core_stack_bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tristream::bench_mcu {

// One configuration that ran.
struct Row {
  std::string mesh, output, tiling, method, opt;
  bool dither;
  bool compressed;
  double cycles_per_pixel;
  std::uint32_t stack;
  std::size_t blob_bytes;
  std::uint64_t open_cycles;
};


// v / n, 0 for no n.
inline double per(std::uint64_t v, double n) { return n > 0 ? double(v) / n : 0; }

// The cycles per pixel, ts_open and compressed tables, rows in the order of meshes, outputs
// (their names, WxH) and tilings.
// core: the titles' name of the core (core_title).
void print_summary(const std::vector<Row>& rows, const std::vector<std::string>& meshes,
                   const std::vector<std::string>& outputs, const std::vector<std::string>& tilings,
                   const char* core = "Cortex-M4");
// Per method the largest stack high-water mark, v1 and compressed, beside core_stack_bytes and
// core_compressed_stack_bytes.
void print_stack_summary(const std::vector<Row>& rows, const std::vector<std::string>& methods);

}  // namespace tristream::bench_mcu
