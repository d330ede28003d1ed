/* SPDX-License-Identifier: MIT */
#pragma once
// The Cortex-M0+ cycle model of bench-mcu (docs/MCU_BENCH.md, "The Cortex-M0+"): ARMv6-M only,
// each instruction's cost from the Cortex-M0+ Technical Reference Manual's instruction timings,
// zero wait states, the single-cycle multiplier (as on the RP2040). No cost depends on the
// instruction before; a conditional branch costs m0plus_taken_extra more when taken.
#include <capstone/capstone.h>

#include <string>

#include "cycle_model.h"

namespace tristream::bench_mcu {

// B<cond>: 1 cycle not taken, 2 taken.
inline constexpr int m0plus_taken_extra = 1;

// The cost of one instruction on the Cortex-M0+. An instruction outside ARMv6-M (any 32-bit
// encoding but BL, MSR, MRS, DMB, DSB, ISB and UDF; CBZ, CBNZ, IT) sets `refused` to its mnemonic
// and operands.
DecodedInsn cost_m0plus(const cs_insn& insn, std::string* refused);

}  // namespace tristream::bench_mcu
