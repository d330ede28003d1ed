#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# make experiments, make experiments-quick and make baselines build the tools alone (the target
# tristream_tools: trisim, tripack, triencode, tribaseline), never the whole tree with its tests: their
# recipes, as make -n prints them, build only that target.
# Usage: test_make_experiments.sh SOURCE_DIR
set -uo pipefail
src=$1
source "$(dirname "$0")/cli_checks.sh"
for target in experiments experiments-quick baselines; do
  make -n -C "$src" "$target" BUILD=/nonexistent/build JOBS=1 >"$tmp/$target" 2>&1
  check "make -n $target works" test $? -eq 0
  check "$target builds the target tristream_tools" \
    grep -q -- "cmake --build /nonexistent/build -j1 --target tristream_tools" "$tmp/$target"
  check "$target builds nothing else" \
    test "$(grep -c -- "cmake --build" "$tmp/$target")" -eq 1
done
finish
