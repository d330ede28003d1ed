# SPDX-License-Identifier: MIT
# Toolchain of the cortex-m33 preset (CMakePresets.json): Cortex-M33, Armv8-M Mainline with the
# single-precision FPU, hard-float ABI
# (multilib thumb/v8-m.main+fp/hard of arm-none-eabi-gcc).
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16")
include(${CMAKE_CURRENT_LIST_DIR}/../arm-none-eabi.cmake)
