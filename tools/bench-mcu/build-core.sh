#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds the programs of bench-mcu for one emulated core in <dir>, a separate cross
# build with the project's toolchain file for it:
#   m4       tools/bench-mcu/m4 for the Cortex-M4 (arm-none-eabi, the flags of its CMakeLists.txt)
#   m0plus   tools/bench-mcu/m4 for -mcpu=cortex-m0plus (ARMv6-M, the flags of
#            cmake/toolchains/cortex-m0plus.cmake)
#   rv32imc  tools/bench-mcu/riscv (riscv32-unknown-elf)
# Usage: build-core.sh <core> <dir> [target...] (default: all).
set -euo pipefail
usage="usage: build-core.sh m4|m0plus|rv32imc <dir> [target...]"
root=$(cd "$(dirname "$0")/../.." && pwd)
core=${1:?$usage}
dir=${2:?$usage}
shift 2
case $core in
  m4) project=m4 toolchain=arm-none-eabi flags=() ;;
  m0plus)
    project=m4 toolchain=arm-none-eabi
    flags=("-DTRISTREAM_ARM_FLAGS=-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft") ;;
  rv32imc) project=riscv toolchain=riscv32-unknown-elf flags=() ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root/tools/bench-mcu/$project" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/$toolchain.cmake" \
  "${flags[@]}" -DCMAKE_BUILD_TYPE= "${launcher[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j2 "${targets[@]}"
