#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per pixel of the core (valgrind --tool=callgrind, counted inside
# tristream::core::render only) for the benchmark matrix of issue 3: 512 x 512, about 2,000,
# 4,000, 20,000 and 40,000 triangles, bilinear and zienkiewicz, 32x32 tiles and full frame,
# RGB888 and RGB565. Counted in the render call that takes RenderBuffers (the other one forwards
# to it; toggling on both would count nothing). Usage: tests/core/callgrind_core.sh <build-dir>/bin/core_frames
set -euo pipefail
driver=${1:?usage: callgrind_core.sh <path to core_frames>}
frames=2
printf "%-9s %-12s %-6s %-9s %12s\n" triangles method tile format instr/pixel
for n in 2000 4000 20000 40000; do
  for m in bilinear zienkiewicz; do
    for t in 32 0; do
      for f in rgb888 rgb565le; do
        out=$(mktemp)
        valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect='tristream::core::render(*RenderBuffers*' \
          "$driver" "$n" "$m" "$t" "$f" "$frames" >/dev/null 2>&1
        ir=$(callgrind_annotate "$out" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
        rm -f "$out"
        printf "%-9s %-12s %-6s %-9s %12.1f\n" "$n" "$m" "$([ "$t" = 0 ] && echo full || echo "$t")" "$f" \
          "$(awk -v ir="$ir" -v f="$frames" 'BEGIN { print ir / (f * 512 * 512) }')"
      done
    done
  done
done
