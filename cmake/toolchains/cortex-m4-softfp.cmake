# SPDX-License-Identifier: MIT
# Toolchain of the cortex-m4-softfp preset (CMakePresets.json): Cortex-M4F, Armv7E-M, FPU
# instructions with the soft-float calling convention (links with -mfloat-abi=soft and softfp
# firmware)
# (multilib thumb/v7e-m+fp/softfp of arm-none-eabi-gcc).
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=softfp -mfpu=fpv4-sp-d16")
include(${CMAKE_CURRENT_LIST_DIR}/../arm-none-eabi.cmake)
