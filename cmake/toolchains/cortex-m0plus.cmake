# SPDX-License-Identifier: MIT
# Toolchain of the cortex-m0plus preset (CMakePresets.json): Cortex-M0+, Armv6-M, no FPU
# (multilib thumb/v6-m/nofp of arm-none-eabi-gcc).
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
include(${CMAKE_CURRENT_LIST_DIR}/../arm-none-eabi.cmake)
