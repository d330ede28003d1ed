#!/usr/bin/env bash
# Bad input, faults and scale (issue 17) across trisim, tripack and triencode: limits checked
# before allocating, non-regular inputs, encoder outputs its reader accepts, lost stdout.
# Usage: test_bad_input_cli.sh BIN_DIR
set -uo pipefail
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0

# expect <code> <stderr-substring or ''> <command...>
expect() {
  local code=$1 needle=$2
  shift 2
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" -ne "$code" ] || { [ -n "$needle" ] && ! grep -qF -- "$needle" "$tmp/err"; }; then
    echo "FAIL: $* -> exit $got (expected $code), stderr: $(head -c 300 "$tmp/err")"
    failures=$((failures + 1))
  else
    passes=$((passes + 1))
  fi
}
check() {  # check <description> <command...>: passes when the command succeeds
  local what=$1
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $what"; failures=$((failures + 1)); fi
}

cat >"$tmp/huge.tri" <<'TRI'
tri 1
size 65535 65535
channels grey
vertices 3
0 0 0
65534 0 255
0 65534 128
TRI
cat >"$tmp/small.tri" <<'TRI'
tri 1
size 24 16
channels grey
vertices 4
0 0 0
23 0 255
0 15 128
23 15 60
TRI

# Item 6: limits checked before allocating, named in the message (65 from the data, 64 from options).
expect 65 "the limit for a render" "$bin/trisim" render "$tmp/huge.tri" -o "$tmp/x.png"
expect 65 "the limit for a render" "$bin/trisim" render "$tmp/huge.tri" --engine core -o "$tmp/x.png"
expect 65 "the limit for a render" "$bin/trisim" bench "$tmp/huge.tri" --engine core --runs 1
expect 0 "" "$bin/trisim" render "$tmp/huge.tri" --width 300 --height 300 -o "$tmp/x.png"
expect 64 "the limit for a render" "$bin/trisim" render "$tmp/small.tri" --width 65535 --height 65535 -o "$tmp/x.png"
expect 64 "the limit for a render" "$bin/trisim" compare "$tmp/small.tri" --width 65535 --height 65535 --original "$tmp/x.png"
# A PNG header that claims 30000 x 30000 pixels is refused before decoding.
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x75\x30\x00\x00\x75\x30\x08\x00\x00\x00\x00\x00\x00\x00\x00' >"$tmp/claims.png"
expect 65 "the limit for" "$bin/triencode" "$tmp/claims.png" -n 10 -o "$tmp/x.tri"
expect 65 "the limit for an image" "$bin/trisim" metrics "$tmp/claims.png" "$tmp/claims.png"
# Inputs that are not regular files: a device read without end, a directory, a FIFO without writer.
expect 66 "not a regular file" "$bin/tripack" /dev/zero -o "$tmp/x.bin"
expect 66 "directory" "$bin/tripack" "$tmp" -o "$tmp/x.bin"
mkfifo "$tmp/fifo"
expect 66 "not a regular file" timeout 20 "$bin/tripack" "$tmp/fifo" -o "$tmp/x.bin"
expect 66 "not a regular file" timeout 20 "$bin/triencode" "$tmp/fifo" -n 10 -o "$tmp/x.tri"

# Item 8: the encoder refuses an image whose .tri its own reader would refuse.
{ printf 'P5\n70000 2\n255\n'; head -c 140000 /dev/zero; } >"$tmp/wide.pgm"
expect 65 "at most 65535 pixels a side" "$bin/triencode" "$tmp/wide.pgm" -n 10 -o "$tmp/wide.tri"
check "triencode left a .tri for an image it refused" test ! -e "$tmp/wide.tri"

# Item 9: results that cannot be written to stdout are exit 74; JSON holds names that are not UTF-8.
expect 0 "" "$bin/trisim" render "$tmp/small.tri" -o "$tmp/small.png"
expect_stdout() {  # expect_stdout <code> <redirection: full|closed> <command...>
  local code=$1 how=$2 got
  shift 2
  if [ "$how" = full ]; then "$@" >/dev/full 2>"$tmp/err"; else "$@" >&- 2>"$tmp/err"; fi
  got=$?
  if [ "$got" -eq "$code" ] && grep -qF "stdout" "$tmp/err"; then passes=$((passes + 1)); else
    echo "FAIL: $* >$how -> exit $got (expected $code), stderr: $(head -c 300 "$tmp/err")"
    failures=$((failures + 1))
  fi
}
for how in full closed; do
  expect_stdout 74 $how "$bin/trisim" metrics "$tmp/small.png" "$tmp/small.png"
  expect_stdout 74 $how "$bin/trisim" metrics "$tmp/small.png" "$tmp/small.png" --json
  expect_stdout 74 $how "$bin/trisim" compare "$tmp/small.tri" --original "$tmp/small.png" --json
  expect_stdout 74 $how "$bin/tripack" "$tmp/small.tri" -o "$tmp/small.bin"
  expect_stdout 74 $how "$bin/triencode" "$tmp/small.png" -n 8 -q -o "$tmp/enc.tri"
done
weird=$(printf '%s/n\xff\xfe.tri' "$tmp")
expect 0 "" "$bin/triencode" "$tmp/small.png" -n 8 -q --json -o "$weird"
check "triencode did not write the file with a non-UTF-8 name" test -s "$weird"
check "triencode --json with a non-UTF-8 name is not valid JSON naming it" \
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["output"].endswith("n\\xFF\\xFE.tri"), j' "$tmp/out"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
