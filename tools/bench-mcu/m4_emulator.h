/* SPDX-License-Identifier: MIT */
#pragma once
// An emulated Cortex-M4 (unicorn, UC_MODE_THUMB | UC_MODE_MCLASS, CPU model Cortex-M4) running a
// benchmark program, counting instructions and modelled cycles (cycle_model.h) with a hook per
// translation block: each block is decoded once, its static cost cached; taken conditional
// branches (the next block is not the fall-through) and divisions (a hook on each SDIV/UDIV) are
// added as they run. Memory: the program's flash at 0 (read/execute), 256 KiB of RAM at
// 0x20000000 (read/write), and a read-only region for blobs at rom_base.
#include <cstdint>
#include <string>
#include <vector>

#include "cycle_model.h"
#include "elf_image.h"

struct uc_struct;

namespace tristream::bench_mcu {

inline constexpr std::uint32_t flash_base = 0x00000000u;
inline constexpr std::uint32_t flash_size = 1u << 20;
inline constexpr std::uint32_t ram_base = 0x20000000u;
inline constexpr std::uint32_t ram_size = 256u << 10;
inline constexpr std::uint32_t rom_base = 0x08000000u;
inline constexpr std::uint32_t rom_size = 16u << 20;

struct Counts {
  std::uint64_t instructions = 0;
  std::uint64_t cycles = 0;
  std::uint64_t by_class[class_count] = {};
  std::uint64_t taken_branches = 0;  // conditional branches taken (each paid P)
  std::uint64_t divide_cycles = 0;   // cycles of the divisions beyond their minimum of 2
};

struct RunCounts {
  Counts counted;   // everything but the excluded range
  Counts excluded;  // the excluded range (the benchmark's sink)
  std::vector<std::uint64_t> function_cycles;  // counted cycles per function of functions()
  // Counted runs of a block starting at each function's first instruction: its calls (and any
  // branch back to its start).
  std::vector<std::uint64_t> function_entries;
  // With set_address_profile(true): how many times a counted block started at each halfword of
  // flash, by (address - flash_base) / 2 (see M4Emulator::block_cost for its size and static cost;
  // branch refills and division extras are in the totals only).
  std::vector<std::uint64_t> block_runs;
  // With set_stack_chain(true): at the lowest SP a block started with, the function running and
  // the functions of the return addresses then on the stack (words that follow a BL or BLX in the
  // code; a stale word left in a frame's unused slot passes too), deepest first, each with its
  // distance below the SP of the call.
  struct Frame {
    std::uint32_t depth;      // bytes below the SP the call started with
    std::uint32_t function;   // index into functions()
  };
  std::vector<Frame> stack_chain;
};

class M4Emulator {
 public:
  // per_instruction: count with a hook on every instruction instead (slow; the check that block
  // counting is exact: same instructions and cycles).
  // core: Core::m0plus runs unicorn's Cortex-M0 model, costs by cycle_model_m0plus.h, refuses any
  // instruction outside ARMv6-M and any halfword or word access not aligned to its size (the
  // emulator would run both).
  explicit M4Emulator(const ElfImage& elf, bool per_instruction = false, Core core = Core::m4);
  ~M4Emulator();
  M4Emulator(const M4Emulator&) = delete;
  M4Emulator& operator=(const M4Emulator&) = delete;

  void write(std::uint32_t address, const void* data, std::size_t size);
  void read(std::uint32_t address, void* data, std::size_t size);
  void fill(std::uint32_t address, std::uint32_t word, std::size_t words);
  // Reloads the writable segments from the image (initial .data, zero .bss).
  void reset_data();
  // Counts apart the instructions in [begin, end) (the sink of the benchmark program).
  void exclude(std::uint32_t begin, std::uint32_t end);
  // Calls the Thumb function at `function` with r0..r3 = args and SP = stack_top, until it
  // returns; throws std::runtime_error on a fault or a counting error.
  RunCounts call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args = {});

  const std::vector<ElfFunction>& functions() const { return functions_; }
  // Whether call() fills RunCounts::block_runs (block counting only).
  void set_address_profile(bool on) { address_profile_ = on; }
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
  void fail(const std::string& message);
  void resolve_pending(std::uint32_t next_address);
  int entry_cycles(std::uint32_t address);
  void count_entry(const Block& b, std::uint32_t address);
  void skip_to(std::uint32_t address);
  void finish_block();
  void watch_stack(std::uint32_t address);
  bool follows_call(std::uint32_t return_address);
  void count_insn(const DecodedInsn& insn);
  std::uint32_t function_of(std::uint32_t address) const;

  const ElfImage& elf_;
  uc_struct* uc_ = nullptr;
  CycleModel model_;
  int taken_extra_;
  bool per_instruction_;
  bool address_profile_ = false;
  std::uint32_t halt_ = 0;
  std::uint32_t exclude_begin_ = 0, exclude_end_ = 0;
  std::vector<ElfFunction> functions_;  // the image's, then one for code outside them
  std::vector<std::int32_t> block_index_;  // by (address - flash_base) / 2: index into blocks_, or -1
  std::vector<Block> blocks_;
  std::vector<DivideSite> divides_;
  RunCounts run_;
  std::string error_;
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
