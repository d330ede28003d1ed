// SPDX-License-Identifier: MIT
#include "riscv_emulator.h"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <stdexcept>

namespace tristream::bench_mcu::riscv {

namespace {

std::string hex(std::uint32_t v) {
  char s[16];
  std::snprintf(s, sizeof s, "0x%08x", unsigned(v));
  return s;
}

void block_hook(uc_engine*, std::uint64_t address, std::uint32_t size, void* self) {
  static_cast<RiscvEmulator*>(self)->on_block(std::uint32_t(address), size);
}
void insn_hook(uc_engine*, std::uint64_t address, std::uint32_t size, void* self) {
  static_cast<RiscvEmulator*>(self)->on_insn(std::uint32_t(address), size);
}
void divide_hook(uc_engine*, std::uint64_t address, std::uint32_t, void* self) {
  static_cast<RiscvEmulator*>(self)->on_divide(std::uint32_t(address));
}
void access_hook(uc_engine*, uc_mem_type type, std::uint64_t address, int size, std::int64_t, void* self) {
  static_cast<RiscvEmulator*>(self)->on_access(std::uint32_t(address), size, type == UC_MEM_WRITE);
}

bool by_address(const DivideSite& a, const DivideSite& b) { return a.address < b.address; }

}  // namespace

RiscvEmulator::RiscvEmulator(const ElfImage& elf, bool per_instruction)
    : UnicornMachine(elf, UC_ARCH_RISCV, UC_MODE_RISCV32), per_instruction_(per_instruction) {
  const auto gp = elf.symbols.find("__global_pointer$");
  if (gp != elf.symbols.end()) global_pointer_ = gp->second.address;
  if (per_instruction_) insn_index_.assign(flash_size / 2, -1);
  uc_hook h;
  const std::uint64_t first = flash_base, last = flash_base + flash_size - 1;
  if (per_instruction_)
    check(uc_hook_add(uc_, &h, UC_HOOK_CODE, reinterpret_cast<void*>(insn_hook), this, first, last),
          "add the instruction hook");
  else
    check(uc_hook_add(uc_, &h, UC_HOOK_BLOCK, reinterpret_cast<void*>(block_hook), this, first, last),
          "add the block hook");
  check(uc_hook_add(uc_, &h, UC_HOOK_MEM_READ | UC_HOOK_MEM_WRITE, reinterpret_cast<void*>(access_hook), this, 1, 0),
        "add the alignment hook");
  divides_ = find_divides(elf);
  std::sort(divides_.begin(), divides_.end(), by_address);
  // Per-instruction counting costs its divisions in the instruction hook: unicorn runs through
  // every code hook's range check on each instruction a hook covers.
  if (!per_instruction_)
    for (const DivideSite& d : divides_)
      check(uc_hook_add(uc_, &h, UC_HOOK_CODE, reinterpret_cast<void*>(divide_hook), this, d.address, d.address),
            "add a division hook");
}

void RiscvEmulator::exclude(std::uint32_t begin, std::uint32_t end) {
  set_excluded(begin, end);
  for (Cached& b : blocks_) b.excluded = b.decoded.address >= begin && b.decoded.address < end;
}

void RiscvEmulator::set_stack_chain(bool on) {
  if (on) throw std::runtime_error("bench-mcu: --stack-chain is available on the Cortex-M4 only");
}

const RiscvEmulator::Cached* RiscvEmulator::block_at(std::uint32_t address, std::uint32_t size) {
  const std::int32_t index = block_index_[(address - flash_base) / 2];
  if (index >= 0 && blocks_[index].decoded.size == size) return &blocks_[index];
  // A new block, or one translated again with another size: decode it (and keep the latest).
  std::vector<std::uint8_t> code(size);
  check(uc_mem_read(uc_, address, code.data(), size), "read code");
  Cached b;
  if (!decode_block(code.data(), size, address, &b.decoded)) {
    fail("the block at " + hex(address) + " (" + std::to_string(size) + " bytes) is not RV32IMC code");
    return nullptr;
  }
  for (const Insn& insn : b.decoded.insns)
    if (insn.divide && !std::binary_search(divides_.begin(), divides_.end(), DivideSite{insn.address}, by_address))
      fail("a division at " + hex(insn.address) + " outside the image's functions");
  return &keep_block(blocks_, address, std::move(b));
}

const Insn* RiscvEmulator::insn_at(std::uint32_t address, std::uint32_t* function) {
  std::int32_t& index = insn_index_[(address - flash_base) / 2];
  if (index < 0) {
    std::uint8_t code[4] = {};
    const std::uint32_t available = std::min<std::uint32_t>(4, flash_base + flash_size - address);
    check(uc_mem_read(uc_, address, code, available), "read code");
    Insn insn;
    if (!decode(code, available, address, &insn)) {
      fail("the instruction at " + hex(address) + " is not RV32IMC");
      return nullptr;
    }
    index = std::int32_t(insns_.size());
    insns_.push_back(insn);
    insn_functions_.push_back(function_of(address));
  }
  *function = insn_functions_[index];
  return &insns_[index];
}

void RiscvEmulator::add(Counts& c, std::uint32_t function, bool excluded, std::uint64_t cycles) {
  c.cycles += cycles;
  if (!excluded) run_.function_cycles[function] += cycles;
}

// The instruction after a branch or a jump is known: a branch was taken when it is not the next in
// memory (the refill, and its target's alignment), a jump pays its target's alignment.
void RiscvEmulator::resolve_pending(std::uint32_t next_address, std::uint32_t next_size) {
  if (pending_branch_ && next_address != pending_fallthrough_) {
    add(*pending_counts_, pending_function_, pending_excluded_,
        std::uint64_t(taken_branch_extra + target_extra(next_address, next_size)));
    pending_counts_->taken_branches += 1;
  } else if (pending_jump_) {
    add(*pending_counts_, pending_function_, pending_excluded_, std::uint64_t(target_extra(next_address, next_size)));
  }
  pending_branch_ = pending_jump_ = false;
}

void RiscvEmulator::on_block(std::uint32_t address, std::uint32_t size) {
  if (address == halt_) return;
  if (size == 0 || !in_flash(address)) return fail("a translation block of unknown size at " + hex(address));
  const Cached* b = block_at(address, size);
  if (!b) return;
  const Insn& first = b->decoded.insns.front();
  resolve_pending(address, first.size);
  Counts& c = b->excluded ? run_.excluded : run_.counted;
  // Entered by falling through from the block before it in memory: its first instruction's
  // hazards with that block's last, as if the two were one block (unicorn ends blocks where the
  // pipeline does not, e.g. at page boundaries).
  if (address == previous_end_) {
    Context ignored;
    const int extra = cost_after(first, previous_exit_, &ignored) - cost_after(first, Context{}, &ignored);
    add(c, b->function, b->excluded, std::uint64_t(extra));
  }
  previous_end_ = address + size;
  previous_exit_ = b->decoded.exit;
  c.instructions += b->decoded.insns.size();
  add(c, b->function, b->excluded, b->decoded.cycles);
  if (b->entry && !b->excluded) run_.function_entries[b->function] += 1;
  for (int k = 0; k < class_count; ++k) c.by_class[k] += b->decoded.by_class[k];
  if (address_profile_ && !b->excluded) run_.block_runs[(address - flash_base) / 2] += 1;
  const Insn& last = b->decoded.insns.back();
  pending_branch_ = last.branch;
  pending_jump_ = last.jump;
  pending_fallthrough_ = address + size;
  pending_counts_ = &c;
  pending_function_ = b->function;
  pending_excluded_ = b->excluded;
}

// Per-instruction counting: the same model, the context carried from one executed instruction to
// the next instead of within decoded blocks.
void RiscvEmulator::on_insn(std::uint32_t address, std::uint32_t size) {
  if (address == halt_) return;
  if (!in_flash(address)) return fail("an instruction outside flash at " + hex(address));
  std::uint32_t function = 0;
  const Insn* insn = insn_at(address, &function);
  if (!insn) return;
  if (insn->size != size) return fail("the instruction at " + hex(address) + " has another size for unicorn");
  resolve_pending(address, size);
  const bool excluded = address >= exclude_begin_ && address < exclude_end_;
  Counts& c = excluded ? run_.excluded : run_.counted;
  const Context before = address == previous_end_ ? previous_exit_ : Context{};
  c.instructions += 1;
  c.by_class[insn->klass] += 1;
  add(c, function, excluded, std::uint64_t(cost_after(*insn, before, &previous_exit_)));
  if (address == functions_[function].begin && !excluded) run_.function_entries[function] += 1;
  if (insn->divide) on_divide(address);
  previous_end_ = address + size;
  pending_branch_ = insn->branch;
  pending_jump_ = insn->jump;
  pending_fallthrough_ = address + size;
  pending_counts_ = &c;
  pending_function_ = function;
  pending_excluded_ = excluded;
}

void RiscvEmulator::on_divide(std::uint32_t address) {
  const auto it = std::lower_bound(divides_.begin(), divides_.end(), DivideSite{address}, by_address);
  if (it == divides_.end() || it->address != address) return;
  std::uint32_t divisor = 0;
  uc_reg_read(uc_, it->divisor_reg, &divisor);
  const int extra = divide_cycles(divisor, it->is_signed) - divide_static_cycles;
  const bool excluded = address >= exclude_begin_ && address < exclude_end_;
  Counts& c = excluded ? run_.excluded : run_.counted;
  add(c, function_of(address), excluded, std::uint64_t(extra));
  c.divide_cycles += std::uint64_t(extra);
}

void RiscvEmulator::on_access(std::uint32_t address, int size, bool write) {
  if (size > 0 && address % std::uint32_t(size) == 0) return;
  std::uint32_t pc = 0;
  uc_reg_read(uc_, UC_RISCV_REG_PC, &pc);
  fail(std::string("a misaligned ") + std::to_string(size) + "-byte " + (write ? "store" : "load") + " at " +
       hex(address) + " (pc " + hex(pc) + ": the instruction, or the start of its translation block)");
}

void RiscvEmulator::block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const {
  *size = *cycles = 0;
  if (!in_flash(address)) return;
  const std::int32_t index = block_index_[(address - flash_base) / 2];
  if (index < 0) return;
  *size = blocks_[index].decoded.size;
  *cycles = blocks_[index].decoded.cycles;
}

RunCounts RiscvEmulator::call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args) {
  start_call(args, UC_RISCV_REG_A0, "write a0..a3");
  pending_branch_ = pending_jump_ = false;
  previous_end_ = 0;
  previous_exit_ = Context{};
  std::uint32_t sp = stack_top, ra = halt_, gp = global_pointer_;
  check(uc_reg_write(uc_, UC_RISCV_REG_SP, &sp), "write SP");
  check(uc_reg_write(uc_, UC_RISCV_REG_RA, &ra), "write RA");
  check(uc_reg_write(uc_, UC_RISCV_REG_GP, &gp), "write GP");
  const uc_err e = uc_emu_start(uc_, function, halt_, 0, 0);
  if (!error_.empty()) throw std::runtime_error("bench-mcu: " + error_);
  std::uint32_t pc = 0;
  uc_reg_read(uc_, UC_RISCV_REG_PC, &pc);
  if (e != UC_ERR_OK) throw std::runtime_error(std::string("unicorn: ") + uc_strerror(e) + " at pc " + hex(pc));
  if (pc != halt_) throw std::runtime_error("bench-mcu: the call stopped at pc " + hex(pc));
  // The return to bench_halt (a 4-byte EBREAK on a word boundary: riscv/halt.S) resolves the last jump.
  resolve_pending(halt_, 4);
  return run_;
}

}  // namespace tristream::bench_mcu::riscv
