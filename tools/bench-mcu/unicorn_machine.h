/* SPDX-License-Identifier: MIT */
#pragma once
// The board every emulated core of bench-mcu runs on, and the unicorn plumbing they share: the
// memory map (the program's flash at 0, read/execute; 256 KiB of RAM at 0x20000000, read/write; a
// read-only region for blobs at rom_base), the image's segments loaded into it, memory access from
// the host, the image's functions and the counts a call reports. The core's own emulator
// (m4_emulator.h, riscv_emulator.h) adds its hooks, its cycle model and its calling convention.
#include <cstdint>
#include <string>
#include <utility>
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
  // flash, by (address - flash_base) / 2 (see the emulator's block_cost for its size and static
  // cost; branch refills and division extras are in the totals only).
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

class UnicornMachine {
 public:
  UnicornMachine(const UnicornMachine&) = delete;
  UnicornMachine& operator=(const UnicornMachine&) = delete;

  void write(std::uint32_t address, const void* data, std::size_t size);
  void read(std::uint32_t address, void* data, std::size_t size);
  void fill(std::uint32_t address, std::uint32_t word, std::size_t words);
  // Reloads the writable segments from the image (initial .data, zero .bss).
  void reset_data();

  const std::vector<ElfFunction>& functions() const { return functions_; }
  // Whether call() fills RunCounts::block_runs (block counting only).
  void set_address_profile(bool on) { address_profile_ = on; }

 protected:
  // Opens unicorn with `arch` and `mode` (a uc_arch and a uc_mode), selects `cpu_model` (a
  // unicorn CPU model; none when negative) before anything is mapped, maps the board, checks that
  // every segment of `elf` lies in flash or RAM (code in flash) and loads them. Throws
  // std::runtime_error on a unicorn error or a segment off the board.
  UnicornMachine(const ElfImage& elf, int arch, int mode, int cpu_model = -1);
  ~UnicornMachine();

  // Throws std::runtime_error naming `what` unless `error` (a uc_err) is UC_ERR_OK.
  static void check(int error, const char* what);
  // Sets the range exclude() counts apart; the emulator marks its decoded blocks.
  void set_excluded(std::uint32_t begin, std::uint32_t end);
  // Clears the counts and the error of the last call for a new one with `args` (at most 4; throws
  // otherwise), written to the `args.size()` registers from `first_register` (a unicorn register).
  void start_call(const std::vector<std::uint32_t>& args, int first_register, const char* what);
  // The index into functions() of the function holding `address` (the last, "(no symbol)", when none).
  std::uint32_t function_of(std::uint32_t address) const;
  // Keeps the first error of a call and stops the emulation (from a hook).
  void fail(const std::string& message);
  // Stores `b`, the block decoded at `address`, in `blocks` under its slot of block_index_ (in
  // place of the one decoded there before), with its function, whether it starts that function and
  // whether it lies in the excluded range; returns it.
  template <typename B>
  B& keep_block(std::vector<B>& blocks, std::uint32_t address, B b) {
    b.function = function_of(address);
    b.entry = address == functions_[b.function].begin;
    b.excluded = address >= exclude_begin_ && address < exclude_end_;
    std::int32_t& index = block_index_[(address - flash_base) / 2];
    if (index < 0) {
      index = std::int32_t(blocks.size());
      blocks.push_back(std::move(b));
    } else {
      blocks[index] = std::move(b);
    }
    return blocks[index];
  }

  const ElfImage& elf_;
  uc_struct* uc_ = nullptr;
  bool address_profile_ = false;
  std::uint32_t halt_ = 0;  // bench_halt, where a call returns to
  std::uint32_t exclude_begin_ = 0, exclude_end_ = 0;
  std::vector<ElfFunction> functions_;     // the image's, then one for code outside them
  std::vector<std::int32_t> block_index_;  // by (address - flash_base) / 2: index into the emulator's blocks, or -1
  RunCounts run_;
  std::string error_;
};

}  // namespace tristream::bench_mcu
