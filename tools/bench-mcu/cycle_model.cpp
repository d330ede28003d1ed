// SPDX-License-Identifier: MIT
#include "cycle_model.h"

#include <capstone/capstone.h>
#include <unicorn/unicorn.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "common/errors.h"
#include "cycle_model_m0plus.h"

namespace tristream::bench_mcu {

namespace {

csh handle_of(std::size_t h) { return csh(h); }

bool in(unsigned id, std::initializer_list<unsigned> ids) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

bool is_single_load(unsigned id) {
  return in(id, {ARM_INS_LDR, ARM_INS_LDRB, ARM_INS_LDRH, ARM_INS_LDRSB, ARM_INS_LDRSH, ARM_INS_LDRT, ARM_INS_LDRBT,
                 ARM_INS_LDRHT, ARM_INS_LDRSBT, ARM_INS_LDRSHT, ARM_INS_LDREX, ARM_INS_LDREXB, ARM_INS_LDREXH});
}
bool is_single_store(unsigned id) {
  return in(id, {ARM_INS_STR, ARM_INS_STRB, ARM_INS_STRH, ARM_INS_STRT, ARM_INS_STRBT, ARM_INS_STRHT, ARM_INS_STREX,
                 ARM_INS_STREXB, ARM_INS_STREXH});
}
bool is_double(unsigned id) { return in(id, {ARM_INS_LDRD, ARM_INS_STRD, ARM_INS_LDREXD, ARM_INS_STREXD}); }
bool is_multiple(unsigned id) {
  return in(id, {ARM_INS_LDM, ARM_INS_LDMDB, ARM_INS_LDMIB, ARM_INS_LDMDA, ARM_INS_STM, ARM_INS_STMDB, ARM_INS_STMIB,
                 ARM_INS_STMDA, ARM_INS_PUSH, ARM_INS_POP});
}
bool is_multiply(std::string_view name) {
  for (std::string_view p : {"mul", "mla", "mls", "umull", "umlal", "umaal", "smul", "smla", "smls", "smmul", "smmla",
                             "smmls", "smua", "smus"})
    if (name.substr(0, p.size()) == p) return true;
  return false;
}

int unicorn_reg(unsigned cs_reg) {
  if (cs_reg >= ARM_REG_R0 && cs_reg <= ARM_REG_R12) return UC_ARM_REG_R0 + int(cs_reg - ARM_REG_R0);
  if (cs_reg == ARM_REG_SP) return UC_ARM_REG_SP;
  if (cs_reg == ARM_REG_LR) return UC_ARM_REG_LR;
  if (cs_reg == ARM_REG_PC) return UC_ARM_REG_PC;
  return -1;
}

const cs_arm_op* memory_operand(const cs_arm& arm) {
  for (int i = 0; i < arm.op_count; ++i)
    if (arm.operands[i].type == ARM_OP_MEM) return &arm.operands[i];
  return nullptr;
}

using Context = InsnContext;
static_assert(ARM_REG_INVALID == 0, "InsnContext's default: no register");

bool uses(const cs_arm_op* mem, unsigned reg) {
  return mem && reg != ARM_REG_INVALID && (mem->mem.base == reg || mem->mem.index == reg);
}

// Cost of one instruction after `prev`; fills `next` for the instruction after it. in_it: the
// instruction is in an IT block (capstone 4 does not give every such instruction its condition,
// e.g. an addle.w of a negative immediate, so the decoder counts the IT block's instructions).
DecodedInsn cost(csh h, const cs_insn& insn, const Context& prev, Context* next, bool in_it) {
  const cs_arm& arm = insn.detail->arm;
  const unsigned id = insn.id;
  DecodedInsn d;
  d.address = std::uint32_t(insn.address);
  d.size = std::uint8_t(insn.size);
  cs_regs read_regs, write_regs;
  std::uint8_t nread = 0, nwrite = 0;
  if (cs_regs_access(h, &insn, read_regs, &nread, write_regs, &nwrite) != CS_ERR_OK) nread = nwrite = 0;
  bool writes_pc = false;
  for (int i = 0; i < nwrite; ++i) writes_pc |= write_regs[i] == ARM_REG_PC;
  const bool conditional =
      in_it || (arm.cc != ARM_CC_AL && arm.cc != ARM_CC_INVALID) || id == ARM_INS_CBZ || id == ARM_INS_CBNZ;
  d.conditional = conditional;
  const cs_arm_op* mem = memory_operand(arm);
  bool agu_stall = false;
  for (int i = 0; i < prev.written_count; ++i) agu_stall |= uses(mem, prev.written[i]);
  const bool after_pipelinable_load = prev.load_pipelinable && !uses(mem, prev.pipelined_load_dest);
  int cycles = 1;
  int refill = 0;  // P, paid when the instruction (if conditional: when it is taken) writes PC
  *next = Context{};
  next->valid = true;
  next->sixteen_bit = insn.size == 2;
  if (is_single_load(id)) {
    d.klass = class_load;
    if (writes_pc) {
      d.klass = class_branch;
      cycles = 2;
      refill = pipeline_refill;
    } else {
      cycles = after_pipelinable_load ? 1 : 2;
      if (!arm.writeback) {
        next->load_pipelinable = true;
        next->pipelined_load_dest = arm.operands[0].reg;
      }
    }
    cycles += agu_stall;
  } else if (is_single_store(id)) {
    d.klass = class_store;
    const bool register_offset = mem && mem->mem.index != ARM_REG_INVALID;
    cycles = (register_offset && !after_pipelinable_load ? 2 : 1) + agu_stall;
  } else if (is_double(id)) {
    d.klass = class_multiple;
    cycles = 3 + agu_stall;
  } else if (is_multiple(id)) {
    d.klass = class_multiple;
    int n = 0;
    const int first = (id == ARM_INS_PUSH || id == ARM_INS_POP) ? 0 : 1;  // LDM/STM: operand 0 is the base
    for (int i = first; i < arm.op_count; ++i) n += arm.operands[i].type == ARM_OP_REG;
    cycles = 1 + n;
    if (writes_pc) {
      d.klass = class_branch;
      refill = pipeline_refill;
    }
  } else if (in(id, {ARM_INS_B, ARM_INS_BL, ARM_INS_BX, ARM_INS_BLX, ARM_INS_CBZ, ARM_INS_CBNZ})) {
    d.klass = class_branch;
    refill = pipeline_refill;
  } else if (in(id, {ARM_INS_TBB, ARM_INS_TBH})) {
    d.klass = class_branch;
    cycles = 2;
    refill = pipeline_refill;
  } else if (in(id, {ARM_INS_SDIV, ARM_INS_UDIV})) {
    d.klass = class_divide;
    cycles = 2;  // the harness adds the operand-dependent rest (divide_cycles)
  } else if (id == ARM_INS_IT) {
    d.klass = class_alu;
    cycles = prev.valid && prev.sixteen_bit ? 0 : 1;  // folded onto a preceding 16-bit instruction
  } else {
    const std::string_view name = cs_insn_name(h, id) ? cs_insn_name(h, id) : "";
    const bool known_alu = arm.op_count > 0 || in(id, {ARM_INS_NOP});
    d.klass = is_multiply(name) ? class_multiply : (name.substr(0, 1) == "v" || !known_alu) ? class_other : class_alu;
    if (writes_pc) {
      d.klass = class_branch;
      refill = pipeline_refill;
    }
    for (int i = 0; i < nwrite && next->written_count < 4; ++i)
      if (write_regs[i] != ARM_REG_PC && write_regs[i] != ARM_REG_CPSR)
        next->written[next->written_count++] = write_regs[i];
  }
  if (refill && conditional) {
    d.conditional_branch = true;  // P only when taken (decided while running)
  } else {
    cycles += refill;
  }
  d.cycles = std::uint8_t(cycles);
  return d;
}

}  // namespace

const char* class_name(int c) {
  static const char* names[class_count] = {"alu", "multiply", "divide", "load", "store", "multiple", "branch", "other"};
  return c >= 0 && c < class_count ? names[c] : "?";
}

Core parse_core(const std::string& name) {
  if (name == "m4") return Core::m4;
  if (name == "m0plus") return Core::m0plus;
  throw UsageError("unknown core '" + name + "' (expected m4 or m0plus)");
}

const char* core_title(Core core) { return core == Core::m0plus ? "Cortex-M0+" : "Cortex-M4"; }

int CycleModel::taken_extra() const { return core_ == Core::m0plus ? m0plus_taken_extra : pipeline_refill; }

CycleModel::CycleModel(Core core) : core_(core) {
  csh h = 0;
  if (cs_open(CS_ARCH_ARM, cs_mode(CS_MODE_THUMB | CS_MODE_MCLASS), &h) != CS_ERR_OK)
    throw std::runtime_error("capstone: cannot open a Thumb (M-profile) disassembler");
  cs_option(h, CS_OPT_DETAIL, CS_OPT_ON);
  handle_ = std::size_t(h);
}

CycleModel::~CycleModel() {
  csh h = handle_of(handle_);
  cs_close(&h);
}

bool CycleModel::decode_block(const std::uint8_t* code, std::uint32_t size, std::uint32_t address,
                              DecodedBlock* out, int it_left) const {
  csh h = handle_of(handle_);
  cs_insn* insns = nullptr;
  const std::size_t n = cs_disasm(h, code, size, address, 0, &insns);
  const int it_left_at_start = it_left;
  *out = DecodedBlock{};
  out->address = address;
  out->size = size;
  std::uint32_t covered = 0;
  Context ctx;
  for (std::size_t i = 0; i < n; ++i) {
    Context next;
    std::string refused;
    const DecodedInsn d =
        core_ == Core::m0plus ? cost_m0plus(insns[i], &refused) : cost(h, insns[i], ctx, &next, it_left > 0);
    if (!refused.empty() && out->refused.empty()) {
      char at[16];
      std::snprintf(at, sizeof at, "0x%08x ", unsigned(insns[i].address));
      out->refused = at + refused;
    }
    if (it_left > 0) --it_left;
    if (insns[i].id == ARM_INS_IT) it_left = int(std::strlen(insns[i].mnemonic)) - 1;  // it, itt, ite, ...
    ctx = next;
    out->cycles += d.cycles;
    out->by_class[d.klass] += 1;
    out->insns.push_back(d);
    covered += insns[i].size;
  }
  out->exit = ctx;
  out->it_left = it_left_at_start;
  if (n) cs_free(insns, n);
  return n > 0 && covered == size;
}

int CycleModel::first_cycles_after(const std::uint8_t* code, std::uint32_t size, std::uint32_t address,
                                   const InsnContext& prev, int it_left) const {
  csh h = handle_of(handle_);
  cs_insn* insn = nullptr;
  if (cs_disasm(h, code, size, address, 1, &insn) != 1) return -1;
  Context next;
  std::string refused;
  const int cycles =
      core_ == Core::m0plus ? cost_m0plus(*insn, &refused).cycles : cost(h, *insn, prev, &next, it_left > 0).cycles;
  cs_free(insn, 1);
  return cycles;
}

std::vector<DivideSite> CycleModel::find_divides(const ElfImage& elf) const {
  csh h = handle_of(handle_);
  std::vector<DivideSite> sites;
  for (const CodeRange& r : elf.thumb_code) {
    const std::vector<std::uint8_t> code = elf.read(r.begin, r.end - r.begin);
    std::uint32_t at = 0;
    while (at + 2 <= code.size()) {
      cs_insn* insn = nullptr;
      if (cs_disasm(h, code.data() + at, code.size() - at, r.begin + at, 1, &insn) != 1) {
        at += 2;  // not an instruction (padding): the next halfword
        continue;
      }
      if (insn->id == ARM_INS_SDIV || insn->id == ARM_INS_UDIV) {
        const cs_arm& arm = insn->detail->arm;
        if (arm.op_count != 3) throw std::runtime_error("capstone: unexpected division operands");
        sites.push_back({std::uint32_t(insn->address), insn->id == ARM_INS_SDIV,
                         unicorn_reg(arm.operands[1].reg), unicorn_reg(arm.operands[2].reg)});
      }
      at += insn->size;
      cs_free(insn, 1);
    }
  }
  return sites;
}

int divide_cycles(std::uint32_t dividend, std::uint32_t divisor, bool is_signed) {
  if (is_signed) {
    dividend = std::int32_t(dividend) < 0 ? 0u - dividend : dividend;
    divisor = std::int32_t(divisor) < 0 ? 0u - divisor : divisor;
  }
  if (divisor == 0 || dividend < divisor) return 2;
  const int q = std::countl_zero(divisor) - std::countl_zero(dividend) + 1;  // 1..32
  return 2 + (10 * q + 31) / 32;
}

}  // namespace tristream::bench_mcu
