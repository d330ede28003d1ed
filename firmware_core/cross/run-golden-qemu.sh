#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the golden-image test as a 32-bit ARM binary (arm-none-eabi, Cortex-A7, newlib
# semihosting) and runs it under qemu-arm: the pixels must match the same PNGs as on x86-64.
# Usage: firmware_core/cross/run-golden-qemu.sh [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-cross}
cmake -S "$root/firmware_core/cross" -B "$build/golden" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
  -DTRISTREAM_ARM_FLAGS="-mcpu=cortex-a7 -marm" -DTRISTREAM_CROSS=golden -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build/golden" -j2
file "$build/golden/test_core_golden.elf" | sed 's/,.*ARM/: ARM/' | cut -c1-120
cd "$build/golden"
qemu-arm ./test_core_golden.elf
