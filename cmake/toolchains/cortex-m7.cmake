# SPDX-License-Identifier: MIT
# Toolchain of the cortex-m7 preset (CMakePresets.json): Cortex-M7, Armv7E-M with the double-
# precision FPU, hard-float ABI
# (multilib thumb/v7e-m+dp/hard of arm-none-eabi-gcc).
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-d16")
include(${CMAKE_CURRENT_LIST_DIR}/../arm-none-eabi.cmake)
