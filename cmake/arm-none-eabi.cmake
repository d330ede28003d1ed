# SPDX-License-Identifier: MIT
# CMake toolchain for arm-none-eabi-gcc (Debian gcc-arm-none-eabi + libstdc++-arm-none-eabi-newlib).
# TRISTREAM_ARM_FLAGS selects the CPU: the default is the Cortex-M4 firmware target; the qemu
# run of the golden test uses an A-profile CPU (firmware_core/cross/run-golden-qemu.sh).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m4 -mthumb" CACHE STRING "CPU flags of the cross build")
set(CMAKE_C_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
