// SPDX-License-Identifier: MIT
#include "m4_emulator.h"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace tristream::bench_mcu {

namespace {

void block_hook(uc_engine*, std::uint64_t address, std::uint32_t size, void* self) {
  static_cast<M4Emulator*>(self)->on_block(std::uint32_t(address), size);
}
void insn_hook(uc_engine*, std::uint64_t address, std::uint32_t size, void* self) {
  static_cast<M4Emulator*>(self)->on_insn(std::uint32_t(address), size);
}
void access_hook(uc_engine*, uc_mem_type, std::uint64_t address, int size, std::int64_t, void* self) {
  static_cast<M4Emulator*>(self)->on_access(std::uint32_t(address), size);
}
void divide_hook(uc_engine*, std::uint64_t address, std::uint32_t, void* self) {
  static_cast<M4Emulator*>(self)->on_divide(std::uint32_t(address));
}

}  // namespace

M4Emulator::M4Emulator(const ElfImage& elf, bool per_instruction, Core core)
    : UnicornMachine(elf, UC_ARCH_ARM, UC_MODE_THUMB | UC_MODE_MCLASS,
                     core == Core::m0plus ? UC_CPU_ARM_CORTEX_M0 : UC_CPU_ARM_CORTEX_M4),
      model_(core),
      taken_extra_(model_.taken_extra()),
      per_instruction_(per_instruction) {
  uc_hook h;
  if (per_instruction_)
    check(uc_hook_add(uc_, &h, UC_HOOK_CODE, reinterpret_cast<void*>(insn_hook), this, flash_base,
                      flash_base + flash_size - 1),
          "add the instruction hook");
  check(uc_hook_add(uc_, &h, UC_HOOK_BLOCK, reinterpret_cast<void*>(block_hook), this, flash_base,
                    flash_base + flash_size - 1),
        "add the block hook");
  if (core == Core::m0plus)
    check(uc_hook_add(uc_, &h, UC_HOOK_MEM_READ | UC_HOOK_MEM_WRITE, reinterpret_cast<void*>(access_hook), this, 1, 0),
          "add the alignment hook");
  divides_ = model_.find_divides(elf);
  // Per-instruction counting costs its divisions in the instruction hook: unicorn runs through
  // every code hook's range check on each instruction a hook covers.
  if (!per_instruction_)
    for (const DivideSite& d : divides_)
      check(uc_hook_add(uc_, &h, UC_HOOK_CODE, reinterpret_cast<void*>(divide_hook), this, d.address, d.address),
            "add a division hook");
  std::sort(divides_.begin(), divides_.end(), [](const DivideSite& a, const DivideSite& b) {
    return a.address < b.address;
  });
}

void M4Emulator::exclude(std::uint32_t begin, std::uint32_t end) {
  set_excluded(begin, end);
  for (Block& b : blocks_) b.excluded = b.decoded.address >= begin && b.decoded.address < end;
}

const M4Emulator::Block& M4Emulator::block_at(std::uint32_t address, std::uint32_t size) {
  const std::int32_t index = block_index_[(address - flash_base) / 2];
  if (index >= 0 && blocks_[index].decoded.size == size) return blocks_[index];
  // A new block, or one translated again with another size: decode it (and keep the latest).
  std::vector<std::uint8_t> code(size);
  check(uc_mem_read(uc_, address, code.data(), size), "read code");
  // ITSTATE (xPSR bits 15:10 and 26:25): a block may begin inside an IT block. IT[3:0] shifts left
  // once per instruction and the block ends when it is 0, so 4 - ctz(IT[3:0]) instructions remain.
  std::uint32_t xpsr = 0;
  check(uc_reg_read(uc_, UC_ARM_REG_XPSR, &xpsr), "read xPSR");
  const std::uint32_t it = ((xpsr >> 8) & 0xFCu) | ((xpsr >> 25) & 3u);
  const int it_left = (it & 0xFu) ? 4 - __builtin_ctz(it & 0xFu) : 0;
  Block b;
  if (!model_.decode_block(code.data(), size, address, &b.decoded, it_left)) {
    static const Block none;
    fail("cannot decode the block at 0x" + std::to_string(address) + " (" + std::to_string(size) + " bytes)");
    return none;
  }
  if (!b.decoded.refused.empty()) fail("not an ARMv6-M instruction: " + b.decoded.refused);
  for (const DecodedInsn& insn : b.decoded.insns)
    if (insn.klass == class_divide &&
        !std::binary_search(divides_.begin(), divides_.end(), DivideSite{insn.address},
                            [](const DivideSite& x, const DivideSite& y) { return x.address < y.address; }))
      fail("a division at " + std::to_string(insn.address) + " outside the image's code ranges");
  return keep_block(blocks_, address, std::move(b));
}

// A conditional branch ran last: it was taken when execution continues elsewhere than after it.
void M4Emulator::resolve_pending(std::uint32_t next_address) {
  if (!pending_) return;
  pending_ = false;
  if (next_address == pending_fallthrough_) return;
  pending_counts_->cycles += std::uint64_t(taken_extra_);
  pending_counts_->taken_branches += 1;
  if (pending_counts_ == &run_.counted) run_.function_cycles[pending_function_] += std::uint64_t(taken_extra_);
}

// A block entered by falling through from the block that ran before it (no branch between): its
// first instruction costed after that block's last, as if the two were one block. Unicorn ends
// translation blocks where the M4's pipeline does not (page boundaries, after a conditional
// branch not taken), and without this the same code cost more or less as it moved against them
// (-0.1 % to +0.4 % of a function's cycles). The instruction that ends at `address` is the same
// whichever block ran it, so the difference is kept with the block.
int M4Emulator::entry_cycles(std::uint32_t address) {
  if (address != previous_end_) return 0;
  Block& b = blocks_[block_index_[(address - flash_base) / 2]];
  if (!b.fallthrough_known) {
    const DecodedInsn& first = b.decoded.insns.front();
    std::vector<std::uint8_t> code(first.size);
    check(uc_mem_read(uc_, address, code.data(), code.size()), "read code");
    const int after = model_.first_cycles_after(code.data(), first.size, address, previous_exit_, b.decoded.it_left);
    if (after < 0) fail("cannot decode the instruction at " + std::to_string(address));
    b.fallthrough_cycles = after - int(first.cycles);
    b.fallthrough_known = true;
  }
  return b.fallthrough_cycles;
}

// Counts a block's entry (entry_cycles) and remembers where it ends for the next one.
void M4Emulator::count_entry(const Block& b, std::uint32_t address) {
  const int extra = entry_cycles(address);
  if (extra) {
    Counts& c = b.excluded ? run_.excluded : run_.counted;
    c.cycles += std::uint64_t(std::int64_t(extra));
    if (!b.excluded) run_.function_cycles[b.function] += std::uint64_t(std::int64_t(extra));
  }
  previous_end_ = address + b.decoded.size;
  previous_exit_ = b.decoded.exit;
}

void M4Emulator::block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const {
  *size = *cycles = 0;
  if (address < flash_base || address - flash_base >= flash_size) return;
  const std::int32_t index = block_index_[(address - flash_base) / 2];
  if (index < 0) return;
  *size = blocks_[index].decoded.size;
  *cycles = blocks_[index].decoded.cycles;
}

void M4Emulator::on_block(std::uint32_t address, std::uint32_t size) {
  if (address == halt_) return;
  if (size == 0 || address < flash_base || address - flash_base >= flash_size) {
    fail("a translation block of unknown size at " + std::to_string(address));
    return;
  }
  if (stack_chain_) watch_stack(address);
  block_address_ = address;
  const Block& b = block_at(address, size);
  if (b.entry && !b.excluded) run_.function_entries[b.function] += 1;
  if (per_instruction_) {
    finish_block();
    current_ = &b;
    current_insn_ = 0;
    count_entry(b, address);
    return;
  }
  resolve_pending(address);
  count_entry(b, address);
  Counts& c = b.excluded ? run_.excluded : run_.counted;
  c.instructions += b.decoded.insns.size();
  c.cycles += b.decoded.cycles;
  for (int k = 0; k < class_count; ++k) c.by_class[k] += b.decoded.by_class[k];
  if (!b.excluded) run_.function_cycles[b.function] += b.decoded.cycles;
  if (address_profile_ && !b.excluded) run_.block_runs[(address - flash_base) / 2] += 1;
  if (b.decoded.ends_with_conditional_branch()) {
    pending_ = true;
    pending_fallthrough_ = address + size;
    pending_counts_ = &c;
    pending_function_ = b.function;
  }
}

// Per-instruction mode: the instructions of the current block up to `address` that did not
// reach the instruction hook, which unicorn skips for an IT block's instructions whose condition
// fails. Block counting counts them as executed (the M4 spends a cycle on each), so they are
// counted here too; any other instruction left out is an error.
void M4Emulator::skip_to(std::uint32_t address) {
  while (current_ && current_insn_ < current_->decoded.insns.size() &&
         current_->decoded.insns[current_insn_].address < address) {
    const DecodedInsn& insn = current_->decoded.insns[current_insn_];
    if (!insn.conditional) {
      fail("the instruction at " + std::to_string(insn.address) + " of its translation block did not run");
      return;
    }
    count_insn(insn);
  }
}

void M4Emulator::finish_block() { skip_to(0xFFFFFFFFu); }

void M4Emulator::on_insn(std::uint32_t address, std::uint32_t size) {
  if (address == halt_) return;
  skip_to(address);
  if (!current_ || current_insn_ >= current_->decoded.insns.size() ||
      current_->decoded.insns[current_insn_].address != address ||
      current_->decoded.insns[current_insn_].size != size) {
    fail("instruction at " + std::to_string(address) + " is not the next one of its translation block");
    return;
  }
  const DecodedInsn& insn = current_->decoded.insns[current_insn_];
  count_insn(insn);
  if (insn.klass == class_divide) on_divide(address);  // before it runs, as a division hook would
}

void M4Emulator::count_insn(const DecodedInsn& insn) {
  ++current_insn_;
  const std::uint32_t address = insn.address, size = insn.size;
  resolve_pending(address);
  Counts& c = current_->excluded ? run_.excluded : run_.counted;
  c.instructions += 1;
  c.cycles += insn.cycles;
  c.by_class[insn.klass] += 1;
  if (!current_->excluded) run_.function_cycles[current_->function] += insn.cycles;
  if (insn.conditional_branch) {
    pending_ = true;
    pending_fallthrough_ = address + size;
    pending_counts_ = &c;
    pending_function_ = current_->function;
  }
}

void M4Emulator::on_divide(std::uint32_t address) {
  const auto it = std::lower_bound(divides_.begin(), divides_.end(), address,
                                   [](const DivideSite& d, std::uint32_t a) { return d.address < a; });
  if (it == divides_.end() || it->address != address) return;
  std::uint32_t n = 0, d = 0;
  uc_reg_read(uc_, it->dividend_reg, &n);
  uc_reg_read(uc_, it->divisor_reg, &d);
  const int extra = divide_cycles(n, d, it->is_signed) - 2;
  const bool excluded = address >= exclude_begin_ && address < exclude_end_;
  Counts& c = excluded ? run_.excluded : run_.counted;
  c.cycles += extra;
  c.divide_cycles += extra;
  if (!excluded) run_.function_cycles[function_of(address)] += extra;
}

// A load or store of the Cortex-M0+ (every access of the program; the harness's own reads and
// writes do not reach the hook): ARMv6-M faults on a halfword or word access not aligned to its
// size, which unicorn would perform. Unicorn's PC is not exact inside a block: the block is named.
void M4Emulator::on_access(std::uint32_t address, int size) {
  if (size > 1 && address % std::uint32_t(size) != 0) {
    char what[112];
    std::snprintf(what, sizeof what, "unaligned %d-byte access to 0x%08x in the block at 0x%08x (", size,
                  unsigned(address), unsigned(block_address_));
    fail(what + functions_[function_of(block_address_)].name + ")");
  }
}

// Whether the halfwords before return_address (Thumb bit clear) are a BL, or a BLX of a register.
bool M4Emulator::follows_call(std::uint32_t return_address) {
  if (return_address < flash_base + 4 || return_address - flash_base >= flash_size) return false;
  std::uint16_t h[2];
  if (uc_mem_read(uc_, return_address - 4, h, sizeof h) != UC_ERR_OK) return false;
  const bool bl = (h[0] & 0xF800u) == 0xF000u && (h[1] & 0xD000u) == 0xD000u;
  const bool blx = (h[1] & 0xFF87u) == 0x4780u;
  return bl || blx;
}

// A block starting below the lowest SP so far: the chain of calls then live, from the words
// between SP and the top of the stack.
void M4Emulator::watch_stack(std::uint32_t address) {
  std::uint32_t sp = 0;
  uc_reg_read(uc_, UC_ARM_REG_SP, &sp);
  if (sp >= lowest_sp_ || sp >= stack_top_) return;
  lowest_sp_ = sp;
  std::vector<std::uint32_t> words((stack_top_ - sp) / 4);
  if (uc_mem_read(uc_, sp, words.data(), words.size() * 4) != UC_ERR_OK) return;
  auto& chain = run_.stack_chain;
  chain.clear();
  chain.push_back({stack_top_ - sp, function_of(address)});
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::uint32_t w = words[i];
    if ((w & 1u) && follows_call(w & ~1u))
      chain.push_back({stack_top_ - (sp + 4 * std::uint32_t(i)), function_of(w & ~1u)});
  }
}

RunCounts M4Emulator::call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args) {
  start_call(args, UC_ARM_REG_R0, "write r0..r3");
  pending_ = false;
  previous_end_ = 0;
  previous_exit_ = InsnContext{};
  current_ = nullptr;
  current_insn_ = 0;
  std::uint32_t sp = stack_top, lr = halt_ | 1u;
  stack_top_ = lowest_sp_ = stack_top;
  check(uc_reg_write(uc_, UC_ARM_REG_SP, &sp), "write SP");
  check(uc_reg_write(uc_, UC_ARM_REG_LR, &lr), "write LR");
  const uc_err e = uc_emu_start(uc_, function | 1u, halt_, 0, 0);
  if (!error_.empty()) throw std::runtime_error("bench-mcu: " + error_);
  if (e != UC_ERR_OK) {
    std::uint32_t pc = 0;
    uc_reg_read(uc_, UC_ARM_REG_PC, &pc);
    throw std::runtime_error(std::string("unicorn: ") + uc_strerror(e) + " at pc " + std::to_string(pc));
  }
  std::uint32_t pc = 0;
  uc_reg_read(uc_, UC_ARM_REG_PC, &pc);
  if ((pc & ~1u) != halt_) throw std::runtime_error("bench-mcu: the call stopped at pc " + std::to_string(pc));
  if (per_instruction_) finish_block();
  // The return to bench_halt decides a conditional branch left pending (a conditional return).
  resolve_pending(halt_);
  if (!error_.empty()) throw std::runtime_error("bench-mcu: " + error_);
  return run_;
}

}  // namespace tristream::bench_mcu
