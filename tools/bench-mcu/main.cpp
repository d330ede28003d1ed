// SPDX-License-Identifier: MIT
// bench_mcu: runs firmware_core on an emulated Cortex-M4, Cortex-M0+ (m4_emulator.h) or RISC-V
// rv32imc (riscv_emulator.h) and reports instructions, modelled cycles, stack, RAM and flash per
// configuration, with the pixels checked against the host build of the core. docs/MCU_BENCH.md
// describes the models and the matrix.
//   bench_mcu run [--cpus m4,m0plus,rv32imc] --m4-elf-dir <dir> --m0plus-elf-dir <dir>
//                 --rv32imc-elf-dir <dir> [matrix options]
//                          one JSON line per configuration, then the summary per core (matrix.h)
//   bench_mcu calibrate [--cpu m4|m0plus|rv32imc] <calibrate.elf>
//                          the hand-counted loops must count exactly (calibrate.h)
#include <CLI/CLI.hpp>
#include <string>

#include "bench_meshes.h"
#include "calibrate.h"
#include "common/tool_main.h"
#include "cores.h"
#include "matrix.h"

using namespace tristream;
using namespace tristream::bench_mcu;

int main(int argc, char** argv) {
  CLI::App app{"Run firmware_core on an emulated Cortex-M4, Cortex-M0+ or RISC-V rv32imc: instructions, modelled\n"
               "cycles, stack, RAM, flash, and the pixels against the host build (docs/MCU_BENCH.md)."};
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
  for (Core c : all_cores) {
    const std::string name = core_name(c);
    // --elf-dir: the Cortex-M4's, as the bench's first core.
    run_cmd->add_option("--" + name + "-elf-dir" + (c == Core::m4 ? ",--elf-dir" : ""), o.elf_dirs[std::size_t(c)],
                        std::string("Build directory of the ") + core_title(c) + " programs (tools/bench-mcu/build-" +
                            name + ".sh)");
  }
  run_cmd->add_option("--cpus", o.cpus, "m4, m0plus, rv32imc (default: every core whose --<core>-elf-dir is given)")
      ->delimiter(',');
  run_cmd->add_option("--meshes", o.meshes, "kodim23, grey1pct, scene4k, grid40k, strip5k, fan4k")->delimiter(',')->capture_default_str();
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
  run_cmd->add_flag("--check-stack", o.check_stack,
                    "Fail when a Cortex-M4 stack high-water mark exceeds core_stack_bytes (other cores': reported)");
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
  cal_cmd->add_option("--cpu", cal_cpu, "m4, m0plus or rv32imc: the core calibrate.elf was built for")
      ->capture_default_str();
  return run_tool("bench_mcu", app, argc, argv, [&]() -> int {
    if (*cal_cmd) return calibrate(cal_elf, parse_core(cal_cpu));
    return run_matrix(o);
  });
}
