#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Remakes tests/fuzz/corpus/compressed: each .tri of tests/fuzz/corpus/tri and the golden grey
# mesh compressed by tripack --compress for both core methods.
# Usage: tests/fuzz/make_compressed_corpus.sh BIN_DIR
set -euo pipefail
bin=${1:?usage: make_compressed_corpus.sh BIN_DIR}
here=$(cd "$(dirname "$0")" && pwd)
out=$here/corpus/compressed
rm -rf "$out"
mkdir -p "$out"
for tri in "$here"/corpus/tri/*.tri "$here"/../golden/grey.tri; do
  name=$(basename "$tri" .tri)
  for method in bilinear zienkiewicz; do
    "$bin/tripack" "$tri" -m "$method" --compress -o "$out/$name-$method.bin" >/dev/null
  done
done
ls "$out" | wc -l
