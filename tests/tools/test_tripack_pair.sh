#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tripack -o x.c writes x.h and x.c as one unit (issue 44): when the second file cannot be written
# (a file-size limit, a rename that fails) the old pair stays byte for byte, or no file appears
# where there was none; two runs writing the same pair at once leave one run's pair, never the
# header of one beside the source of the other; and x.c refuses to compile beside a header that is
# not its own. Usage: test_tripack_pair.sh TRIPACK CC INCLUDE_DIR FAIL_RENAME_LIB SOURCE_DIR
# (FAIL_RENAME_LIB: fail_rename.c built as a shared library, loaded with LD_PRELOAD)
set -uo pipefail
tripack=$1
cc=$2
include=$3
shim=$4
src=$5
source "$(dirname "$0")/cli_checks.sh"
small=$src/tests/golden/grey.tri
large=$src/data/demo/kodim23.rgb.tri
cflags=(-std=c99 -Wall -Wextra -pedantic -Werror -I"$include")
# AddressSanitizer wants its runtime first among the libraries; the preloaded shim comes before it.
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0

# Nothing but the pair is left in $1: no temporary, no kept old header.
only_pair() {
  local left
  left=$(find "$1" -name '*.tmp.*' -o -name '*.old.*' | head -3)
  if [ -n "$left" ]; then echo "FAIL: files left beside the pair: $left"; failures=$((failures + 1)); find "$1" \( -name '*.tmp.*' -o -name '*.old.*' \) -delete
  else passes=$((passes + 1)); fi
}
# The pair in $1 is the saved one, byte for byte.
unchanged() {
  check "$2: x.h is the old header" cmp -s "$1/x.h" "$tmp/saved.h"
  check "$2: x.c is the old source" cmp -s "$1/x.c" "$tmp/saved.c"
}
# An old pair (from the small triangulation) in a fresh directory $1, saved for comparison.
old_pair() {
  rm -rf "$1"
  mkdir -p "$1"
  "$tripack" "$small" -o "$1/x.c" >/dev/null || { echo "FAIL: tripack $small"; failures=$((failures + 1)); }
  cp "$1/x.h" "$tmp/saved.h"
  cp "$1/x.c" "$tmp/saved.c"
}

# A file-size limit of 50 KiB: the new header (2 KB) fits, the new source (600 KB) does not.
for form in "" --compress; do
  old_pair "$tmp/limit"
  expect 73 "File too large" bash -c 'ulimit -f 50; exec "$@"' limited "$tripack" "$large" -o "$tmp/limit/x.c" $form
  unchanged "$tmp/limit" "a size limit at the source $form"
  only_pair "$tmp/limit"
done

# The rename of the source fails (the second rename): the old header is put back.
old_pair "$tmp/rename"
expect 73 "x.h is as it was" env LD_PRELOAD="$shim" TS_FAIL_RENAME=2 "$tripack" "$large" -o "$tmp/rename/x.c"
unchanged "$tmp/rename" "the source's rename failed"
only_pair "$tmp/rename"
# The same where hard links cannot be made: the old header is kept in memory and written back.
expect 73 "x.h is as it was" env LD_PRELOAD="$shim" TS_FAIL_RENAME=2 TS_FAIL_LINK=1 "$tripack" "$large" -o "$tmp/rename/x.c"
unchanged "$tmp/rename" "the source's rename failed, no hard links"
only_pair "$tmp/rename"
# The header's rename fails (the first): nothing changed.
expect 73 "cannot rename" env LD_PRELOAD="$shim" TS_FAIL_RENAME=1 "$tripack" "$large" -o "$tmp/rename/x.c"
unchanged "$tmp/rename" "the header's rename failed"
only_pair "$tmp/rename"
# No pair before: a failed second rename leaves none.
mkdir -p "$tmp/new"
expect 73 "x.h is as it was" env LD_PRELOAD="$shim" TS_FAIL_RENAME=2 "$tripack" "$large" -o "$tmp/new/x.c"
check "no pair after a failed first write" test ! -e "$tmp/new/x.h" -a ! -e "$tmp/new/x.c"
only_pair "$tmp/new"
# Without a fault the shim changes nothing: the pair is written.
expect 0 "" env LD_PRELOAD="$shim" TS_FAIL_LINK=1 "$tripack" "$large" -o "$tmp/new/x.c"
check "the pair is written through the shim" test -s "$tmp/new/x.h" -a -s "$tmp/new/x.c"

# Two runs writing the same pair at once, 20 rounds: one run's pair each time. The runs pack the
# same triangulation under two names, so that they take the same time and meet; each file's first
# line names its input. Checked by those lines, not by the source's own check, then by that too.
cp "$large" "$tmp/one.tri"
cp "$large" "$tmp/two.tri"
mixed=0
for round in $(seq 1 20); do
  d=$tmp/race
  rm -rf "$d"
  mkdir -p "$d"
  "$tripack" "$tmp/one.tri" -o "$d/p.c" >/dev/null 2>&1 &
  a=$!
  "$tripack" "$tmp/two.tri" -o "$d/p.c" >/dev/null 2>&1 &
  b=$!
  wait $a; ca=$?
  wait $b; cb=$?
  [ $ca -eq 0 ] && [ $cb -eq 0 ] || { echo "FAIL: round $round: tripack exited $ca and $cb"; failures=$((failures + 1)); continue; }
  [ "$(head -1 "$d/p.h")" = "$(head -1 "$d/p.c")" ] || mixed=$((mixed + 1))
  if ! "$cc" "${cflags[@]}" -c "$d/p.c" -o "$d/p.o" 2>"$d/err"; then
    echo "FAIL: round $round: p.c does not compile beside p.h: $(head -c 300 "$d/err")"; failures=$((failures + 1))
  fi
  only_pair "$d"
done
check "concurrent runs: $mixed of 20 rounds left a header of one blob beside the source of the other" test $mixed -eq 0

# A stale pair fails to compile: the header of another blob, or of the same blob packed with
# other options, or one from before the pair hash.
mkdir -p "$tmp/stale" "$tmp/other"
"$tripack" "$small" -o "$tmp/stale/x.c" >/dev/null
for other in "$large" "$small --tile 16" "$small --compress"; do
  "$tripack" $other -o "$tmp/other/x.c" >/dev/null
  cp "$tmp/stale/x.h" "$tmp/own.h"
  cp "$tmp/other/x.h" "$tmp/stale/x.h"
  if "$cc" "${cflags[@]}" -c "$tmp/stale/x.c" -o "$tmp/stale/x.o" 2>"$tmp/err"; then
    echo "FAIL: x.c compiled beside the x.h of $other"; failures=$((failures + 1))
  elif ! grep -q "x.h is not the header tripack wrote with this source" "$tmp/err"; then
    echo "FAIL: x.c beside the x.h of $other: $(head -c 300 "$tmp/err")"; failures=$((failures + 1))
  else passes=$((passes + 1)); fi
  cp "$tmp/own.h" "$tmp/stale/x.h"
done
grep -v '_PAIR_HASH 0x' "$tmp/own.h" >"$tmp/stale/x.h"
expect 1 "x.h is not the header tripack wrote" "$cc" "${cflags[@]}" -c "$tmp/stale/x.c" -o "$tmp/stale/x.o"
cp "$tmp/own.h" "$tmp/stale/x.h"
expect 0 "" "$cc" "${cflags[@]}" -c "$tmp/stale/x.c" -o "$tmp/stale/x.o"
finish
