// SPDX-License-Identifier: MIT
#include "cycle_model_m0plus.h"

#include <algorithm>
#include <initializer_list>

namespace tristream::bench_mcu {

namespace {

bool in(unsigned id, std::initializer_list<unsigned> ids) { return std::find(ids.begin(), ids.end(), id) != ids.end(); }

// ARMv6-M: the 16-bit Thumb instructions but CBZ, CBNZ and IT (ARMv7-M's), and six 32-bit ones.
bool armv6m(const cs_insn& insn) {
  if (insn.size == 2) return !in(insn.id, {ARM_INS_CBZ, ARM_INS_CBNZ, ARM_INS_IT});
  return in(insn.id, {ARM_INS_BL, ARM_INS_MSR, ARM_INS_MRS, ARM_INS_DMB, ARM_INS_DSB, ARM_INS_ISB, ARM_INS_UDF});
}

bool writes_pc(const cs_arm& arm) {
  return arm.op_count > 0 && arm.operands[0].type == ARM_OP_REG && arm.operands[0].reg == ARM_REG_PC;
}

int registers_listed(const cs_arm& arm, int first) {
  int n = 0;
  for (int i = first; i < arm.op_count; ++i) n += arm.operands[i].type == ARM_OP_REG;
  return n;
}

bool lists_pc(const cs_arm& arm) {
  for (int i = 0; i < arm.op_count; ++i)
    if (arm.operands[i].type == ARM_OP_REG && arm.operands[i].reg == ARM_REG_PC) return true;
  return false;
}

}  // namespace

DecodedInsn cost_m0plus(const cs_insn& insn, std::string* refused) {
  const cs_arm& arm = insn.detail->arm;
  const unsigned id = insn.id;
  DecodedInsn d;
  d.address = std::uint32_t(insn.address);
  d.size = std::uint8_t(insn.size);
  if (!armv6m(insn)) *refused = std::string(insn.mnemonic) + " " + insn.op_str;
  int cycles = 1;
  if (in(id, {ARM_INS_LDR, ARM_INS_LDRB, ARM_INS_LDRH, ARM_INS_LDRSB, ARM_INS_LDRSH})) {
    d.klass = class_load;
    cycles = 2;
  } else if (in(id, {ARM_INS_STR, ARM_INS_STRB, ARM_INS_STRH})) {
    d.klass = class_store;
    cycles = 2;
  } else if (in(id, {ARM_INS_LDM, ARM_INS_STM, ARM_INS_PUSH, ARM_INS_POP})) {
    const bool base = id == ARM_INS_LDM || id == ARM_INS_STM;  // operand 0 is the base register
    const int n = registers_listed(arm, base ? 1 : 0);
    d.klass = class_multiple;
    cycles = 1 + n;
    if (id == ARM_INS_POP && lists_pc(arm)) {
      d.klass = class_branch;
      cycles = 3 + n;
    }
  } else if (id == ARM_INS_B) {
    d.klass = class_branch;
    if (arm.cc != ARM_CC_AL && arm.cc != ARM_CC_INVALID) {
      d.conditional = d.conditional_branch = true;  // 1, + m0plus_taken_extra when taken
    } else {
      cycles = 2;
    }
  } else if (id == ARM_INS_BL) {
    d.klass = class_branch;
    cycles = 3;
  } else if (in(id, {ARM_INS_BX, ARM_INS_BLX})) {
    d.klass = class_branch;
    cycles = 2;
  } else if (in(id, {ARM_INS_MSR, ARM_INS_MRS, ARM_INS_DMB, ARM_INS_DSB, ARM_INS_ISB})) {
    d.klass = class_other;
    cycles = 3;
  } else if (id == ARM_INS_MUL) {
    d.klass = class_multiply;
  } else if (writes_pc(arm)) {  // ADD PC, Rm and MOV PC, Rm
    d.klass = class_branch;
    cycles = 2;
  } else {
    d.klass = arm.op_count > 0 || id == ARM_INS_NOP ? class_alu : class_other;
  }
  d.cycles = std::uint8_t(cycles);
  return d;
}

}  // namespace tristream::bench_mcu
