#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tristream_add_golden_test from an installed prefix (components core and tools), moved after the
# install (the package finds its trisim relative to itself): the target <name>_update writes the
# goldens, the CTest test passes, and fails with a diff image once a picture's settings change.
# Usage: check_golden.sh PREFIX WORK   (environment: BUILD_DIR, BLOB)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
prefix=${1:?usage: check_golden.sh PREFIX WORK}
work=${2:?}
rm -rf "$prefix" "$prefix.moved" "$work"
cmake --install "$BUILD_DIR" --prefix "$prefix" --component core >/dev/null
cmake --install "$BUILD_DIR" --prefix "$prefix" --component tools >/dev/null
mv "$prefix" "$prefix.moved"
mkdir -p "$work/src/pics"
cp "$here/golden_consumer/CMakeLists.txt" "$work/src/"
cp "$BLOB" "$work/src/pics/photo.bin"
echo '{"pictures": {"photo.bin": {"format": "rgb565le"}}}' >"$work/src/pics/golden.json"
cmake -S "$work/src" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix.moved" >"$work/configure.log" ||
  { cat "$work/configure.log"; exit 1; }
fail() { echo "check_golden: $*" >&2; exit 1; }
(cd "$work/build" && ctest >/dev/null) && fail "the test passed without goldens"
cmake --build "$work/build" --target pictures_golden_update >/dev/null
[ -f "$work/src/pics/photo.png" ] || fail "pictures_golden_update wrote no golden"
(cd "$work/build" && ctest --output-on-failure) || fail "the test failed on the goldens just written"
echo '{"pictures": {"photo.bin": {"format": "rgb565le", "dither": true}}}' >"$work/src/pics/golden.json"
(cd "$work/build" && ctest >"$work/ctest.log") && fail "the test passed after the picture's settings changed"
grep -q "photo: [0-9]* pixels changed" "$work/build/Testing/Temporary/LastTest.log" ||
  fail "the failing test did not name the picture"
[ -s "$work/build/pictures_golden-diff/photo.diff.png" ] || fail "no diff image in the build directory"
echo "check_golden: tristream_add_golden_test from a moved prefix: passes on its goldens, fails on a change"
