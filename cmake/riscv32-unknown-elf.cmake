# SPDX-License-Identifier: MIT
# CMake toolchain for bare-metal RISC-V rv32imc (ESP32-C3 class), with Debian's
# gcc-riscv64-unknown-elf and picolibc-riscv64-unknown-elf (the compiler builds 32-bit code with
# -march/-mabi; GCC's multilib reuse links rv32imc against its rv32im/ilp32 libgcc and picolibc, so
# library code is uncompressed). TRISTREAM_RISCV_FLAGS selects the CPU; its default is rv32imc with
# the ilp32 (soft-float) ABI. Used by tools/bench-mcu/riscv (build-rv32imc.sh).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_CXX_COMPILER riscv64-unknown-elf-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
if(NOT DEFINED TRISTREAM_RISCV_FLAGS)
  set(TRISTREAM_RISCV_FLAGS "-march=rv32imc -mabi=ilp32" CACHE STRING "CPU flags of the cross build")
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES TRISTREAM_RISCV_FLAGS)
# picolibc's specs (in the compile flags, which the link uses too) give the C headers (stdint.h,
# string.h) and its libraries: the compiler has no C library of its own.
set(CMAKE_C_FLAGS_INIT "${TRISTREAM_RISCV_FLAGS} --specs=picolibc.specs")
set(CMAKE_CXX_FLAGS_INIT "${TRISTREAM_RISCV_FLAGS} --specs=picolibc.specs")
set(CMAKE_ASM_FLAGS_INIT "${TRISTREAM_RISCV_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${TRISTREAM_RISCV_FLAGS}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
