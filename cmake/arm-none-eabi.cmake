# SPDX-License-Identifier: MIT
# CMake toolchain for arm-none-eabi-gcc (Debian gcc-arm-none-eabi + libstdc++-arm-none-eabi-newlib).
# TRISTREAM_ARM_FLAGS selects the CPU: the toolchain files of the presets (cmake/toolchains/*.cmake)
# set it before including this file; otherwise it is a cache variable whose default is the
# Cortex-M4 firmware target with the soft-float ABI; the qemu run of the golden test uses an
# A-profile CPU (firmware_core/cross/run-golden-qemu.sh). The flags go into CMAKE_<LANG>_FLAGS
# when the build directory is first configured; firmware_core/CMakeLists.txt stops the configure
# if a CMAKE_C_FLAGS or CMAKE_CXX_FLAGS given on the command line has replaced them.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
if(NOT DEFINED TRISTREAM_ARM_FLAGS)
  set(TRISTREAM_ARM_FLAGS "-mcpu=cortex-m4 -mthumb" CACHE STRING "CPU flags of the cross build")
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES TRISTREAM_ARM_FLAGS)
set(CMAKE_C_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${TRISTREAM_ARM_FLAGS}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
