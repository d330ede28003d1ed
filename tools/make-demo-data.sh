#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the demo triangulations in data/demo from data/demo/kodim23.png with triencode
# (Kodak Lossless True Color Image Suite, free for any use). Deterministic: the same bytes
# every run. Usage: tools/make-demo-data.sh BIN_DIR
set -euo pipefail
bin=$(cd "${1:?usage: make-demo-data.sh BIN_DIR}" && pwd)
demo=$(cd "$(dirname "$0")/../data/demo" && pwd)
"$bin/triencode" "$demo/kodim23.png" --grey -n 4000 -o "$demo/kodim23.grey.tri"
"$bin/triencode" "$demo/kodim23.png" -n 4000 -o "$demo/kodim23.rgb.tri"
"$bin/triencode" "$demo/kodim23.png" --color separate --space ycbcr -n 2000 -o "$demo/kodim23.ycbcr-layers.tri"
