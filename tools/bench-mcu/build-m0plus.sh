#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds the Cortex-M0+ side of bench-mcu in <dir>: the project of
# tools/bench-mcu/m4 for -mcpu=cortex-m0plus (ARMv6-M, the flags of cmake/toolchains/cortex-m0plus.cmake),
# with the project's arm-none-eabi toolchain file. Usage: build-m0plus.sh <dir> [target...] (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:?usage: build-m0plus.sh <dir> [target...]}
shift
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root/tools/bench-mcu/m4" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
  "-DTRISTREAM_ARM_FLAGS=-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft" -DCMAKE_BUILD_TYPE= "${launcher[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j2 "${targets[@]}"
