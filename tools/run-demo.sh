#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job of `make run`: renders every demo triangulation in data/demo with every method
# (reference engine) and with the firmware core (bilinear, zienkiewicz) into OUT_DIR/<name>/
# [core/]<method>.png and prints, per triangulation, a table of method, engine,
# MSE, PSNR, SSIM and milliseconds against the original photograph.
# Demo files are named <image>.<kind>.tri and compared with data/demo/<image>.png.
# Usage: tools/run-demo.sh BIN_DIR OUT_DIR
set -euo pipefail
bin=$(cd "${1:?usage: run-demo.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run-demo.sh BIN_DIR OUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)

shopt -s nullglob
files=("$root"/data/demo/*.tri)
[ ${#files[@]} -gt 0 ] || { echo "run-demo: no .tri files in $root/data/demo" >&2; exit 66; }
for tri in "${files[@]}"; do
  stem=$(basename "$tri" .tri)
  image=${stem%%.*}
  mkdir -p "$out/$stem"
  echo
  echo "== $stem.tri against $image.png -> $out/$stem/"
  "$bin/trisim" compare "$tri" --method all --original "$root/data/demo/$image.png" --save "$out/$stem"
  # The fixed-point firmware core, run on the host: 32x32 tiles, RGB888 (L8 for grey).
  mkdir -p "$out/$stem/core"
  "$bin/trisim" compare "$tri" --engine core --method bilinear zienkiewicz --original "$root/data/demo/$image.png" \
    --save "$out/$stem/core" | grep -v '^method'
done
