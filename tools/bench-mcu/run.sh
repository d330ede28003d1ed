#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make bench-mcu: cross-builds the Cortex-M4 programs (build-m4.sh) into <build>/bench-mcu-m4 and
# runs the whole matrix with bench_mcu (one JSON line per configuration, then a summary). Extra
# arguments go to `bench_mcu run`, e.g. a subset: --meshes kodim23 --opts O2 --dither off.
# Usage: tools/bench-mcu/run.sh <host build dir> [bench_mcu run options...]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:?usage: run.sh <host build dir> [options...]}
shift
bash "$root/tools/bench-mcu/build-m4.sh" "$build/bench-mcu-m4" >/dev/null
exec "$build/bin/bench_mcu" run --elf-dir "$build/bench-mcu-m4" --check-stack "$@"
