#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds the Cortex-M4 side of bench-mcu (tools/bench-mcu/m4) in <dir>, with the
# project's arm-none-eabi toolchain file. Usage: build-m4.sh <dir> [target...] (default: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:?usage: build-m4.sh <dir> [target...]}
shift
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root/tools/bench-mcu/m4" -B "$dir" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi.cmake" \
  -DCMAKE_BUILD_TYPE= "${launcher[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j2 "${targets[@]}"
