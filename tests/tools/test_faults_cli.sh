#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Faults a tool meets while writing (issue 44): a file-size limit (SIGXFSZ), output names at the
# file system's limit, and memory that runs out. Each must end with a message, the documented exit
# code and no temporary file left.
# Usage: test_faults_cli.sh BIN_DIR SOURCE_DIR [SANITIZER_FLAGS]
set -uo pipefail
bin=$1
src=$2
sanitized=${3:-}
source "$(dirname "$0")/cli_checks.sh"
tri=$src/data/demo/kodim23.rgb.tri

no_temporaries() {
  local left
  left=$(find "$tmp" -name '*.tmp.*' | head -3)
  if [ -n "$left" ]; then echo "FAIL: temporaries left: $left"; failures=$((failures + 1)); find "$tmp" -name '*.tmp.*' -delete
  else passes=$((passes + 1)); fi
}

# A file-size limit of 50 KiB: every tool's output is larger (a 103,808-byte blob, a 768 x 512 PNG,
# a 4,000-vertex .tri), so the write fails with EFBIG (73), not the signal (exit 153).
limited() { (ulimit -f 50; exec "$@"); }
expect 73 "File too large" limited "$bin/tripack" "$tri" -o "$tmp/blob.bin"
no_temporaries
expect 73 "File too large" limited "$bin/trisim" render "$tri" --method bilinear -o "$tmp/x.png"
no_temporaries
expect 73 "File too large" limited "$bin/triencode" "$src/data/demo/kodim23.png" -n 4000 -o "$tmp/x.tri"
no_temporaries
check "nothing written under the limit" test ! -e "$tmp/blob.bin" -a ! -e "$tmp/x.png" -a ! -e "$tmp/x.tri"

# Output names of 245 to 255 bytes (NAME_MAX): the temporary's name is cut to fit beside them.
for n in 245 251 255; do
  name=$(printf 'n%.0s' $(seq 1 $((n - 4)))).bin
  expect 0 "" "$bin/tripack" "$src/tests/golden/grey.tri" -o "$tmp/$name"
  check "a $n-byte output name is written" test -s "$tmp/$name"
  rm -f "$tmp/$name"
done
no_temporaries

# Memory that runs out: exit 71 and the step that needed it. A 5000 x 5000 reference render needs
# more than 500 MB; the process gets 300 MB of address space. Not under AddressSanitizer: it
# reserves terabytes of address space, and its operator new reports and aborts instead of
# throwing std::bad_alloc.
if [ -n "$sanitized" ]; then
  echo "skipped: out of memory under AddressSanitizer (its operator new aborts instead of throwing)"
else
  expect 71 "out of memory while rendering 5000 x 5000 pixels" \
    bash -c 'ulimit -v 300000; exec "$@"' oom "$bin/trisim" render "$tri" --method bilinear \
    --width 5000 --height 5000 -o "$tmp/big.png"
  no_temporaries
  check "no output after running out of memory" test ! -e "$tmp/big.png"
fi
finish
