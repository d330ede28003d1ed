#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Command-line contract of trisim: outputs, JSON keys, diagnostics and exit codes.
# Usage: test_trisim_cli.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
source "$(dirname "$0")/cli_checks.sh"

tri=$tmp/rgb.tri
cat >"$tri" <<'TRI'
tri 1
size 24 16
channels rgb
vertices 5
0 0 0 10 200
23 0 255 30 20
23 15 128.5 50 60
0 15 3 70 80
11 7 90 250 0
TRI
cat >"$tmp/bad.tri" <<'TRI'
tri 1
size 10 10
channels grey
vertices 3
0 0 1
9 0 2
0 9 300
TRI

expect 0 "" "$bin/trisim" --help
expect 0 "" "$bin/trisim" render --help
expect 64 "" "$bin/trisim"
expect 64 "--method" "$bin/trisim" render "$tri" --method nosuch -o "$tmp/x.png"
expect 66 "cannot open" "$bin/trisim" render "$tmp/missing.tri" -o "$tmp/x.png"
expect 65 "bad.tri:7: expected a value" "$bin/trisim" render "$tmp/bad.tri" -o "$tmp/x.png"
expect 73 "cannot write" "$bin/trisim" render "$tri" -o "$tmp/no/such/dir/x.png"
expect 0 "" "$bin/trisim" render "$tri" --method zienkiewicz -o "$tmp/a.png"
[ -s "$tmp/a.png" ] && passes=$((passes + 1)) || { echo "FAIL: render wrote no PNG"; failures=$((failures + 1)); }
ls "$tmp" | grep -q '\.tmp\.' && { echo "FAIL: a temporary file was left behind"; failures=$((failures + 1)); }


# Outputs that are not regular files: a device is written through (and /dev/full's ENOSPC is an
# error), a FIFO is written through and stays a FIFO, a link stays a link. Inputs must be regular files.
expect 73 "No space left" "$bin/trisim" render "$tri" -o /dev/full
[ -c /dev/full ] && passes=$((passes + 1)) || { echo "FAIL: /dev/full is no longer a device"; failures=$((failures + 1)); }
mkfifo "$tmp/out.fifo"
timeout 20 cat "$tmp/out.fifo" >"$tmp/from_fifo" &
reader=$!
expect 0 "" timeout 20 "$bin/trisim" render "$tri" --method zienkiewicz -o "$tmp/out.fifo"
wait $reader
cmp -s "$tmp/from_fifo" "$tmp/a.png" && [ -p "$tmp/out.fifo" ] && passes=$((passes + 1)) ||
  { echo "FAIL: render to a FIFO did not write through it"; failures=$((failures + 1)); }
rm -f "$tmp/out.fifo" "$tmp/from_fifo"
ln -s "$tmp/a.png" "$tmp/link.png"
expect 0 "" "$bin/trisim" render "$tri" --method bilinear -o "$tmp/link.png"
expect 0 "" "$bin/trisim" render "$tri" --method bilinear -o "$tmp/b.png"
[ -L "$tmp/link.png" ] && cmp -s "$tmp/a.png" "$tmp/b.png" && passes=$((passes + 1)) ||
  { echo "FAIL: render through a link replaced the link"; failures=$((failures + 1)); }
rm -f "$tmp/link.png" "$tmp/b.png"
expect 0 "" "$bin/trisim" render "$tri" --method zienkiewicz -o "$tmp/a.png"
expect 66 "directory" "$bin/trisim" render "$tmp" -o "$tmp/x.png"
mkfifo "$tmp/in.fifo"
expect 66 "not a regular file" timeout 20 "$bin/trisim" render "$tmp/in.fifo" -o "$tmp/x.png"
rm -f "$tmp/in.fifo"

expect 0 "" "$bin/trisim" compare "$tri" --method bilinear --original "$tmp/a.png" --json
for key in method engine mse psnr ssim ms; do
  grep -q "\"$key\":" "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: compare --json lacks '$key'"; failures=$((failures + 1)); }
done
expect 65 "expected an image of 20x20" "$bin/trisim" compare "$tri" --width 20 --height 20 --original "$tmp/a.png"
# The gradient methods: where the gradients come from, and bilinear recommended at equal bytes;
# nothing of it for bilinear alone.
expect 0 "" "$bin/trisim" compare "$tri" --method bilinear zienkiewicz --original "$tmp/a.png"
for line in "# gradients: estimated from the surface" "bilinear is the recommended method"; do
  grep -qF -- "$line" "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: compare -m zienkiewicz lacks '$line'"; failures=$((failures + 1)); }
done
expect 0 "" "$bin/trisim" compare "$tri" --method bilinear --original "$tmp/a.png"
grep -qF "recommended" "$tmp/out" && { echo "FAIL: compare -m bilinear prints the methods' note"; failures=$((failures + 1)); } || passes=$((passes + 1))
# --fit (docs/CONVENTIONS.md "Fitting"): 24 x 16 inside 47 x 47 and filling 40 x 31 are scaled by
# 2 (a border of 8 rows above and below; 4 columns cropped on the left, 3 on the right), where the
# core stays within the tolerance of the reference (bilinear 1, zienkiewicz 2).
expect 64 "--fit" "$bin/trisim" render "$tri" --fit squash -o "$tmp/x.png"
for fit in inside:47:47 fill:40:31; do
  IFS=: read -r mode w h <<<"$fit"
  expect 0 "" "$bin/trisim" render "$tri" --fit "$mode" --width "$w" --height "$h" -o "$tmp/fit.png"
  for m in bilinear:1 zienkiewicz:2; do
    expect 0 "" "$bin/trisim" compare "$tri" --fit "$mode" --width "$w" --height "$h" --method "${m%:*}" \
      --engine core --original "$tmp/fit.png" --json
    diff=$(grep -o '"max_abs_diff_vs_reference":[0-9]*' "$tmp/out" | cut -d: -f2)
    [ -n "$diff" ] && [ "$diff" -le "${m#*:}" ] && passes=$((passes + 1)) ||
      { echo "FAIL: --fit $mode ${m%:*}: core against reference: $(cat "$tmp/out")"; failures=$((failures + 1)); }
  done
done
expect 0 "" "$bin/trisim" metrics "$tmp/a.png" "$tmp/a.png" --json
grep -q '"mse":0' "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: metrics of identical images: $(cat "$tmp/out")"; failures=$((failures + 1)); }
expect 66 "" "$bin/trisim" metrics "$tmp/a.png" "$tmp/missing.png"

for engine in reference core; do
  expect 0 "" "$bin/trisim" bench "$tri" --method zienkiewicz --engine "$engine" --runs 3 --json
  for key in ms_median ms_min cpu_ms_median mpix_per_s runs pixels; do
    grep -q "\"$key\":" "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: bench --json ($engine) lacks '$key'"; failures=$((failures + 1)); }
  done
done
grep -q '"ram_bytes":' "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: bench --engine core --json lacks 'ram_bytes'"; failures=$((failures + 1)); }
expect 64 "" "$bin/trisim" bench "$tri" --method coons --engine core

finish
