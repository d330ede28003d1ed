# SPDX-License-Identifier: MIT
# Toolchain of the cortex-m4 preset (CMakePresets.json): Cortex-M4F, Armv7E-M with the single-
# precision FPU, hard-float ABI (floating-point arguments in FPU registers)
# (multilib thumb/v7e-m+fp/hard of arm-none-eabi-gcc).
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
include(${CMAKE_CURRENT_LIST_DIR}/../arm-none-eabi.cmake)
