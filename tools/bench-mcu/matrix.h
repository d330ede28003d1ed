/* SPDX-License-Identifier: MIT */
#pragma once
// bench_mcu run: every configuration of the matrix (meshes x methods x blob kinds x outputs x
// tilings x optimisation levels x dithering) on each emulated core asked for (cores.h), one JSON line
// each on stdout (per mesh and method, each core's configurations in turn), then the summary tables
// per core (summary.h; panel_table.h for the Cortex-M4 only).
#include <array>
#include <string>
#include <vector>

#include "cores.h"

namespace tristream::bench_mcu {

struct RunOptions {
  // The build directory of each core's programs, by Core ("": not given): m4/ built by
  // build-m4.sh and by build-m0plus.sh, riscv/ by build-rv32imc.sh.
  std::array<std::string, all_cores.size()> elf_dirs;
  // The cores to run (core_name), in this order; empty: every core whose directory is given.
  std::vector<std::string> cpus;
  std::vector<std::string> meshes, methods, opts, dithers, outputs, tilings, blob_kinds;
  bool check_counts = false;  // run each configuration again counting per instruction
  bool check_stack = false;   // a stack above core_stack_bytes fails the run
  int profile = 0;            // the functions with the most cycles on each line
  std::string address_profile;  // the file every block run is written to ("" = none)
  bool stack_chain = false;     // the calls live at the stack's high-water mark on each line
};

// 0 when every render on every core equals the host's (and the checks asked for pass), else 1 with a
// message on stderr. Throws UsageError for an unknown name in the matrix.
int run_matrix(const RunOptions& options);

}  // namespace tristream::bench_mcu
