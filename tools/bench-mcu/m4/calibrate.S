    .syntax unified
    .thumb
    .section .rodata.calibration_cases
    .global calibration_cases
calibration_cases:
    .word 0
