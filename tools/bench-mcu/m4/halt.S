/* SPDX-License-Identifier: MIT */
@ The address the harness puts in LR before calling into the program: emulation stops when
@ execution reaches it (uc_emu_start's `until`). The instructions are never executed.
    .syntax unified
    .thumb
    .section .text.bench_halt, "ax", %progbits
    .global bench_halt
    .type bench_halt, %function
    .thumb_func
bench_halt:
    bkpt #0
    b bench_halt
    .size bench_halt, . - bench_halt
