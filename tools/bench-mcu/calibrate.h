/* SPDX-License-Identifier: MIT */
#pragma once
// bench_mcu calibrate: the hand-counted loops of m4/calibrate.S (riscv/calibrate.S) must count exactly.
#include <string>

namespace tristream::bench_mcu {

// Runs every case of calibrate.elf's table with block counting and with per-instruction counting
// and prints one line each; 0 when all count exactly, else 1. Throws DataError for an empty table.
int calibrate(const std::string& path);

}  // namespace tristream::bench_mcu
