#!/usr/bin/env bash
# Command-line contract of trisim: outputs, JSON keys, diagnostics and exit codes.
# Usage: test_trisim_cli.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$1
src=$2
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

tri=$tmp/rgb.tri
cat >"$tri" <<'TRI'
tri 1
size 24 16
channels rgb
vertices 5
0 0 0 10 200
23 0 255 30 20
23 15 128.5 50 60
0 15 3 70 80
11 7 90 250 0
TRI
cat >"$tmp/bad.tri" <<'TRI'
tri 1
size 10 10
channels grey
vertices 3
0 0 1
9 0 2
0 9 300
TRI

expect 0 "" "$bin/trisim" --help
expect 0 "" "$bin/trisim" render --help
expect 64 "" "$bin/trisim"
expect 64 "--method" "$bin/trisim" render "$tri" --method nosuch -o "$tmp/x.png"
expect 66 "cannot open" "$bin/trisim" render "$tmp/missing.tri" -o "$tmp/x.png"
expect 65 "bad.tri:7: expected a value" "$bin/trisim" render "$tmp/bad.tri" -o "$tmp/x.png"
expect 73 "cannot write" "$bin/trisim" render "$tri" -o "$tmp/no/such/dir/x.png"
expect 0 "" "$bin/trisim" render "$tri" --method zienkiewicz -o "$tmp/a.png"
[ -s "$tmp/a.png" ] && passes=$((passes + 1)) || { echo "FAIL: render wrote no PNG"; failures=$((failures + 1)); }
ls "$tmp" | grep -q '\.tmp\.' && { echo "FAIL: a temporary file was left behind"; failures=$((failures + 1)); }

expect 0 "" "$bin/trisim" compare "$tri" --method bilinear --original "$tmp/a.png" --json
for key in method engine mse psnr ssim ms; do
  grep -q "\"$key\":" "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: compare --json lacks '$key'"; failures=$((failures + 1)); }
done
expect 65 "expected an image of 20x20" "$bin/trisim" compare "$tri" --width 20 --height 20 --original "$tmp/a.png"
expect 0 "" "$bin/trisim" metrics "$tmp/a.png" "$tmp/a.png" --json
grep -q '"mse":0' "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: metrics of identical images: $(cat "$tmp/out")"; failures=$((failures + 1)); }
expect 66 "" "$bin/trisim" metrics "$tmp/a.png" "$tmp/missing.png"

for engine in reference core; do
  expect 0 "" "$bin/trisim" bench "$tri" --method zienkiewicz --engine "$engine" --runs 3 --json
  for key in ms_median ms_min cpu_ms_median mpix_per_s runs pixels; do
    grep -q "\"$key\":" "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: bench --json ($engine) lacks '$key'"; failures=$((failures + 1)); }
  done
done
grep -q '"ram_bytes":' "$tmp/out" && passes=$((passes + 1)) || { echo "FAIL: bench --engine core --json lacks 'ram_bytes'"; failures=$((failures + 1)); }
expect 64 "" "$bin/trisim" bench "$tri" --method coons --engine core

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
