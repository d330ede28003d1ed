#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench-mcu: cross-builds each core's programs (build-core.sh <core>) into <build>/bench-mcu-<core>
# and runs the whole matrix on them with one bench_mcu (one JSON line per configuration, then the
# summary per core). BENCH_MCU_CPUS picks the cores (default "m4 m0plus rv32imc"). Stacks are held
# to core_stack_bytes (--check-stack) on the Cortex-M4 only, whose limits they are; the other cores'
# are reported. Extra arguments go to `bench_mcu run`, e.g. a subset: --meshes kodim23 --opts O2
# --dither off.
# Usage: tools/bench-mcu/run.sh <host build dir> [bench_mcu run options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: run.sh <host build dir> [options...]}
shift
dirs=()
for cpu in ${BENCH_MCU_CPUS:-m4 m0plus rv32imc}; do
  bash "$root/tools/bench-mcu/build-core.sh" "$cpu" "$build/bench-mcu-$cpu" >/dev/null
  dirs+=("--$cpu-elf-dir" "$build/bench-mcu-$cpu")
done
exec "$build/bin/bench_mcu" run "${dirs[@]}" --check-stack "$@"
