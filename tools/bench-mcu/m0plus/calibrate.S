/* SPDX-License-Identifier: MIT */
@ Calibration loops for the Cortex-M0+ cycle model of bench-mcu: hand-written ARMv6-M code with
@ the instruction and cycle counts worked out by hand from docs/MCU_BENCH.md's Cortex-M0+ table,
@ next to each instruction. `bench_mcu calibrate --cpu m0plus` runs every case of
@ calibration_cases (name, function, r0, instructions, cycles) counting per block and per
@ instruction; both must equal the table. Each function returns with bx lr (2 cycles), counted.
@ refusal_cases (name, function, r0, text) must each stop the run with an error containing the
@ text: an ARMv6-M core has neither Thumb-2 instructions nor unaligned halfword and word access.
    .syntax unified
    .cpu cortex-m0plus
    .thumb
    .text

@ N iterations of three ALU instructions and a loop branch: 4N + 1 instructions,
@ 3N + 2(N - 1) (taken) + 1 (not taken) + 2 cycles; N = 100: 401, 501.
    .thumb_func
cal_alu_loop:
1:  adds r1, #1
    eors r2, r1
    subs r0, #1
    bne 1b
    bx lr

@ Single loads and stores of each width (2 each, whatever came before), a literal load. r0 = 4:
@ 17 instructions, 1 + 1 + 10 * 2 + 1 + 2 + 2 + 1 + 2 = 30 cycles.
    .thumb_func
cal_loads:
    sub sp, #16             @ 1
    mov r3, sp              @ 1
    str r3, [sp, #8]        @ 2
    ldr r1, [sp, #8]        @ 2
    ldr r2, [sp, #8]        @ 2  no pipelining of loads
    ldr r1, [r3, r0]        @ 2  register offset
    strh r2, [r3, #2]       @ 2
    ldrh r1, [r3, #2]       @ 2
    strb r2, [r3, #1]       @ 2
    ldrb r1, [r3, #1]       @ 2
    ldrsh r1, [r3, r0]      @ 2
    ldrsb r1, [r3, r0]      @ 2
    adds r3, #4             @ 1
    ldr r1, [r3]            @ 2  an address just computed costs nothing more
    ldr r1, =0x12345678     @ 2  literal
    add sp, #16             @ 1
    bx lr                   @ 2
    .ltorg

@ PUSH, BL, a leaf, POP with PC: 5 instructions, 6 + 3 + 1 + 2 + 8 = 20 cycles.
    .thumb_func
cal_calls:
    push {r4-r7, lr}        @ 1 + 5
    bl cal_leaf             @ 3
    pop {r4-r7, pc}         @ 3 + 5
    .thumb_func
cal_leaf:
    movs r1, #1             @ 1
    bx lr                   @ 2

@ MULS (1, the single-cycle multiplier), LDM / STM (1 + N), BLX (2), MOV PC (2), ADD PC (2),
@ POP {PC} (3 + N): 20 instructions (the leaf's 2 included), 35 cycles.
    .thumb_func
cal_multiple:
    push {lr}               @ 2
    movs r1, #7             @ 1
    movs r2, #5             @ 1
    muls r1, r2, r1         @ 1
    sub sp, #16             @ 1
    mov r3, sp              @ 1
    stmia r3!, {r0-r2}      @ 4
    subs r3, #12            @ 1
    ldmia r3!, {r0-r2}      @ 4
    add sp, #16             @ 1
    ldr r2, =cal_leaf       @ 2  (the Thumb bit set)
    blx r2                  @ 2  + the leaf: 1 + 2
    adr r2, 2f              @ 1
    adds r2, #1             @ 1
    mov pc, r2              @ 2
    .p2align 2
2:  movs r1, #0             @ 1
    add pc, r1              @ 2  to the instruction after the next (PC reads 4 ahead)
    b 3f                    @    skipped
3:  pop {pc}                @ 3 + 1
    .ltorg

@ B<cond> taken (2) and not taken (1), B (2). r0 = 0: 6 instructions, 1 + 2 + 1 + 2 + 1 + 2 = 9.
    .thumb_func
cal_branches:
    cmp r0, #0              @ 1
    beq 1f                  @ 2  taken
    nop
1:  bne 2f                  @ 1  not taken
    b 3f                    @ 2
2:  nop
3:  movs r1, #1             @ 1
    bx lr                   @ 2

@ Refused: a Thumb-2 instruction (ADD.W), CBZ, an unaligned word load and an unaligned
@ halfword store.
    .thumb_func
bad_thumb2:
    movs r1, #1
    .inst.w 0xf1010101      @ add.w r1, r1, #1
    bx lr
    .thumb_func
bad_cbz:
    .short 0xb100           @ cbz r0, (the next instruction but one)
    nop
    bx lr
    .thumb_func
bad_word:
    mov r1, sp
    subs r1, #6
    ldr r2, [r1]
    bx lr
    .thumb_func
bad_halfword:
    mov r1, sp
    subs r1, #3
    strh r0, [r1]
    bx lr

    .section .rodata.calibration_cases, "a"
    .p2align 2
    .global calibration_cases
calibration_cases:
    .word n_alu, cal_alu_loop, 100, 401, 501
    .word n_loads, cal_loads, 4, 17, 30
    .word n_calls, cal_calls, 0, 5, 20
    .word n_multiple, cal_multiple, 0, 20, 35
    .word n_branches, cal_branches, 0, 6, 9
    .word 0, 0, 0, 0, 0
    .global refusal_cases
refusal_cases:
    .word n_thumb2, bad_thumb2, 0, t_thumb2
    .word n_cbz, bad_cbz, 0, t_cbz
    .word n_word, bad_word, 0, t_word
    .word n_halfword, bad_halfword, 0, t_halfword
    .word 0, 0, 0, 0
n_alu: .asciz "alu loop x100"
n_loads: .asciz "loads and stores"
n_calls: .asciz "push, bl, pop pc"
n_multiple: .asciz "muls, ldm, stm, blx, pc"
n_branches: .asciz "beq, bne, b"
n_thumb2: .asciz "add.w"
n_cbz: .asciz "cbz"
n_word: .asciz "unaligned ldr"
n_halfword: .asciz "unaligned strh"
t_thumb2: .asciz "not an ARMv6-M instruction: 0x"
t_cbz: .asciz "cbz r0"
t_word: .asciz "unaligned 4-byte access"
t_halfword: .asciz "unaligned 2-byte access"
