/* SPDX-License-Identifier: MIT */
#pragma once
// The RISC-V rv32imc cycle model of bench-mcu (docs/MCU_BENCH.md has the table and its source, the
// CV32E40X user manual's "Pipeline Details": an in-order 4-stage RV32IMC core, zero-wait-state
// memory): a decoder of RV32IMC written for the bench (capstone 4 has no RISC-V), each instruction's
// static cost, and the hazards between an instruction and the one before it in a straight line.
// Three parts are dynamic and added while running: a taken branch's refill, a jump's or taken
// branch's target that is a 32-bit instruction not on a word boundary, and a division's cycles by
// its divisor. Anything outside RV32IMC (A, F, D, CSR) does not decode: the bench fails on it.
#include <cstdint>
#include <vector>

#include "cycle_model.h"
#include "elf_image.h"

namespace tristream::bench_mcu::riscv {

// Cycles a taken branch costs beyond its 1 (the manual: 3 taken, 1 not taken).
inline constexpr int taken_branch_extra = 2;
// Cycles a jump (JAL, JALR and their compressed forms) costs.
inline constexpr int jump_cycles = 2;
// Static cost of a division or remainder: its operand-dependent cycles (divide_cycles) less this
// are added while running, so `division_cycles_beyond_2` keeps its meaning.
inline constexpr int divide_static_cycles = 2;

struct Insn {
  std::uint32_t address = 0;
  std::uint8_t size = 0;    // 2 or 4
  std::uint8_t cycles = 0;  // static cost, without hazards
  InsnClass klass = class_alu;
  std::uint8_t rd = 0;   // register written (0: none)
  std::uint8_t rs1 = 0;  // registers read (0: none, or x0)
  std::uint8_t rs2 = 0;
  bool load = false;
  bool branch = false;    // conditional: taken when the next instruction is not the next in memory
  bool jump = false;      // JAL, JALR, C.J, C.JAL, C.JR, C.JALR
  bool indirect = false;  // JALR, C.JR, C.JALR (the register hazard)
  bool divide = false;    // DIV, DIVU, REM, REMU
  bool divide_signed = false;
};

// Decodes the instruction at `code` (at least 2 bytes; 4 when the first halfword says so:
// `available` is how many there are). False when it is not an RV32IMC instruction.
bool decode(const std::uint8_t* code, std::uint32_t available, std::uint32_t address, Insn* out);

// What the next instruction's cost depends on of the one before it in a straight line: a load's
// result register (the load-use hazard) and any register written (the JALR hazard). A jump or a
// taken branch leaves none: the refill it costs covers the hazards.
struct Context {
  std::uint8_t loaded = 0;
  std::uint8_t written = 0;
};

// The cycles `insn` costs after an instruction that left `before`, and what it leaves.
int cost_after(const Insn& insn, const Context& before, Context* after);

// Cycles of a jump's or taken branch's refill beyond the static cost, by its target: 1 when the
// target is a 32-bit instruction not on a word boundary.
int target_extra(std::uint32_t target, std::uint32_t target_size);

// Cycles of DIV, DIVU, REM and REMU: 3 + the divisor's leading zeros (of its magnitude when
// signed), 35 for a divisor of 0: 3 .. 35.
int divide_cycles(std::uint32_t divisor, bool is_signed);

// A block of straight-line code as unicorn translates it, decoded and costed.
struct Block {
  std::uint32_t address = 0;
  std::uint32_t size = 0;
  std::uint32_t cycles = 0;  // static costs and hazards within the block, the first after none
  std::uint32_t by_class[class_count] = {};
  std::vector<Insn> insns;
  Context exit;  // after the last instruction
  bool ends_with_branch() const { return !insns.empty() && insns.back().branch; }
  bool ends_with_jump() const { return !insns.empty() && insns.back().jump; }
};

// False when the bytes do not decode exactly into RV32IMC instructions.
bool decode_block(const std::uint8_t* code, std::uint32_t size, std::uint32_t address, Block* out);

struct DivideSite {
  std::uint32_t address = 0;
  bool is_signed = false;
  int divisor_reg = 0;  // unicorn register id
};

// Every DIV, DIVU, REM and REMU of the image's functions (decoded from each function symbol's
// start; bytes that do not decode are stepped over by halfwords).
std::vector<DivideSite> find_divides(const ElfImage& elf);

}  // namespace tristream::bench_mcu::riscv
