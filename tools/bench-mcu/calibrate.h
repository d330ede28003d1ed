/* SPDX-License-Identifier: MIT */
#pragma once
// bench_mcu calibrate: the hand-counted loops of m4/calibrate.S (m0plus/calibrate.S,
// riscv/calibrate.S) must count exactly.
#include <string>

#include "cores.h"

namespace tristream::bench_mcu {

// Runs every case of calibrate.elf's table on `core` with block counting and with per-instruction
// counting and prints one line each; 0 when all count exactly, else 1. Throws DataError for an
// empty table or an image of another architecture than the core's. An image with a table
// refusal_cases (name, function, first argument, the error's expected text: the Cortex-M0+'s and
// RISC-V's) must also fail each of those calls, both countings, with an error containing that text.
int calibrate(const std::string& path, Core core = Core::m4);

}  // namespace tristream::bench_mcu
