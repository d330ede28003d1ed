// SPDX-License-Identifier: MIT
#include "riscv_cycle_model.h"

#include <unicorn/unicorn.h>

#include <bit>
#include <cstring>

namespace tristream::bench_mcu::riscv {

namespace {

std::uint32_t bits(std::uint32_t v, int hi, int lo) { return (v >> lo) & ((1u << (hi - lo + 1)) - 1u); }
// A compressed instruction's 3-bit register field: x8..x15.
std::uint8_t creg(std::uint32_t v, int lo) { return std::uint8_t(8 + bits(v, lo + 2, lo)); }

void set(Insn* i, InsnClass k, std::uint32_t rd, std::uint32_t rs1, std::uint32_t rs2) {
  i->klass = k;
  i->rd = std::uint8_t(rd);
  i->rs1 = std::uint8_t(rs1);
  i->rs2 = std::uint8_t(rs2);
  i->cycles = 1;
}

void as_load(Insn* i, std::uint32_t rd, std::uint32_t rs1) {
  set(i, class_load, rd, rs1, 0);
  i->load = true;
}

void as_store(Insn* i, std::uint32_t rs1, std::uint32_t rs2) { set(i, class_store, 0, rs1, rs2); }

void as_jump(Insn* i, std::uint32_t rd, std::uint32_t rs1) {
  set(i, class_branch, rd, rs1, 0);
  i->jump = true;
  i->cycles = jump_cycles;
}

void as_branch(Insn* i, std::uint32_t rs1, std::uint32_t rs2) {
  set(i, class_branch, 0, rs1, rs2);
  i->branch = true;
}

// OP (register-register), base and M.
bool decode_op(std::uint32_t w, Insn* i) {
  const std::uint32_t f3 = bits(w, 14, 12), f7 = bits(w, 31, 25);
  const std::uint32_t rd = bits(w, 11, 7), rs1 = bits(w, 19, 15), rs2 = bits(w, 24, 20);
  if (f7 == 0x01) {
    set(i, class_multiply, rd, rs1, rs2);
    if (f3 >= 1 && f3 <= 3) i->cycles = 5;  // MULH, MULHSU, MULHU
    if (f3 >= 4) {
      i->klass = class_divide;
      i->divide = true;
      i->divide_signed = f3 == 4 || f3 == 6;
      i->cycles = divide_static_cycles;
    }
    return true;
  }
  if (f7 != 0 && !(f7 == 0x20 && (f3 == 0 || f3 == 5))) return false;
  set(i, class_alu, rd, rs1, rs2);
  return true;
}

bool decode32(std::uint32_t w, Insn* i) {
  const std::uint32_t op = bits(w, 6, 0), f3 = bits(w, 14, 12);
  const std::uint32_t rd = bits(w, 11, 7), rs1 = bits(w, 19, 15), rs2 = bits(w, 24, 20);
  switch (op) {
    case 0x37:  // LUI
    case 0x17:  // AUIPC
      set(i, class_alu, rd, 0, 0);
      return true;
    case 0x6F:  // JAL
      as_jump(i, rd, 0);
      return true;
    case 0x67:  // JALR
      if (f3 != 0) return false;
      as_jump(i, rd, rs1);
      i->indirect = true;
      return true;
    case 0x63:  // BEQ, BNE, BLT, BGE, BLTU, BGEU
      if (f3 == 2 || f3 == 3) return false;
      as_branch(i, rs1, rs2);
      return true;
    case 0x03:  // LB, LH, LW, LBU, LHU
      if (f3 == 3 || f3 > 5) return false;
      as_load(i, rd, rs1);
      return true;
    case 0x23:  // SB, SH, SW
      if (f3 > 2) return false;
      as_store(i, rs1, rs2);
      return true;
    case 0x13: {  // ADDI .. ANDI, SLLI, SRLI, SRAI
      const std::uint32_t f7 = bits(w, 31, 25);
      if ((f3 == 1 && f7 != 0) || (f3 == 5 && f7 != 0 && f7 != 0x20)) return false;
      set(i, class_alu, rd, rs1, 0);
      return true;
    }
    case 0x33: return decode_op(w, i);
    case 0x0F:  // FENCE, FENCE.I
      set(i, class_other, 0, 0, 0);
      return true;
    default:  // SYSTEM (ECALL, EBREAK, CSR), A, F, D and anything else: not in the bench's code
      return false;
  }
}

bool decode_quadrant0(std::uint32_t h, Insn* i) {
  switch (bits(h, 15, 13)) {
    case 0:  // C.ADDI4SPN (all-zero immediate: the defined illegal instruction)
      if (bits(h, 12, 5) == 0) return false;
      set(i, class_alu, creg(h, 2), 2, 0);
      return true;
    case 2:  // C.LW
      as_load(i, creg(h, 2), creg(h, 7));
      return true;
    case 6:  // C.SW
      as_store(i, creg(h, 7), creg(h, 2));
      return true;
    default:  // C.FLD, C.FLW, C.FSD, C.FSW, reserved
      return false;
  }
}

bool decode_quadrant1(std::uint32_t h, Insn* i) {
  const std::uint32_t rd = bits(h, 11, 7);
  switch (bits(h, 15, 13)) {
    case 0:  // C.ADDI, C.NOP
      set(i, class_alu, rd, rd, 0);
      return true;
    case 1:  // C.JAL
      as_jump(i, 1, 0);
      return true;
    case 2:  // C.LI
      set(i, class_alu, rd, 0, 0);
      return true;
    case 3:  // C.ADDI16SP, C.LUI
      set(i, class_alu, rd, rd == 2 ? 2 : 0, 0);
      return true;
    case 4: {
      const std::uint8_t r = creg(h, 7);
      if (bits(h, 11, 10) != 3) {  // C.SRLI, C.SRAI, C.ANDI
        set(i, class_alu, r, r, 0);
        return true;
      }
      if (bits(h, 12, 12)) return false;    // C.SUBW, C.ADDW: RV64
      set(i, class_alu, r, r, creg(h, 2));  // C.SUB, C.XOR, C.OR, C.AND
      return true;
    }
    case 5:  // C.J
      as_jump(i, 0, 0);
      return true;
    default:  // C.BEQZ, C.BNEZ
      as_branch(i, creg(h, 7), 0);
      return true;
  }
}

bool decode_quadrant2(std::uint32_t h, Insn* i) {
  const std::uint32_t r = bits(h, 11, 7), rs2 = bits(h, 6, 2);
  switch (bits(h, 15, 13)) {
    case 0:  // C.SLLI
      set(i, class_alu, r, r, 0);
      return true;
    case 2:  // C.LWSP
      if (r == 0) return false;
      as_load(i, r, 2);
      return true;
    case 4:
      if (!bits(h, 12, 12)) {
        if (rs2 == 0) {  // C.JR
          if (r == 0) return false;
          as_jump(i, 0, r);
          i->indirect = true;
        } else {  // C.MV
          set(i, class_alu, r, 0, rs2);
        }
        return true;
      }
      if (r == 0 && rs2 == 0) return false;  // C.EBREAK
      if (rs2 == 0) {                        // C.JALR
        as_jump(i, 1, r);
        i->indirect = true;
      } else {  // C.ADD
        set(i, class_alu, r, r, rs2);
      }
      return true;
    case 6:  // C.SWSP
      as_store(i, 2, rs2);
      return true;
    default:  // C.FLDSP, C.FLWSP, C.FSDSP, C.FSWSP
      return false;
  }
}

}  // namespace

bool decode(const std::uint8_t* code, std::uint32_t available, std::uint32_t address, Insn* out) {
  if (available < 2) return false;
  Insn i;
  i.address = address;
  const std::uint32_t h = std::uint32_t(code[0]) | std::uint32_t(code[1]) << 8;
  bool ok = false;
  if ((h & 3u) == 3u) {
    if ((h & 0x1Cu) == 0x1Cu || available < 4) return false;  // 48-bit and longer encodings
    std::uint32_t w = 0;
    std::memcpy(&w, code, 4);
    i.size = 4;
    ok = decode32(w, &i);
  } else {
    i.size = 2;
    ok = (h & 3u) == 0 ? decode_quadrant0(h, &i) : (h & 3u) == 1 ? decode_quadrant1(h, &i) : decode_quadrant2(h, &i);
  }
  if (!ok) return false;
  *out = i;
  return true;
}

int cost_after(const Insn& insn, const Context& before, Context* after) {
  int cycles = insn.cycles;
  const auto reads = [&](std::uint8_t r) { return r != 0 && (insn.rs1 == r || insn.rs2 == r); };
  if (reads(before.loaded)) cycles += 1;                                                // load data hazard
  if (insn.indirect && before.written != 0 && insn.rs1 == before.written) cycles += 1;  // JALR hazard
  if (insn.jump) {
    *after = Context{};
  } else {
    after->loaded = insn.load ? insn.rd : 0;
    after->written = insn.rd;
  }
  return cycles;
}

int target_extra(std::uint32_t target, std::uint32_t target_size) { return target_size == 4 && (target & 2u) ? 1 : 0; }

int divide_cycles(std::uint32_t divisor, bool is_signed) {
  std::uint32_t magnitude = divisor;
  if (is_signed && std::int32_t(divisor) < 0) magnitude = 0u - divisor;
  return 3 + std::countl_zero(magnitude);
}

bool decode_block(const std::uint8_t* code, std::uint32_t size, std::uint32_t address, Block* out) {
  Block b;
  b.address = address;
  b.size = size;
  Context c;
  for (std::uint32_t at = 0; at < size;) {
    Insn i;
    if (!decode(code + at, size - at, address + at, &i)) return false;
    b.cycles += std::uint32_t(cost_after(i, c, &c));
    b.by_class[i.klass] += 1;
    b.insns.push_back(i);
    at += i.size;
  }
  b.exit = c;
  *out = std::move(b);
  return true;
}

std::vector<DivideSite> find_divides(const ElfImage& elf) {
  std::vector<DivideSite> sites;
  for (const ElfFunction& f : elf.functions) {
    if (f.end <= f.begin) continue;
    std::vector<std::uint8_t> code;
    try {
      code = elf.read(f.begin, f.end - f.begin);
    } catch (const std::exception&) {
      continue;  // not in a loaded segment
    }
    for (std::uint32_t at = 0; at + 2 <= code.size();) {
      Insn i;
      if (!decode(code.data() + at, std::uint32_t(code.size()) - at, f.begin + at, &i)) {
        at += 2;
        continue;
      }
      if (i.divide) sites.push_back({i.address, i.divide_signed, UC_RISCV_REG_X0 + i.rs2});
      at += i.size;
    }
  }
  return sites;
}

}  // namespace tristream::bench_mcu::riscv
