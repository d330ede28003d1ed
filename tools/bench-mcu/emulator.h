/* SPDX-License-Identifier: MIT */
#pragma once
// What the matrix and the calibration ask of an emulated core, whichever it is: the Cortex-M4 or
// the Cortex-M0+ (m4_emulator.h) or RISC-V rv32imc (riscv_emulator.h). All use the same board (the
// memory map and Counts of m4_emulator.h) and report the same counts.
#include <cstdint>
#include <memory>
#include <vector>

#include "cores.h"
#include "elf_image.h"
#include "m4_emulator.h"

namespace tristream::bench_mcu {

class Emulator {
 public:
  virtual ~Emulator() = default;
  virtual void write(std::uint32_t address, const void* data, std::size_t size) = 0;
  virtual void read(std::uint32_t address, void* data, std::size_t size) = 0;
  virtual void fill(std::uint32_t address, std::uint32_t word, std::size_t words) = 0;
  // Reloads the writable segments from the image (initial .data, zero .bss).
  virtual void reset_data() = 0;
  // Counts apart the instructions in [begin, end) (the sink of the benchmark program).
  virtual void exclude(std::uint32_t begin, std::uint32_t end) = 0;
  // Calls the function at `function` with the first argument registers = args and SP = stack_top,
  // until it returns; throws std::runtime_error on a fault or a counting error.
  virtual RunCounts call(std::uint32_t function, std::uint32_t stack_top,
                         const std::vector<std::uint32_t>& args = {}) = 0;
  virtual const std::vector<ElfFunction>& functions() const = 0;
  virtual void set_address_profile(bool on) = 0;
  virtual void set_stack_chain(bool on) = 0;
  virtual void block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const = 0;
};

// An emulator of `core` running `elf`; per_instruction: count with a hook on every instruction
// (the check that block counting is exact). Throws DataError when the image is not of the core's
// architecture (ARM or RISC-V; a Cortex-M4 build run as a Cortex-M0+ stops at its first
// instruction outside ARMv6-M).
std::unique_ptr<Emulator> make_emulator(Core core, const ElfImage& elf, bool per_instruction);

}  // namespace tristream::bench_mcu
