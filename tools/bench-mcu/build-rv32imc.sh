#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds the RISC-V rv32imc side of bench-mcu (tools/bench-mcu/riscv) in <dir>,
# with the project's riscv32-unknown-elf toolchain file. Usage: build-rv32imc.sh <dir> [target...] (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:?usage: build-rv32imc.sh <dir> [target...]}
shift
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root/tools/bench-mcu/riscv" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/riscv32-unknown-elf.cmake" \
  -DCMAKE_BUILD_TYPE= "${launcher[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j2 "${targets[@]}"
