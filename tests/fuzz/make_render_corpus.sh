#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Remakes tests/fuzz/corpus/render: each .tri of tests/fuzz/corpus/tri packed by tripack for both
# core methods, behind a few 16-byte parameter headers (the layout is in fuzz_render.cpp). The
# regression inputs found by fuzzing (render_*.bin) stay.
# Usage: tests/fuzz/make_render_corpus.sh BIN_DIR
set -euo pipefail
bin=${1:?usage: make_render_corpus.sh BIN_DIR}
here=$(cd "$(dirname "$0")" && pwd)
out=$here/corpus/render
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
rm -f "$out"/*-bilinear-*.bin "$out"/*-zienkiewicz-*.bin  # what this script makes; render_*.bin are kept
# format|dither, tile w, tile h, flags, out w, out h, viewport x0 y0 x1 y1, tile delta, work delta, background, 3 spare
headers=(
  '\x01\x10\x10\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00'
  '\x83\x07\x05\x03\x24\x1c\x07\x06\x1e\x14\x00\x00\x40\x00\x00\x00'
  '\x00\x00\x00\x08\x00\x00\x00\x00\x00\x00\x00\x05\x00\x00\x00\x00'
  '\x04\x0d\x00\x04\x00\x00\x00\x00\x00\x00\xff\x00\x80\x00\x00\x00'
  '\x05\x09\x0b\x02\x00\x00\x00\x00\xf0\xf0\x00\x00\x00\x00\x00\x00'
  '\x02\x20\x08\x01\x00\x00\x00\x00\x00\x00\x00\x00\xff\x00\x00\x00'
)
for tri in "$here"/corpus/tri/*.tri; do
  name=$(basename "$tri" .tri)
  for method in bilinear zienkiewicz; do
    "$bin/tripack" "$tri" -m "$method" -o "$tmp/$name-$method.bin" >/dev/null
    for i in "${!headers[@]}"; do
      { printf "${headers[$i]}"; cat "$tmp/$name-$method.bin"; } >"$out/$name-$method-$i.bin"
    done
  done
done
ls "$out" | wc -l
