#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Compiles the examples and their generated blobs for Cortex-M4 with arm-none-eabi-gcc as C99,
# -Wall -Wextra -Wpedantic -Werror (objects only: a board supplies display.h's driver and links).
# Usage: check_examples_cortex_m4.sh ARM_GCC SOURCE_DIR EXAMPLES_BUILD_DIR
set -euo pipefail
gcc=$1
src=$2
build=$3
mkdir -p "$build/cortex-m4"
for c in "$src/examples/display_bands.c" "$src/examples/display_zoom.c" "$src/examples/display_dma.c" "$src/examples/display_fit.c" "$build/kodim23.c" "$build/kodim23_zoom.c"; do
  "$gcc" -mcpu=cortex-m4 -mthumb -mfloat-abi=soft -Os -std=c99 -Wall -Wextra -Wpedantic -Werror \
    -I"$src/firmware_core/include" -I"$src/examples" -I"$build" -c "$c" -o "$build/cortex-m4/$(basename "$c" .c).o"
done
echo "check_examples_cortex_m4: display_bands, display_zoom, display_dma, display_fit and their blobs compile for Cortex-M4"
