// SPDX-License-Identifier: MIT
// bench_mcu: runs firmware_core on an emulated Cortex-M4 (m4_emulator.h) and reports
// instructions, modelled cycles, stack, RAM and flash per configuration, with the pixels checked
// against the host build of the core. docs/MCU_BENCH.md describes the model and the matrix.
//   bench_mcu run --elf-dir <dir> [matrix options]   one JSON line per configuration, then a summary
//                                                    (matrix.h)
//   bench_mcu calibrate <calibrate.elf>              the hand-counted loops must count exactly
//                                                    (calibrate.h)
#include <CLI/CLI.hpp>
#include <string>

#include "bench_meshes.h"
#include "calibrate.h"
#include "common/tool_main.h"
#include "matrix.h"

using namespace tristream;
using namespace tristream::bench_mcu;

int main(int argc, char** argv) {
  CLI::App app{"Run firmware_core on an emulated Cortex-M4: instructions, modelled cycles, stack, RAM, flash,\n"
               "and the pixels against the host build (docs/MCU_BENCH.md)."};
  app.require_subcommand(1);
  CLI::App* run_cmd = app.add_subcommand("run", "Benchmark a matrix of configurations");
  RunOptions o;
  o.meshes = mesh_names();
  o.methods = {"bilinear", "zienkiewicz"};
  o.opts = {"O2", "Os"};
  o.dithers = {"off", "on"};
  o.outputs = {"native", "320x240", "240x240"};
  o.tilings = {"tiles32", "bands16", "frame"};
  o.blob_kinds = {"v1", "compressed"};
  run_cmd->add_option("--elf-dir", o.elf_dir, "Build directory of tools/bench-mcu/m4 (build-m4.sh, build-m0plus.sh)")
      ->required();
  run_cmd->add_option("--cpu", o.cpu, "m4 or m0plus: the core the programs were built for")->capture_default_str();
  run_cmd->add_option("--meshes", o.meshes, "kodim23, scene4k, grid40k")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--methods", o.methods, "bilinear, zienkiewicz")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--opts", o.opts, "O2, Os")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--dither", o.dithers, "off, on")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--outputs", o.outputs, "native or WxH")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--tilings", o.tilings, "tiles32, bands16, frame (the frame where it fits the RAM)")
      ->delimiter(',')
      ->capture_default_str();
  run_cmd->add_option("--blobs", o.blob_kinds,
                      "v1, compressed (the same mesh compressed by the host, rendered from its streams)")
      ->delimiter(',')
      ->capture_default_str();
  run_cmd->add_flag("--check-counts", o.check_counts,
                    "Run each configuration again counting per instruction; the counts must be equal");
  run_cmd->add_flag("--check-stack", o.check_stack, "Fail when a stack high-water mark exceeds core_stack_bytes");
  run_cmd->add_option("--profile", o.profile, "Add the N functions with the most cycles to each line");
  run_cmd->add_option("--profile-addresses", o.address_profile,
                      "Write every block run (configuration, start address, bytes, runs, static cycles; tab-separated) to "
                      "this file, for addr2line on a build with -g");
  run_cmd->add_flag("--stack-chain", o.stack_chain,
                    "Add the calls live at the stack's high-water mark to each line (reads SP at every block: slower)");
  CLI::App* cal_cmd = app.add_subcommand("calibrate", "Count the calibration loops and compare with their table");
  std::string cal_elf;
  cal_cmd->add_option("elf", cal_elf, "calibrate.elf")->required();
  std::string cal_cpu = "m4";
  cal_cmd->add_option("--cpu", cal_cpu, "m4 or m0plus: the core calibrate.elf was built for")->capture_default_str();
  return run_tool("bench_mcu", app, argc, argv, [&]() -> int {
    if (*cal_cmd) return calibrate(cal_elf, parse_core(cal_cpu));
    return run_matrix(o);
  });
}
