/* SPDX-License-Identifier: MIT */
#pragma once
// An emulated RISC-V rv32imc core (unicorn, UC_ARCH_RISCV, UC_MODE_RISCV32) running a benchmark
// program built by riscv/, counting instructions and modelled cycles (riscv_cycle_model.h) with a
// hook per translation block: each block is decoded once, its static cost cached; taken branches,
// jump targets and divisions (a hook on each DIV/DIVU/REM/REMU) are added as they run. Every load
// and store is checked for alignment (the bench fails on a misaligned one: the ESP32-C3 class of
// core traps or splits them). The board is unicorn_machine.h's. The
// calling convention: arguments in a0..a3, the return address in ra, SP and GP set by the harness.
#include <cstdint>
#include <string>
#include <vector>

#include "elf_image.h"
#include "riscv_cycle_model.h"
#include "unicorn_machine.h"

namespace tristream::bench_mcu::riscv {

class RiscvEmulator : public UnicornMachine {
 public:
  // per_instruction: count with a hook on every instruction instead (slow; the check that block
  // counting is exact: same instructions and cycles).
  explicit RiscvEmulator(const ElfImage& elf, bool per_instruction = false);

  // Counts apart the instructions in [begin, end) (the sink of the benchmark program).
  void exclude(std::uint32_t begin, std::uint32_t end);
  RunCounts call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args = {});
  // The stack chain reads Thumb return addresses: not available here (throws when on).
  void set_stack_chain(bool on);
  void block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const;

  // Hook entry points (public for the C callbacks).
  void on_block(std::uint32_t address, std::uint32_t size);
  void on_insn(std::uint32_t address, std::uint32_t size);
  void on_divide(std::uint32_t address);
  void on_access(std::uint32_t address, int size, bool write);

 private:
  struct Cached {
    Block decoded;
    std::uint32_t function = 0;
    bool excluded = false;
    bool entry = false;  // starts at its function's first instruction (RunCounts::function_entries)
  };
  const Cached* block_at(std::uint32_t address, std::uint32_t size);
  // Per-instruction mode: the instruction at `address`, decoded once; its function in *function.
  const Insn* insn_at(std::uint32_t address, std::uint32_t* function);
  void resolve_pending(std::uint32_t next_address, std::uint32_t next_size);
  void add(Counts& c, std::uint32_t function, bool excluded, std::uint64_t cycles);
  bool in_flash(std::uint32_t address) const { return address >= flash_base && address - flash_base < flash_size; }

  bool per_instruction_;
  std::uint32_t global_pointer_ = 0;
  std::vector<Cached> blocks_;
  std::vector<std::int32_t> insn_index_;  // per-instruction mode: index into insns_, or -1
  std::vector<Insn> insns_;
  std::vector<std::uint32_t> insn_functions_;  // the function of each of insns_
  std::vector<DivideSite> divides_;
  // The last instruction was a branch (taken when the next is not at pending_fallthrough_) or a
  // jump (its target's alignment is paid when the next instruction is known).
  bool pending_branch_ = false, pending_jump_ = false;
  std::uint32_t pending_fallthrough_ = 0;
  Counts* pending_counts_ = nullptr;
  std::uint32_t pending_function_ = 0;
  bool pending_excluded_ = false;
  // Where the last instruction (or block) ended and what it left for the next in a straight line.
  std::uint32_t previous_end_ = 0;
  Context previous_exit_;
};

}  // namespace tristream::bench_mcu::riscv
