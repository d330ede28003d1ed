#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench-mcu: cross-builds the Cortex-M4 programs (build-m4.sh) into <build>/bench-mcu-m4 and
# the RISC-V rv32imc programs (build-riscv.sh) into <build>/bench-mcu-riscv, and runs the whole
# matrix on both with bench_mcu (one JSON line per configuration, then a summary per core). Extra
# arguments go to `bench_mcu run`, e.g. a subset: --meshes kodim23 --opts O2 --dither off, or one
# core: --cpus riscv.
# Usage: tools/bench-mcu/run.sh <host build dir> [bench_mcu run options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: run.sh <host build dir> [options...]}
shift
bash "$root/tools/bench-mcu/build-m4.sh" "$build/bench-mcu-m4" >/dev/null
bash "$root/tools/bench-mcu/build-riscv.sh" "$build/bench-mcu-riscv" >/dev/null
exec "$build/bin/bench_mcu" run --elf-dir "$build/bench-mcu-m4" --riscv-elf-dir "$build/bench-mcu-riscv" \
  --check-stack "$@"
