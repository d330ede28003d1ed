/* SPDX-License-Identifier: MIT */
# Calibration loops for the bench-mcu RISC-V cycle model: hand-written rv32imc with the
# instruction and cycle counts worked out by hand from docs/MCU_BENCH.md's table, next to each
# instruction. `bench_mcu calibrate` runs every case of calibration_cases (name, function, a0,
# instructions, cycles) counting per block and per instruction; both must equal the table. Each
# function returns with a jump to a word-aligned 32-bit instruction (2 cycles), counted. The
# encodings are chosen per instruction (.option rvc / norvc; no linker relaxation), and each
# function starts on a word boundary (.balign with RVC on: without it no 2-byte padding). Each is
# typed a function: the harness finds the divisions in the image's functions.
    .option norelax
    .option norvc
    .text

# N iterations of three ALU instructions and a loop branch: 4N + 1 instructions,
# 3N + 3(N - 1) (taken) + 1 (not taken) + 2 cycles; N = 100: 401, 600.
    .option rvc
    .balign 4
    .option norvc
    .type cal_alu_loop, @function
cal_alu_loop:
1:  addi a1, a1, 1          # 1
    xor a2, a2, a1          # 1
    addi a0, a0, -1         # 1
    bnez a0, 1b             # 3 taken, 1 not
    ret                     # 2

# Loads and stores (1 each) and the load-use hazard (+1 when the next instruction reads the
# loaded register: address, store data or operand), 32-bit and compressed. a0 = 0.
# 21 instructions, 27 cycles.
    .option rvc
    .balign 4
    .option norvc
    .type cal_loads, @function
cal_loads:
    addi sp, sp, -16        # 1
    sw a0, 0(sp)            # 1
    sw sp, 4(sp)            # 1
    lw a1, 0(sp)            # 1
    addi a2, a2, 1          # 1  does not read a1
    lw a3, 4(sp)            # 1
    lw a4, 0(a3)            # 2  its address is the load's result
    lw a5, 4(sp)            # 1
    sw a5, 8(sp)            # 2  its data is the load's result
    lbu a1, 8(sp)           # 1
    lhu a2, 10(sp)          # 1
    add a2, a2, a1          # 2  reads a2, just loaded
    sh a2, 12(sp)           # 1
    sb a2, 14(sp)           # 1
    .option rvc
    c.lwsp a1, 0(sp)        # 1
    c.add a1, a2            # 2  reads a1 (its destination), just loaded
    c.mv a3, a1             # 1
    c.lwsp a4, 4(sp)        # 1
    c.mv a5, a4             # 2
    .option norvc
    addi sp, sp, 16         # 1
    ret                     # 2

# JAL (2), JALR (2; +1 when its register was written by the instruction before, +1 more when that
# was a load): 12 instructions, 19 cycles, and three calls of the leaf (2 instructions, 3 cycles):
# 18 instructions, 28 cycles.
    .option rvc
    .balign 4
    .option norvc
    .type cal_calls, @function
cal_calls:
    addi sp, sp, -16        # 1
    sw ra, 12(sp)           # 1
    jal ra, cal_leaf        # 2
    lui a5, %hi(cal_leaf)   # 1
    addi a5, a5, %lo(cal_leaf)  # 1
    jalr ra, 0(a5)          # 3  a5 just written
    sw a5, 0(sp)            # 1
    lw a4, 0(sp)            # 1
    jalr ra, 0(a4)          # 4  a4 just loaded
    lw ra, 12(sp)           # 1
    addi sp, sp, 16         # 1
    ret                     # 2
    .option rvc
    .balign 4
    .option norvc
    .type cal_leaf, @function
cal_leaf:
    addi a1, a1, 1          # 1
    ret                     # 2

# MUL (1), MULH, MULHU, MULHSU (5), DIV, DIVU, REM, REMU (3 + the divisor's leading zeros, of its
# magnitude when signed; 35 for 0): 17 instructions, 156 cycles.
    .option rvc
    .balign 4
    .option norvc
    .type cal_muldiv, @function
cal_muldiv:
    li a1, 7                # 1
    li a2, 5                # 1
    mul a3, a1, a2          # 1
    mulh a3, a1, a2         # 5
    mulhu a3, a1, a2        # 5
    mulhsu a3, a1, a2       # 5
    li a2, 1                # 1
    divu a3, a1, a2         # 34  1 has 31 leading zeros
    li a2, 0                # 1
    div a3, a1, a2          # 35  divisor 0
    li a2, -1               # 1
    rem a3, a1, a2          # 34  |-1| = 1
    lui a2, 0x80000         # 1
    div a3, a1, a2          # 3   |-2^31| = 2^31, no leading zero
    li a2, 1000             # 1
    remu a3, a1, a2         # 25  1000 has 22 leading zeros
    ret                     # 2

# Branches (1 not taken, 3 taken) and jumps (2), +1 when the target is a 32-bit instruction not on
# a word boundary (a compressed one on a halfword costs nothing more). a0 = 0; offsets from the
# function's start in the comments. 12 instructions, 21 cycles.
    .option rvc
    .balign 4
    .option norvc
    .type cal_branches, @function
cal_branches:
    .option rvc
    c.li a1, 1              # +0   1
    .option norvc
    beq a0, a1, 9f          # +2   1  not taken
    bne a0, a1, 1f          # +6   4  taken, to a 32-bit instruction at +14
    .option rvc
    c.nop                   # +10     skipped
    c.nop                   # +12     skipped
    .option norvc
1:  addi a2, a0, 1          # +14  1
    .option rvc
    c.beqz a0, 2f           # +18  3  taken, to a compressed instruction at +22
    c.nop                   # +20     skipped
2:  c.addi a2, 1            # +22  1
    .option norvc
    j 3f                    # +24  3  to a 32-bit instruction at +30
    .option rvc
    c.nop                   # +28     skipped
    .option norvc
3:  addi a3, a0, 2          # +30  1
    .option rvc
    c.j 4f                  # +34  2  to a 32-bit instruction at +36
    .option norvc
4:  addi a4, a0, 3          # +36  1
    .option rvc
    c.bnez a0, 9f           # +40  1  not taken
    c.jr ra                 # +42  2
9:  c.jr ra
    .option norvc

# Misaligned accesses, which the bench refuses (the run fails, naming the access): refusal_cases.
    .option rvc
    .balign 4
    .option norvc
    .type cal_misaligned_load, @function
cal_misaligned_load:
    addi sp, sp, -16
    lw a1, 2(sp)
    addi sp, sp, 16
    ret
    .type cal_misaligned_store, @function
cal_misaligned_store:
    addi sp, sp, -16
    sh a1, 1(sp)
    addi sp, sp, 16
    ret

    .section .rodata
name_misaligned_load: .asciz "misaligned load"
name_misaligned_store: .asciz "misaligned store"
text_misaligned_load: .asciz "a misaligned 4-byte load"
text_misaligned_store: .asciz "a misaligned 2-byte store"
name_alu_loop: .asciz "alu loop"
name_loads: .asciz "loads and stores"
name_calls: .asciz "jal, jalr, hazards"
name_muldiv: .asciz "mul, mulh, div, rem"
name_branches: .asciz "branches, jump targets"
    .balign 4
    .global calibration_cases
calibration_cases:
    .word name_alu_loop, cal_alu_loop, 100, 401, 600
    .word name_loads, cal_loads, 0, 21, 27
    .word name_calls, cal_calls, 0, 18, 28
    .word name_muldiv, cal_muldiv, 0, 17, 156
    .word name_branches, cal_branches, 0, 12, 21
    .word 0, 0, 0, 0, 0
    .balign 4
    .global refusal_cases
refusal_cases:
    .word name_misaligned_load, cal_misaligned_load, 0, text_misaligned_load
    .word name_misaligned_store, cal_misaligned_store, 0, text_misaligned_store
    .word 0, 0, 0, 0
