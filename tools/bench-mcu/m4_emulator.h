/* SPDX-License-Identifier: MIT */
#pragma once
// An emulated Cortex-M4 (unicorn, UC_MODE_THUMB | UC_MODE_MCLASS, CPU model Cortex-M4) running a
// benchmark program, counting instructions and modelled cycles (cycle_model.h) with a hook per
// translation block: each block is decoded once, its static cost cached; taken conditional
// branches (the next block is not the fall-through) and divisions (a hook on each SDIV/UDIV) are
// added as they run. The board and its memory are unicorn_machine.h's.
#include <cstdint>
#include <string>
#include <vector>

#include "cycle_model.h"
#include "elf_image.h"
#include "unicorn_machine.h"

namespace tristream::bench_mcu {

class M4Emulator : public UnicornMachine {
 public:
  // per_instruction: count with a hook on every instruction instead (slow; the check that block
  // counting is exact: same instructions and cycles).
  // core: Core::m0plus runs unicorn's Cortex-M0 model, costs by cycle_model_m0plus.h, refuses any
  // instruction outside ARMv6-M and any halfword or word access not aligned to its size (the
  // emulator would run both).
  explicit M4Emulator(const ElfImage& elf, bool per_instruction = false, Core core = Core::m4);

  // Counts apart the instructions in [begin, end) (the sink of the benchmark program).
  void exclude(std::uint32_t begin, std::uint32_t end);
  // Calls the Thumb function at `function` with r0..r3 = args and SP = stack_top, until it
  // returns; throws std::runtime_error on a fault or a counting error.
  RunCounts call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args = {});
  // Whether call() fills RunCounts::stack_chain (reads SP at every block: slower).
  void set_stack_chain(bool on) { stack_chain_ = on; }
  // Size in bytes and static cycles of the last block decoded at `address` (0, 0 for none).
  void block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const;

  // Hook entry points (public for the C callbacks).
  void on_block(std::uint32_t address, std::uint32_t size);
  void on_insn(std::uint32_t address, std::uint32_t size);
  void on_divide(std::uint32_t address);
  void on_access(std::uint32_t address, int size);

 private:
  struct Block {
    DecodedBlock decoded;
    std::uint32_t function = 0;
    bool excluded = false;
    bool entry = false;  // starts at its function's first instruction
    // Cycles to add when entered by falling through (entry_cycles), once known.
    bool fallthrough_known = false;
    int fallthrough_cycles = 0;
  };
  const Block& block_at(std::uint32_t address, std::uint32_t size);
  void resolve_pending(std::uint32_t next_address);
  int entry_cycles(std::uint32_t address);
  void count_entry(const Block& b, std::uint32_t address);
  void skip_to(std::uint32_t address);
  void finish_block();
  void watch_stack(std::uint32_t address);
  bool follows_call(std::uint32_t return_address);
  void count_insn(const DecodedInsn& insn);

  CycleModel model_;
  int taken_extra_;
  bool per_instruction_;
  std::vector<Block> blocks_;
  std::vector<DivideSite> divides_;
  bool stack_chain_ = false;
  std::uint32_t stack_top_ = 0, lowest_sp_ = 0;
  std::uint32_t block_address_ = 0;  // the block running (the Cortex-M0+'s alignment errors name it)
  // Pending taken-branch decision: the last block (or instruction) was a conditional branch.
  bool pending_ = false;
  // The block that ran last: where it ended and the context its last instruction left.
  std::uint32_t previous_end_ = 0;
  InsnContext previous_exit_;
  std::uint32_t pending_fallthrough_ = 0;
  Counts* pending_counts_ = nullptr;
  std::uint32_t pending_function_ = 0;
  // Per-instruction mode: the block being executed and the next instruction expected in it.
  const Block* current_ = nullptr;
  std::size_t current_insn_ = 0;
};

}  // namespace tristream::bench_mcu
