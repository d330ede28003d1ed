// SPDX-License-Identifier: MIT
#include "cores.h"

#include <elf.h>

#include "common/errors.h"

namespace tristream::bench_mcu {

const char* core_name(Core core) {
  switch (core) {
    case Core::m4: return "m4";
    case Core::m0plus: return "m0plus";
    case Core::rv32imc: return "rv32imc";
  }
  return "?";
}

const char* core_title(Core core) {
  switch (core) {
    case Core::m4: return "Cortex-M4";
    case Core::m0plus: return "Cortex-M0+";
    case Core::rv32imc: return "RISC-V rv32imc";
  }
  return "?";
}

Core parse_core(const std::string& name) {
  for (Core c : all_cores)
    if (name == core_name(c)) return c;
  throw UsageError("unknown core '" + name + "' (expected m4, m0plus or rv32imc)");
}

std::uint16_t core_machine(Core core) { return core == Core::rv32imc ? EM_RISCV : EM_ARM; }

}  // namespace tristream::bench_mcu
