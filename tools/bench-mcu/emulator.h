/* SPDX-License-Identifier: MIT */
#pragma once
// What the matrix and the calibration ask of an emulated core, whichever it is: the Cortex-M4
// (m4_emulator.h) or RISC-V rv32imc (riscv_emulator.h). Both use the same board (the memory map
// and Counts of m4_emulator.h) and report the same counts.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

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

// What the JSON lines and tables call a core of the bench: "m4" (Cortex-M4), "riscv" (rv32imc).
std::string cpu_label(const std::string& cpu);
// The core an image is built for, by its ELF machine: "m4" or "riscv".
std::string cpu_of(const ElfImage& elf);
// An emulator of `cpu` running `elf`; per_instruction: count with a hook on every instruction
// (the check that block counting is exact).
std::unique_ptr<Emulator> make_emulator(const std::string& cpu, const ElfImage& elf, bool per_instruction);

}  // namespace tristream::bench_mcu
