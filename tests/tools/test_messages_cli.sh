#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Messages that name what README promises (issue 44 item 9): the lines of a triangle that
# collapses on the core's grid (also in a triangulation the reader computed), the lines of two
# vertices that round to one point of that grid (issue 44), the coordinate budget behind a refused
# --fit fill, the files too small for SSIM, and a vertex count out of range as it was typed.
# Usage: test_messages_cli.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
source "$(dirname "$0")/cli_checks.sh"

# A 3 x 3 picture with a vertex 0.01 pixel off the edge between two corners: the triangle of the
# three collapses on the 1/16-pixel grid. With a comment line, so that line numbers are not indices + 5.
cat >"$tmp/computed.tri" <<'TRI'
tri 1
size 3 3
channels grey
# the four corners, then the vertex near the top edge
vertices 5
0 0 10
2 0 20
0 2 30
2 2 40
1 0.01 50
TRI
expect 65 "computed.tri: a triangle of the Delaunay triangulation the reader computed (the file lists no triangles), vertices on lines 6, 7 and 10, collapses" \
  "$bin/tripack" "$tmp/computed.tri" -o "$tmp/x.bin"
{ sed '/^#/d' "$tmp/computed.tri"; printf 'triangles 4\n0 4 2\n4 3 2\n4 1 3\n0 1 4\n'; } >"$tmp/listed.tri"
expect 65 "listed.tri: triangle 3 of the triangles section (counting from 0), vertices on lines 5, 6 and 9, collapses" \
  "$bin/tripack" "$tmp/listed.tri" -o "$tmp/x.bin"
check "nothing written for a collapsing triangle" test ! -e "$tmp/x.bin"

# Two vertices of different triangles 0.01 pixel apart (an hourglass's tips): no triangle collapses,
# but both round to one point of the grid, which the core would draw with two vertices' values
# (170 levels off the reference at that pixel). Refused when packed, naming both lines and points.
cat >"$tmp/hourglass.tri" <<'TRI'
tri 1
size 3 3
channels grey
# two triangles whose tips are 0.01 pixel apart
vertices 6
0 0 10
2 0 20
1 1 30
1 1.01 200
2 2 40
0 2 50
triangles 2
0 1 2
3 4 5
TRI
coincident="hourglass.tri: vertices on lines 8 (1, 1) and 9 (1, 1.01) both round to (1, 1) on the core's 1/16-pixel grid"
expect 65 "$coincident" "$bin/tripack" "$tmp/hourglass.tri" -o "$tmp/x.bin"
expect 65 "$coincident" "$bin/tripack" "$tmp/hourglass.tri" --compress -o "$tmp/x.bin"
expect 65 "$coincident" "$bin/tripack" "$tmp/hourglass.tri" -m zienkiewicz -o "$tmp/x.c"
check "nothing written for coincident vertices" test ! -e "$tmp/x.bin" -a ! -e "$tmp/x.c"
expect 65 "$coincident" "$bin/trisim" render "$tmp/hourglass.tri" --engine core -o "$tmp/x.png"
expect 65 "$coincident" "$bin/trisim" compare "$tmp/hourglass.tri" --engine core
# The reference draws the file as it is; 1/16 pixel apart (distinct on the grid) packs.
expect 0 "" "$bin/trisim" render "$tmp/hourglass.tri" -o "$tmp/x.png"
sed 's/^1 1.01 200$/1 1.0625 200/' "$tmp/hourglass.tri" >"$tmp/apart.tri"
expect 0 "" "$bin/tripack" "$tmp/apart.tri" -o "$tmp/x.bin"

# --fit fill of the 768 x 512 demo on 1500 x 1500 draws it 2250 pixels wide: past the core's
# coordinate budget. The message names the budget and the option, for a .tri, a blob and a
# compressed blob; a fill within the budget renders.
tri=$src/data/demo/kodim23.rgb.tri
expect 0 "" "$bin/tripack" "$tri" -o "$tmp/k.bin"
expect 0 "" "$bin/tripack" "$tri" --compress -o "$tmp/kc.bin"
for input in "$tri" "$tmp/k.bin" "$tmp/kc.bin"; do
  expect 64 "--fit fill: the 768 x 512 picture filling 1500 x 1500 would be drawn 2250 x 1500 pixels, beyond the core's coordinate budget of" \
    "$bin/trisim" render "$input" --engine core --fit fill --width 1500 --height 1500 -o "$tmp/fill.png"
  check "the message names the limit's macro and --fit inside" grep -q "(TS_MAX_DIMENSION.*--fit inside" "$tmp/err"
done
expect 0 "" "$bin/trisim" render "$tmp/k.bin" --fit fill --width 1200 --height 700 -o "$tmp/fill.png"

# SSIM of images smaller than its window names the files and the window.
expect 0 "" "$bin/trisim" render "$src/tests/golden/grey.tri" --width 5 --height 5 -o "$tmp/five.png"
cp "$tmp/five.png" "$tmp/other.png"
expect 65 "$tmp/five.png and $tmp/other.png: too small for SSIM: expected images of at least 11 x 11 pixels (the window of --ssim-window gaussian), found 5 x 5" \
  "$bin/trisim" metrics "$tmp/five.png" "$tmp/other.png"
expect 65 "at least 8 x 8 pixels (the window of --ssim-window 8x8)" \
  "$bin/trisim" metrics "$tmp/five.png" "$tmp/other.png" --ssim-window 8x8
expect 65 "$tmp/five.png (and the render of its size): too small for SSIM" \
  "$bin/trisim" compare "$src/tests/golden/grey.tri" --width 5 --height 5 --original "$tmp/five.png"

# -n as typed: a number past 2^63 is out of range (not clamped to 2^63 - 1), "010" is ten (not octal).
png=$tmp/five.png
expect 64 "--vertices: expected at least 4 vertices (the corners) and at most 16777216 (the pixels of the largest image encoded), found '99999999999999999999' (out of range)" \
  "$bin/triencode" "$png" -n 99999999999999999999 -o "$tmp/x.tri"
check "the clamped value is not echoed" bash -c "! grep -q 9223372036854775807 '$tmp/err'"
expect 64 "found '0x10' (not a decimal integer)" "$bin/triencode" "$png" -n 0x10 -o "$tmp/x.tri"
expect 0 "" "$bin/triencode" "$png" -n 010 -q -o "$tmp/x.tri"
check "-n 010 encodes 10 vertices" grep -qx "vertices 10" "$tmp/x.tri"
# The same for the other numbers whose CLI11 check misread or misprinted them: --max-bytes (an
# integer of 64 bits, read as octal with a leading zero) and --max-mse (printed DBL_MAX in full).
expect 64 "--max-bytes 10: expected at least" "$bin/triencode" "$png" --max-bytes 010 -o "$tmp/x.tri"
expect 64 "--max-bytes: expected a number of bytes from 1 to 1099511627776, found '99999999999999999999' (out of range)" \
  "$bin/triencode" "$png" --max-bytes 99999999999999999999 -o "$tmp/x.tri"
expect 64 "--max-mse: expected a finite number of at least 0, found '1e999'" \
  "$bin/trisim" metrics "$tmp/five.png" "$tmp/other.png" --max-mse 1e999
check "the --max-mse message does not print DBL_MAX in full" bash -c "! grep -q 17976931348623157 '$tmp/err'"
finish
