#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# trisim render|compare|bench of a blob (tripack's output) as well as a .tri: the core draws the
# blob's own bytes (the same pixels as the .tri packed for that method), compare measures it
# against the reference of the mesh read back and against an original, bad blobs exit 65 naming
# the byte (a damaged v1 blob: its checksum at byte 36; one of version 1, from before the checksum:
# what to do; a file with bytes after its blob: where the blob ends). A compressed blob (tripack
# --compress) is expanded by the core and then draws the v1 blob's pixels; a damaged one exits 65
# with the byte offset the decoder reports.
# Usage: test_trisim_blob.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
source "$(dirname "$0")/cli_checks.sh"

# Positions on pixels and values in q8_8, so the blob holds this mesh exactly.
tri=$tmp/rgb.tri
cat >"$tri" <<'TRI'
tri 1
size 24 16
channels rgb
vertices 6
0 0 0 10 200
23 0 255 30 20
23 15 128.5 50 60
0 15 3 70 80
11 7 90 250 0
5 12 40 41 42
TRI
demo=$src/data/demo

same() {  # same <description> <file> <file>
  if cmp -s "$2" "$3"; then passes=$((passes + 1)); else echo "FAIL: $1 ($2 and $3 differ)"; failures=$((failures + 1)); fi
}

for m in bilinear zienkiewicz; do
  expect 0 "" "$bin/tripack" "$tri" -m $m -o "$tmp/$m.bin"
  # render: the blob's method by default, the core by default, any format and tiling.
  expect 0 "with $m (core)" "$bin/trisim" render "$tmp/$m.bin" -o "$tmp/blob-$m.png"
  expect 0 "" "$bin/trisim" render "$tri" --engine core --method $m -o "$tmp/tri-$m.png"
  same "render of the $m blob = core render of the .tri" "$tmp/blob-$m.png" "$tmp/tri-$m.png"
  expect 0 "" "$bin/trisim" render "$tmp/$m.bin" --format rgb565be --tile 5 --dither --raw -o "$tmp/blob-$m.raw"
  expect 0 "" "$bin/trisim" render "$tri" --engine core --method $m --format rgb565be --tile 5 --dither --raw \
    -o "$tmp/tri-$m.raw"
  same "raw RGB565 frame of the $m blob" "$tmp/blob-$m.raw" "$tmp/tri-$m.raw"
  # --engine reference renders the mesh read back: here exactly the .tri's.
  expect 0 "" "$bin/trisim" render "$tmp/$m.bin" --engine reference --method clough-tocher -o "$tmp/blob-ref.png"
  expect 0 "" "$bin/trisim" render "$tri" --method clough-tocher -o "$tmp/tri-ref.png"
  same "reference render of the $m blob's mesh" "$tmp/blob-ref.png" "$tmp/tri-ref.png"
done
expect 64 "packed for zienkiewicz" "$bin/trisim" render "$tmp/zienkiewicz.bin" --method bilinear -o "$tmp/x.png"
expect 64 "applies to --engine core only" "$bin/trisim" render "$tmp/bilinear.bin" --engine reference --tile 8 \
  -o "$tmp/x.png"
# The extension does not matter, the bytes do.
cp "$tmp/bilinear.bin" "$tmp/looks-like.tri"
expect 0 "" "$bin/trisim" render "$tmp/looks-like.tri" -o "$tmp/x.png"
same "a blob named .tri is read as a blob" "$tmp/x.png" "$tmp/blob-bilinear.png"

# compare: the core's render against the reference, with or without an original.
expect 0 "" "$bin/trisim" compare "$tmp/zienkiewicz.bin" --json
grep -q '"method":"zienkiewicz"' "$tmp/out" && grep -q '"engine":"core"' "$tmp/out" &&
  grep -q '"max_abs_diff_vs_reference":[0-9]' "$tmp/out" && grep -q '"mse":null' "$tmp/out" &&
  passes=$((passes + 1)) || { echo "FAIL: compare of a blob without original: $(cat "$tmp/out")"; failures=$((failures + 1)); }
expect 0 "" "$bin/trisim" compare "$tmp/zienkiewicz.bin" --original "$tmp/tri-ref.png" --json
sed 's/"ms":[0-9.e+-]*,//' "$tmp/out" >"$tmp/blob.json"
expect 0 "" "$bin/trisim" compare "$tri" --engine core --method zienkiewicz --original "$tmp/tri-ref.png" --json
sed 's/"ms":[0-9.e+-]*,//' "$tmp/out" >"$tmp/tri.json"
same "compare of the blob = compare of the .tri with the core" "$tmp/blob.json" "$tmp/tri.json"
expect 0 "" "$bin/trisim" compare "$tmp/bilinear.bin" --engine reference -m bilinear natural --original "$tmp/tri-ref.png"
expect 64 "--original: required" "$bin/trisim" compare "$tmp/bilinear.bin" --engine reference
expect 64 "--original: required" "$bin/trisim" compare "$tri"
# A layered YCbCr blob and a grey one, against the demo original.
expect 0 "" "$bin/tripack" "$demo/kodim23.ycbcr-layers.tri" -o "$tmp/layers.bin"
expect 0 "" "$bin/trisim" compare "$tmp/layers.bin" --original "$demo/kodim23.png" --json
grep -q '"psnr":[0-9]' "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: layered blob compare: $(cat "$tmp/out")"; failures=$((failures + 1)); }
expect 0 "" "$bin/tripack" "$demo/kodim23.grey.tri" -o "$tmp/grey.bin"
# The reference of the mesh read back may round a few pixels differently from the .tri's (the
# blob lists each triangle from its top vertex), so only the measures against the original are compared.
strip='s/"ms":[0-9.e+-]*,//; s/"psnr_vs_reference":[0-9.e+-]*,//'
expect 0 "" "$bin/trisim" compare "$tmp/grey.bin" --original "$demo/kodim23.png" --format rgb565le --json
sed "$strip" "$tmp/out" >"$tmp/blob.json"
expect 0 "" "$bin/trisim" compare "$demo/kodim23.grey.tri" --engine core --original "$demo/kodim23.png" --format rgb565le --json
sed "$strip" "$tmp/out" >"$tmp/tri.json"
same "grey blob compare in RGB565 = the .tri's" "$tmp/blob.json" "$tmp/tri.json"

# bench: the blob's bytes with the core, its mesh with the reference.
for engine in core reference; do
  expect 0 "" "$bin/trisim" bench "$tmp/zienkiewicz.bin" --engine $engine --runs 2 --json
  grep -q '"pixels":384' "$tmp/out" && grep -q "\"method\":\"zienkiewicz\"" "$tmp/out" && passes=$((passes + 1)) ||
    { echo "FAIL: bench of a blob ($engine): $(cat "$tmp/out")"; failures=$((failures + 1)); }
done
grep -q '"ram_bytes":' "$tmp/out" && { echo "FAIL: bench --engine reference reports RAM"; failures=$((failures + 1)); }

# Compressed blobs: render (any format, tiling, engine), compare and bench as the v1 blob.
for m in bilinear zienkiewicz; do
  expect 0 "" "$bin/tripack" "$tri" -m $m --compress -o "$tmp/$m-c.bin"
  check "tripack --compress writes TSTC" test "$(head -c 4 "$tmp/$m-c.bin")" = TSTC
  expect 0 "" "$bin/trisim" render "$tmp/$m-c.bin" -o "$tmp/tstc-$m.png"
  same "render of the compressed $m blob = the v1 blob's" "$tmp/tstc-$m.png" "$tmp/blob-$m.png"
  same "render of the compressed $m blob = core render of the .tri" "$tmp/tstc-$m.png" "$tmp/tri-$m.png"
  expect 0 "" "$bin/trisim" render "$tmp/$m-c.bin" --format rgb565be --tile 5 --dither --raw -o "$tmp/tstc-$m.raw"
  same "raw RGB565 frame of the compressed $m blob" "$tmp/tstc-$m.raw" "$tmp/tri-$m.raw"
  expect 0 "" "$bin/trisim" render "$tmp/$m-c.bin" --engine reference --method clough-tocher -o "$tmp/tstc-ref.png"
  same "reference render of the compressed $m blob's mesh" "$tmp/tstc-ref.png" "$tmp/tri-ref.png"
done
expect 64 "packed for zienkiewicz" "$bin/trisim" render "$tmp/zienkiewicz-c.bin" --method bilinear -o "$tmp/x.png"
expect 0 "" "$bin/tripack" "$demo/kodim23.grey.tri" --compress -o "$tmp/grey-c.bin"
for engine in core reference; do
  expect 0 "" "$bin/trisim" compare "$tmp/grey.bin" --engine $engine --original "$demo/kodim23.png" --json
  sed 's/"ms":[0-9.e+-]*,//' "$tmp/out" >"$tmp/blob.json"
  expect 0 "" "$bin/trisim" compare "$tmp/grey-c.bin" --engine $engine --original "$demo/kodim23.png" --json
  sed 's/"ms":[0-9.e+-]*,//' "$tmp/out" >"$tmp/tstc.json"
  same "compare of the compressed grey blob = the v1 blob's ($engine)" "$tmp/tstc.json" "$tmp/blob.json"
done
expect 0 "" "$bin/trisim" bench "$tmp/grey-c.bin" --runs 2 --json
grep -q '"pixels":393216' "$tmp/out" && grep -q '"v1_ms_median":[0-9]' "$tmp/out" && grep -q '"cpu_ratio_to_v1":[0-9]' "$tmp/out" && passes=$((passes + 1)) ||
  { echo "FAIL: bench of a compressed blob: $(cat "$tmp/out")"; failures=$((failures + 1)); }

# Bad blobs: exit 65, the file and the byte offset open_blob reports.
poke() {  # poke <file> <offset> <octal byte>
  printf "\\$3" | dd of="$1" bs=1 seek="$2" conv=notrunc status=none
}
rm -f "$tmp/x.png"
cp "$tmp/bilinear.bin" "$tmp/version.bin"
poke "$tmp/version.bin" 4 011
head -c 100 "$tmp/bilinear.bin" >"$tmp/short.bin"
printf 'TSTB' >"$tmp/magic-only.bin"
for cmd in render compare bench; do
  out=(-o "$tmp/x.png")
  [ $cmd = render ] || out=()
  expect 65 "version.bin: byte 4: unsupported blob version" "$bin/trisim" $cmd "$tmp/version.bin" "${out[@]}"
  expect 65 "short.bin: byte 8: blob truncated" "$bin/trisim" $cmd "$tmp/short.bin" "${out[@]}"
  expect 65 "magic-only.bin: byte 4: blob truncated" "$bin/trisim" $cmd "$tmp/magic-only.bin" "${out[@]}"
  expect 65 "version1-grey-bilinear.bin: byte 4: version 1 blob without checksum: pack it again with tripack" \
    "$bin/trisim" $cmd "$src/tests/core/version1-grey-bilinear.bin" "${out[@]}"
done
# One bit flipped anywhere past the header's size fields: the checksum at byte 36, with the CRC-32 the
# header records and the one the bytes have, as zlib computes it over bytes 0..35 and 40..end.
size=$(wc -c <"$tmp/grey.bin")
for at in 12 35 40 63 64 1000 $((size - 1)); do
  cp "$tmp/grey.bin" "$tmp/flip.bin"
  python3 -c 'import sys; p, at = sys.argv[1], int(sys.argv[2]); b = bytearray(open(p, "rb").read()); b[at] ^= 0x10; open(p, "wb").write(b)' \
    "$tmp/flip.bin" $at
  crcs=$(python3 -c 'import sys, zlib; b = open(sys.argv[1], "rb").read()
print("the header records CRC-32 0x%08X, bytes 0..%d have 0x%08X" % (int.from_bytes(b[36:40], "little"), len(b) - 1, zlib.crc32(b[:36] + b[40:])))' \
    "$tmp/flip.bin")
  for cmd in render compare bench; do
    out=(-o "$tmp/x.png")
    [ $cmd = render ] || out=()
    expect 65 "flip.bin: byte 36: checksum mismatch: the blob is damaged ($crcs)" "$bin/trisim" $cmd "$tmp/flip.bin" "${out[@]}"
  done
done
# Damaged compressed blobs: the header's offset, or the offset where the decoder stood when a
# check failed: never before the damaged byte (it has to be read first), never past the end.
cp "$tmp/grey-c.bin" "$tmp/version-c.bin"
poke "$tmp/version-c.bin" 4 011
head -c 60 "$tmp/grey-c.bin" >"$tmp/short-c.bin"
head -c 5000 "$tmp/grey-c.bin" >"$tmp/cut-c.bin"
for cmd in render compare bench; do
  out=(-o "$tmp/x.png")
  [ $cmd = render ] || out=()
  expect 65 "version-c.bin: byte 4: unsupported blob version" "$bin/trisim" $cmd "$tmp/version-c.bin" "${out[@]}"
  expect 65 "short-c.bin: byte 60: blob truncated" "$bin/trisim" $cmd "$tmp/short-c.bin" "${out[@]}"
  expect 65 "cut-c.bin: byte 8: blob truncated" "$bin/trisim" $cmd "$tmp/cut-c.bin" "${out[@]}"
done
for at in 100 1000 5000 $(($(wc -c <"$tmp/grey-c.bin") - 100)); do
  cp "$tmp/grey-c.bin" "$tmp/flip-c.bin"
  poke "$tmp/flip-c.bin" $at 125
  expect 65 "flip-c.bin: byte " "$bin/trisim" render "$tmp/flip-c.bin" -o "$tmp/x.png"
  offset=$(sed -n 's/.*flip-c\.bin: byte \([0-9]*\):.*/\1/p' "$tmp/err")
  check "damage at $at reported at byte $offset, from $at to the end" \
    test -n "$offset" -a "${offset:-0}" -ge "$at" -a "${offset:-0}" -le "$(wc -c <"$tmp/grey-c.bin")"
done

# A blob file with bytes after the blob (its total size, at byte 8): refused, naming where the
# blob ends and the file's length, for a v1 and a compressed blob. The core itself ignores them
# (a blob in a larger flash section; docs/FORMAT.md).
for blob in grey grey-c; do
  size=$(wc -c <"$tmp/$blob.bin")
  { cat "$tmp/$blob.bin"; printf '\377\377\377\377\377\377\377\377'; } >"$tmp/padded.bin"
  for cmd in render compare bench; do
    out=(-o "$tmp/x.png")
    [ $cmd = render ] || out=()
    expect 65 "padded.bin: byte $size: expected the end of the file, where the blob ends (its total size at byte 8), found 8 bytes more (a file of $((size + 8)) bytes)" \
      "$bin/trisim" $cmd "$tmp/padded.bin" "${out[@]}"
  done
  expect 65 "padded.bin: byte $size: expected the end of the file" \
    "$bin/trisim" render "$tmp/padded.bin" --engine reference -o "$tmp/x.png"
  head -c "$size" "$tmp/padded.bin" >"$tmp/cut.bin"
  expect 0 "" "$bin/trisim" render "$tmp/cut.bin" -o "$tmp/cut.png"
  rm -f "$tmp/x.png" "$tmp/cut.png"
done

# A vertex pushed outside the domain (the first x of the positions, which follow the 64-byte
# header and the 32-byte layer entry): a checksum mismatch, and with the checksum written again
# (zlib's CRC-32), the vertex.
cp "$tmp/bilinear.bin" "$tmp/outside.bin"
poke "$tmp/outside.bin" 97 377
expect 65 "outside.bin: byte 36: checksum mismatch" "$bin/trisim" compare "$tmp/outside.bin"
python3 -c 'import sys, zlib; p = sys.argv[1]; b = bytearray(open(p, "rb").read()); b[36:40] = zlib.crc32(b[:36] + b[40:]).to_bytes(4, "little"); open(p, "wb").write(b)' \
  "$tmp/outside.bin"
expect 65 "outside.bin: byte 96: vertex outside the domain" "$bin/trisim" compare "$tmp/outside.bin"
[ -e "$tmp/x.png" ] && { echo "FAIL: a bad blob left an output"; failures=$((failures + 1)); }

finish
