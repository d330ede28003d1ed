/* SPDX-License-Identifier: MIT */
#pragma once
// The cores bench-mcu models, and their names. One name per core everywhere: the command line
// (--cpus, --<name>-elf-dir, calibrate --cpu), the JSON lines' "cpu", the build script
// (build-<name>.sh) and run.sh's build directory (bench-mcu-<name>).
#include <array>
#include <cstdint>
#include <string>

namespace tristream::bench_mcu {

// The Cortex-M4 (cycle_model.h), the Cortex-M0+ (ARMv6-M, cycle_model_m0plus.h; both run by
// m4_emulator.h) and RISC-V rv32imc (riscv_emulator.h).
enum class Core { m4, m0plus, rv32imc };
inline constexpr std::array<Core, 3> all_cores = {Core::m4, Core::m0plus, Core::rv32imc};

// "m4", "m0plus", "rv32imc".
const char* core_name(Core core);
// "Cortex-M4", "Cortex-M0+", "RISC-V rv32imc": the summary tables' titles.
const char* core_title(Core core);
// The core of a name of core_name; throws UsageError for another name.
Core parse_core(const std::string& name);
// The ELF machine (e_machine) of the core's programs: EM_ARM or EM_RISCV.
std::uint16_t core_machine(Core core);

}  // namespace tristream::bench_mcu
