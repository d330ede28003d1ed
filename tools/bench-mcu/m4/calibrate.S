/* SPDX-License-Identifier: MIT */
@ Calibration loops for the bench-mcu cycle model: hand-written Thumb-2 with the instruction and
@ cycle counts worked out by hand from docs/MCU_BENCH.md's table (P = 2), next to each
@ instruction. `bench_mcu calibrate` runs every case of calibration_cases (name, function, r0,
@ instructions, cycles) counting per block and per instruction; both must equal the table. Each
@ function returns with bx lr (1 + P = 3 cycles), counted.
    .syntax unified
    .thumb
    .text

@ N iterations of three ALU instructions and a loop branch: 4N + 1 instructions,
@ 3N + 3(N - 1) (taken) + 1 (not taken) + 3 cycles; N = 100: 401, 601.
    .thumb_func
cal_alu_loop:
1:  adds r1, #1
    eors r2, r1
    subs r0, #1
    bne 1b
    bx lr

@ Single loads and stores: pipelining, the stall on an address just computed, LDRD. r0 = 0.
@ 17 instructions, 27 cycles.
    .thumb_func
cal_loads:
    sub sp, #16             @ 1
    mov r3, sp              @ 1
    str r3, [sp, #8]        @ 1  STR with an immediate offset
    nop                     @ 1
    ldr r1, [sp, #0]        @ 2
    ldr r2, [sp, #4]        @ 1  pipelined after a load
    ldr r3, [sp, #8]        @ 1  pipelined
    ldr r1, [r3]            @ 2  its address is the previous load's result: not pipelined
    str r2, [sp, #12]       @ 1
    ldr r1, [sp, #4]        @ 2  nothing is pipelined after a store
    str r2, [r3, r0]        @ 1  register offset, pipelined after a load
    str r2, [r3, r0]        @ 2  register offset after a store
    adds r3, #4             @ 1
    ldr r1, [r3]            @ 3  address from the preceding data-processing instruction: +1
    ldrd r1, r2, [sp]       @ 3  1 + N
    add sp, #16             @ 1
    bx lr                   @ 3

@ PUSH, BL, a leaf, POP with PC: 5 instructions, 6 + 3 + 1 + 3 + 8 = 21 cycles.
    .thumb_func
cal_calls:
    push {r4-r7, lr}        @ 1 + 5
    bl cal_leaf             @ 1 + P
    pop {r4-r7, pc}         @ 1 + 5 + P
    .thumb_func
cal_leaf:
    movs r1, #1             @ 1
    bx lr                   @ 1 + P

@ Multiplies (1 each) and divisions (2 + ceil(10 q / 32), q = quotient bits): 16 instructions,
@ 37 cycles.
    .thumb_func
cal_muldiv:
    movs r1, #7             @ 1
    movs r2, #5             @ 1
    mul r3, r1, r2          @ 1
    umull r3, r12, r1, r2   @ 1
    smlal r3, r12, r1, r2   @ 1
    mla r3, r1, r2, r3      @ 1
    udiv r3, r2, r1         @ 2  5 / 7: quotient 0
    udiv r3, r1, r2         @ 3  7 / 5: q = 1
    mvn r1, #0              @ 1
    movs r2, #1             @ 1
    udiv r3, r1, r2         @ 12 0xFFFFFFFF / 1: q = 32
    movs r2, #3             @ 1
    sdiv r3, r1, r2         @ 2  -1 / 3: quotient 0
    movw r1, #1000          @ 1
    udiv r3, r1, r2         @ 5  1000 / 3: q = 9
    bx lr                   @ 3

@ IT folding (0 after a 16-bit instruction, 1 after a 32-bit one) and an instruction whose
@ condition fails (counted, 1 cycle). r0 = 5: 8 instructions, 9 cycles.
    .thumb_func
cal_it:
    cmp r0, #3              @ 1
    ite gt                  @ 0  folded
    movgt r1, #1            @ 1
    movle r1, #2            @ 1  condition fails
    cmp.w r0, #4            @ 1
    it ne                   @ 1  after a 32-bit instruction
    addne r1, #1            @ 1
    bx lr                   @ 3

@ CBZ taken (1 + P), CBNZ not taken (1), B (1 + P), TBB (2 + P). r0 = 0: 6 instructions,
@ 3 + 1 + 3 + 1 + 4 + 3 = 15 cycles.
    .thumb_func
cal_branches:
    cbz r0, 1f
    nop
1:  cbnz r0, 2f
    b 3f
2:  nop
3:  movs r1, #1
    tbb [pc, r1]
4:  .byte (5f - 4b) / 2
    .byte (6f - 4b) / 2
    .p2align 1
5:  nop
6:  bx lr

@ A conditional return in an IT block: r0 = 1 returns (3 instructions, 1 + 0 + 3 = 4 cycles);
@ r0 = 0 falls through (5 instructions, 1 + 0 + 1 + 1 + 3 = 6 cycles).
    .thumb_func
cal_cond_return:
    cmp r0, #1
    it eq
    bxeq lr
    movs r1, #0
    bx lr

    .section .rodata.calibration_cases, "a"
    .p2align 2
    .global calibration_cases
calibration_cases:
    .word n_alu, cal_alu_loop, 100, 401, 601
    .word n_loads, cal_loads, 0, 17, 27
    .word n_calls, cal_calls, 0, 5, 21
    .word n_muldiv, cal_muldiv, 0, 16, 37
    .word n_it, cal_it, 5, 8, 9
    .word n_branches, cal_branches, 0, 6, 15
    .word n_ret_taken, cal_cond_return, 1, 3, 4
    .word n_ret_not, cal_cond_return, 0, 5, 6
    .word 0, 0, 0, 0, 0
n_alu: .asciz "alu loop x100"
n_loads: .asciz "loads and stores"
n_calls: .asciz "push, bl, pop pc"
n_muldiv: .asciz "multiplies, divisions"
n_it: .asciz "it blocks"
n_branches: .asciz "cbz, cbnz, b, tbb"
n_ret_taken: .asciz "bxeq taken"
n_ret_not: .asciz "bxeq not taken"
