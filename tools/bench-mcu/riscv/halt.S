/* SPDX-License-Identifier: MIT */
# The address the harness puts in ra before calling into the program: emulation stops when
# execution reaches it (uc_emu_start's `until`). The instructions are never executed.
    .option norvc
    .section .text.bench_halt, "ax", @progbits
    .balign 4
    .global bench_halt
    .type bench_halt, @function
bench_halt:
    ebreak
    j bench_halt
    .size bench_halt, . - bench_halt
