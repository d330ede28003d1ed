#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# trisim options that scripts and firmware developers rely on: metrics thresholds (--max-mse,
# --min-psnr: exit 1 when not met), compare --save into a new directory, --method all with the
# core, --background R,G,B, and --viewport/--tile-width/--tile-height reproducing a firmware frame
# (a golden of tests/golden, rendered by the core with RenderParams set as here).
# Usage: test_trisim_options.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
source "$(dirname "$0")/cli_checks.sh"
trisim=$bin/trisim
golden=$src/tests/golden

# Two renders that differ: bilinear and zienkiewicz of the same triangulation.
expect 0 "" "$trisim" render "$golden/grey.tri" --method bilinear -o "$tmp/a.png"
expect 0 "" "$trisim" render "$golden/grey.tri" --method zienkiewicz -o "$tmp/b.png"
expect 0 "" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --json
mse=$(grep -oE '"mse":[0-9.e+-]+' "$tmp/out" | cut -d: -f2)
psnr=$(grep -oE '"psnr":[0-9.e+-]+' "$tmp/out" | cut -d: -f2)
check "the two renders differ (mse $mse)" awk "BEGIN { exit !($mse > 0.01) }"
above=$(awk "BEGIN { print $mse * 1.01 }")
below=$(awk "BEGIN { print $mse * 0.99 }")
expect 0 "" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --max-mse "$above"
expect 1 "is above --max-mse" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --max-mse "$below"
check "the metrics are still printed when a threshold fails" grep -q "^mse " "$tmp/out"
expect 0 "" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --min-psnr "$(awk "BEGIN { print $psnr - 0.01 }")"
expect 1 "is below --min-psnr" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --min-psnr "$(awk "BEGIN { print $psnr + 0.01 }")"
expect 1 "" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --max-mse "$above" --min-psnr 200 --json
expect 0 "" "$trisim" metrics "$tmp/a.png" "$tmp/a.png" --max-mse 0 --min-psnr 200
expect 64 "--max-mse" "$trisim" metrics "$tmp/a.png" "$tmp/b.png" --max-mse -1

# compare --save creates its directory (and its parents); a file in the way is an error.
expect 0 "" "$trisim" compare "$golden/grey.tri" --engine core --method bilinear --save "$tmp/new/dir"
check "compare --save wrote into a new directory" test -s "$tmp/new/dir/bilinear.png"
touch "$tmp/file"
expect 73 "--save: $tmp/file" "$trisim" compare "$golden/grey.tri" --engine core --save "$tmp/file"

# --method all with the core: the core's methods, and a note naming the skipped ones.
expect 0 "skipped: bezier, coons, voronoi, natural, clough-tocher" \
  "$trisim" compare "$golden/rgb.tri" --engine core --method all --json
check "--method all --engine core: two methods measured" test "$(grep -c '"method"' "$tmp/out")" -eq 2
expect 0 "the blob is packed for zienkiewicz; skipped: bilinear," "$trisim" compare "$golden/rgb-zienkiewicz.bin" --method all --json
check "--method all of a blob: its own method" test "$(grep -c '"method":"zienkiewicz"' "$tmp/out")" -eq 1
expect 64 "the core renders bilinear and zienkiewicz only" "$trisim" compare "$golden/rgb.tri" --engine core --method bezier
check "nothing printed before a usage error" test ! -s "$tmp/out"

# --background R,G,B: the border of a fit inside, by the core (the frame's bytes) and the reference.
expect 0 "" "$trisim" render "$golden/rgb.tri" --engine core --fit inside --width 64 --height 64 --background 255,0,7 \
  --raw -o "$tmp/bg.raw"
check "core: the first pixel is the background 255 0 7" test "$(od -An -tu1 -N3 "$tmp/bg.raw" | tr -s ' ')" = " 255 0 7"
expect 0 "" "$trisim" render "$golden/rgb.tri" --engine core --fit inside --width 64 --height 64 --background 255,0,7 \
  -o "$tmp/bg-core.png"
expect 0 "" "$trisim" render "$golden/rgb.tri" --fit inside --width 64 --height 64 --background 255,0,7 -o "$tmp/bg-ref.png"
expect 0 "" "$trisim" metrics "$tmp/bg-core.png" "$tmp/bg-ref.png" --max-mse 1
expect 0 "" "$trisim" render "$golden/grey.tri" --engine core --fit inside --width 64 --height 64 --background 9,200,200 \
  --raw -o "$tmp/grey.raw"
check "a grey render takes the first value" test "$(od -An -tu1 -N1 "$tmp/grey.raw" | tr -d ' ')" = 9
for bad in 1,2 256 1,2,3,4 a,b,c ""; do
  expect 64 "--background: expected one value or R,G,B" "$trisim" render "$golden/rgb.tri" --background "$bad" -o "$tmp/x.png"
done

# --viewport and --tile-width/--tile-height with the core's meaning: the golden case
# ycbcr-zienkiewicz-xrgb8888-bands-viewport (viewport {20, 10, 170, 110}, tiles 0 x 8, background
# 255 0 255) pixel for pixel.
expect 0 "" "$trisim" render "$golden/ycbcr-layers-zienkiewicz.bin" --viewport 20,10,170,110 --tile-width 0 \
  --tile-height 8 --format xrgb8888 --background 255,0,255 -o "$tmp/view.png"
expect 0 "" "$trisim" metrics "$tmp/view.png" "$golden/ycbcr-zienkiewicz-xrgb8888-bands-viewport.png" --max-mse 0
expect 0 "" "$trisim" render "$golden/rgb-zienkiewicz.bin" --tile-width 13 --tile-height 7 -o "$tmp/t.png"
expect 0 "" "$trisim" metrics "$tmp/t.png" "$golden/rgb-zienkiewicz-rgb888-tiles13x7.png" --max-mse 0
# The viewport is the output's part: a 10 x 5 frame of bytes.
expect 0 "" "$trisim" render "$golden/rgb-zienkiewicz.bin" --viewport 5,5,15,10 --raw -o "$tmp/v.raw"
check "--viewport 5,5,15,10: 10 x 5 pixels of RGB888" test "$(stat -c %s "$tmp/v.raw")" -eq 150
expect 64 "--viewport: expected X0,Y0,X1,Y1" "$trisim" render "$golden/rgb.tri" --engine core --viewport 5,5,5,10 -o "$tmp/x.png"
expect 64 "--viewport: applies to --engine core only" "$trisim" render "$golden/rgb.tri" --viewport 0,0,5,5 -o "$tmp/x.png"
expect 64 "--tile-width: applies to --engine core only" "$trisim" render "$golden/rgb.tri" --tile-width 8 -o "$tmp/x.png"
expect 64 "render options" "$trisim" render "$golden/rgb.tri" --engine core --viewport 0,0,500,10 -o "$tmp/x.png"

finish
