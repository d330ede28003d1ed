/* SPDX-License-Identifier: MIT */
#pragma once
// The Cortex-M4 cycle model of bench-mcu (docs/MCU_BENCH.md has the table and its sources): each
// Thumb-2 instruction gets a static cost from the Technical Reference Manual's instruction timing
// table, in the context of the instruction before it in its block (load pipelining, the address
// generation stall, IT folding); two parts are dynamic and added while running: a taken
// conditional branch costs the pipeline refill P, and a division costs 2..12 cycles by its
// operands. Zero-wait-state memory.
#include <cstdint>
#include <string>
#include <vector>

#include "elf_image.h"

namespace tristream::bench_mcu {

// P of the TRM: the cycles of a pipeline refill after a taken branch (1..3 on the M4, by the
// target's alignment and width and whether the branch was speculated); one value for all.
inline constexpr int pipeline_refill = 2;

// The cores the bench models: the Cortex-M4 (this file's model) and the Cortex-M0+ (ARMv6-M,
// cycle_model_m0plus.h).
enum class Core { m4, m0plus };
// "m4" or "m0plus"; throws UsageError for another name.
Core parse_core(const std::string& name);
// "Cortex-M4", "Cortex-M0+".
const char* core_title(Core core);

enum InsnClass : std::uint8_t {
  class_alu,        // data processing, moves, shifts, compares, extends, bit fields, IT, NOP
  class_multiply,   // MUL, MLA, MLS, the long multiplies and the DSP multiplies
  class_divide,     // SDIV, UDIV
  class_load,       // single loads (LDR, LDRB, LDRH, LDRSB, LDRSH, LDREX)
  class_store,      // single stores
  class_multiple,   // LDM, STM, PUSH, POP, LDRD, STRD
  class_branch,     // B, BL, BX, BLX, CBZ, CBNZ, TBB, TBH and any other write to PC
  class_other,      // anything else (system, floating point): costed 1, reported to spot surprises
  class_count
};

const char* class_name(int c);

struct DecodedInsn {
  std::uint32_t address = 0;
  std::uint8_t size = 0;
  std::uint8_t cycles = 0;  // static cost; a division's minimum (2)
  InsnClass klass = class_alu;
  bool conditional_branch = false;  // costs P more when the next instruction is not the next in memory
  bool conditional = false;         // has a condition (in an IT block, or a conditional branch)
};

// What an instruction's cost depends on of the instruction before it: IT folding after a 16-bit
// instruction, load pipelining, the address generation stall.
struct InsnContext {
  bool valid = false;
  bool sixteen_bit = false;
  unsigned pipelined_load_dest = 0;  // capstone's ARM_REG_INVALID: none
  bool load_pipelinable = false;
  unsigned written[4] = {};  // registers a data-processing instruction wrote (address generation stall)
  int written_count = 0;
};

struct DecodedBlock {
  std::uint32_t address = 0;
  std::uint32_t size = 0;
  std::uint32_t cycles = 0;  // sum of the static costs, the first instruction's after none
  std::uint32_t by_class[class_count] = {};
  std::vector<DecodedInsn> insns;
  InsnContext exit;  // after the last instruction
  int it_left = 0;   // as decoded
  std::string refused;  // an instruction the core does not have: "0x<address> <mnemonic> <operands>"
  bool ends_with_conditional_branch() const { return !insns.empty() && insns.back().conditional_branch; }
};

struct DivideSite {
  std::uint32_t address = 0;
  bool is_signed = false;
  int dividend_reg = 0;  // unicorn register ids
  int divisor_reg = 0;
};

class CycleModel {
 public:
  explicit CycleModel(Core core = Core::m4);
  ~CycleModel();
  CycleModel(const CycleModel&) = delete;
  CycleModel& operator=(const CycleModel&) = delete;

  // Decodes [address, address + size) as one block of Thumb-2 code (a unicorn translation block)
  // and costs it. Returns false when the bytes do not decode exactly into instructions.
  // it_left: instructions of an IT block still to come at the block's start (a block may begin
  // inside one; from the processor's ITSTATE).
  bool decode_block(const std::uint8_t* code, std::uint32_t size, std::uint32_t address, DecodedBlock* out,
                    int it_left = 0) const;
  // The static cost of the instruction at `address` (the first of `code`) after an instruction
  // that left `prev`: a block entered by falling through from the one before it in memory (a
  // translation block ends where the M4's pipeline does not, e.g. at a page boundary) costs its
  // first instruction so, as if the two were one block.
  int first_cycles_after(const std::uint8_t* code, std::uint32_t size, std::uint32_t address, const InsnContext& prev,
                         int it_left) const;
  // Cycles a conditional branch costs more when taken.
  int taken_extra() const;
  // Every SDIV and UDIV in the image's Thumb code ranges.
  std::vector<DivideSite> find_divides(const ElfImage& elf) const;

 private:
  std::size_t handle_ = 0;
  Core core_;
};

// Cycles of SDIV / UDIV: 2 when the quotient is 0 (or the divisor is 0), else 2 plus the number
// of quotient bits q (the leading-bit distance of the magnitudes plus 1) scaled to 1..10:
// 2 + ceil(10 q / 32), so 2..12 as in the TRM, which documents only the range and early
// termination on the operands' leading zeros.
int divide_cycles(std::uint32_t dividend, std::uint32_t divisor, bool is_signed);

}  // namespace tristream::bench_mcu
