/* SPDX-License-Identifier: MIT */
#pragma once
// bench_mcu run: every configuration of the matrix (meshes x methods x blob kinds x outputs x
// tilings x optimisation levels x dithering) on the emulated Cortex-M4, one JSON line each on stdout
// in that order, then the summary tables (summary.h, panel_table.h).
#include <string>
#include <vector>

namespace tristream::bench_mcu {

struct RunOptions {
  std::string elf_dir;     // the build directory of m4/ (build-m4.sh, build-m0plus.sh)
  std::string cpu = "m4";  // the core the programs are built for and run on (parse_core)
  std::vector<std::string> meshes, methods, opts, dithers, outputs, tilings, blob_kinds;
  bool check_counts = false;  // run each configuration again counting per instruction
  bool check_stack = false;   // a stack above core_stack_bytes fails the run
  int profile = 0;            // the functions with the most cycles on each line
  std::string address_profile;  // the file every block run is written to ("" = none)
  bool stack_chain = false;     // the calls live at the stack's high-water mark on each line
};

// 0 when every render on the M4 equals the host's (and the checks asked for pass), else 1 with a
// message on stderr. Throws UsageError for an unknown name in the matrix.
int run_matrix(const RunOptions& options);

}  // namespace tristream::bench_mcu
