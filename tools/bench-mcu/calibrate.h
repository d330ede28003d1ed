/* SPDX-License-Identifier: MIT */
#pragma once
// bench_mcu calibrate: the hand-counted loops of m4/calibrate.S must count exactly.
#include <string>

#include "cycle_model.h"

namespace tristream::bench_mcu {

// Runs every case of calibrate.elf's table with block counting and with per-instruction counting
// and prints one line each; 0 when all count exactly, else 1. Throws DataError for an empty table.
// An image with a table refusal_cases (name, function, r0, the message's expected text: the
// Cortex-M0+'s) must also fail each of those calls with an error containing that text.
int calibrate(const std::string& path, Core core = Core::m4);

}  // namespace tristream::bench_mcu
