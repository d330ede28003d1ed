#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench-mcu: cross-builds the Cortex-M4 programs (build-m4.sh) into <build>/bench-mcu-m4 and
# runs the whole matrix with bench_mcu (one JSON line per configuration, then a summary), then the
# same for the Cortex-M0+ (build-m0plus.sh, <build>/bench-mcu-m0plus; its stack is reported, not
# held to core_stack_bytes, whose limits are the M4's). Extra arguments go to `bench_mcu run`, e.g.
# a subset: --meshes kodim23 --opts O2 --dither off. BENCH_MCU_CPUS picks the cores (default
# "m4 m0plus").
# Usage: tools/bench-mcu/run.sh <host build dir> [bench_mcu run options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: run.sh <host build dir> [options...]}
shift
status=0
for cpu in ${BENCH_MCU_CPUS:-m4 m0plus}; do
  bash "$root/tools/bench-mcu/build-$cpu.sh" "$build/bench-mcu-$cpu" >/dev/null
  check=()
  [ "$cpu" = m4 ] && check=(--check-stack)
  "$build/bin/bench_mcu" run --cpu "$cpu" --elf-dir "$build/bench-mcu-$cpu" "${check[@]}" "$@" || status=1
done
exit $status
