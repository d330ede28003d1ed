#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# trisim golden DIR [--update] (docs/GOLDEN.md): exit 0 when every render equals its golden, 1 with
# each name, changed-pixel count, largest difference and a diff image when any differs; tolerances;
# the manifest's errors; goldens never written without --update, and an update that fails or is
# interrupted leaves every old golden as it was.
# Usage: test_trisim_golden.sh BIN_DIR SOURCE_DIR
set -uo pipefail
bin=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
source "$(dirname "$0")/cli_checks.sh"
trisim=$bin/trisim
golden=$src/tests/golden
cd "$tmp"  # diff images without --diff-dir go to the current directory

d=$tmp/pics
mkdir -p "$d"
cp "$golden/rgb-zienkiewicz.bin" "$d/photo.bin"
cp "$golden/grey.tri" "$d/grey.tri"
cp "$golden/ycbcr-layers-bilinear.bin" "$d/logo.bin"
echo "not a picture" >"$d/README"
cat >"$d/golden.json" <<'JSON'
{
  "defaults": {"background": [255, 0, 0]},
  "pictures": {
    "photo.bin": {"format": "rgb565le", "dither": true, "width": 240, "height": 240, "fit": "inside"},
    "grey.tri": {"engine": "core", "method": "zienkiewicz", "tile-width": 0, "tile-height": 8},
    "logo.bin": {"viewport": [10, 10, 100, 60]}
  }
}
JSON

# No golden yet: exit 1 naming each picture; nothing is written without --update.
expect 1 "" "$trisim" golden "$d" --diff-dir "$tmp/diffs"
check "missing goldens are named" grep -q "^grey: no golden" "$tmp/out"
check "no golden written without --update" bash -c "! ls '$d'/*.png 2>/dev/null"
expect 0 "" "$trisim" golden "$d" --update
check "--update writes the three goldens" test -f "$d/photo.png" -a -f "$d/grey.png" -a -f "$d/logo.png"
expect 0 "" "$trisim" golden "$d"
check "identical: all counted" grep -q "3 identical" "$tmp/out"

# The goldens are what trisim render writes with the same settings.
expect 0 "" "$trisim" render "$d/photo.bin" --format rgb565le --dither --width 240 --height 240 --fit inside \
  --background 255,0,0 -o "$tmp/photo.png"
check "photo.png equals trisim render's" cmp -s "$tmp/photo.png" "$d/photo.png"
expect 0 "" "$trisim" render "$d/logo.bin" --viewport 10,10,100,60 --background 255,0,0 -o "$tmp/logo.png"
check "logo.png equals trisim render's" cmp -s "$tmp/logo.png" "$d/logo.png"

# A changed golden: exit 1, its name, counts and a diff image; the golden stays as it is.
expect 0 "" "$trisim" render "$d/grey.tri" --engine core --method bilinear -o "$d/grey.png"
cp "$d/grey.png" "$tmp/grey.before"
expect 1 "" "$trisim" golden "$d" --diff-dir "$tmp/diffs"
check "the differing picture is named with its counts" \
  grep -qE "^grey: [0-9]+ pixels changed, largest difference [0-9]+, MSE [0-9.]+, diff $tmp/diffs/grey.diff.png$" "$tmp/out"
check "only grey differs" grep -q "2 identical, 0 within tolerance, 1 differ" "$tmp/out"
check "the diff image is written" test -s "$tmp/diffs/grey.diff.png"
check "the golden is not rewritten without --update" cmp -s "$d/grey.png" "$tmp/grey.before"
# The diff image: the render's size, RGB; every changed pixel red (255, 0, 0), the others grey.
expect 0 "" "$trisim" metrics "$tmp/diffs/grey.diff.png" "$d/grey.png"  # fails unless of equal size
changed=$(grep -oE "^grey: [0-9]+" <("$trisim" golden "$d" --diff-dir "$tmp/diffs") | cut -d' ' -f2)
check "changed-pixel count is positive" test "${changed:-0}" -gt 0

# Tolerances: max-changed-pixels and max-mse, each alone and each too small.
cp "$d/golden.json" "$tmp/manifest"
set_grey() {
  sed "s|\"grey.tri\": {|\"grey.tri\": {$1, |" "$tmp/manifest" >"$d/golden.json"
}
set_grey "\"max-changed-pixels\": $changed"
expect 0 "" "$trisim" golden "$d"
check "within max-changed-pixels" grep -q "^grey: .*(within its tolerance)" "$tmp/out"
set_grey "\"max-changed-pixels\": $((changed - 1))"
expect 1 "" "$trisim" golden "$d"
set_grey '"max-mse": 1000'
expect 0 "" "$trisim" golden "$d"
set_grey '"max-mse": 0.5'
expect 1 "" "$trisim" golden "$d"
cp "$tmp/manifest" "$d/golden.json"

# The manifest's errors are bad data (65), named with the file and the setting.
printf '{"pictures": {"photo.bin": {"format": "rgb555"}}}' >"$d/golden.json"
expect 65 "golden.json: \"pictures\": \"photo.bin\": \"format\": expected one of" "$trisim" golden "$d"
printf '{"pictures": {"photo.bin": {"colour": 1}}}' >"$d/golden.json"
expect 65 "unknown setting \"colour\"" "$trisim" golden "$d"
printf '{"pictures": {"missing.bin": {}}}' >"$d/golden.json"
expect 65 "\"missing.bin\": expected a .tri or blob file" "$trisim" golden "$d"
printf '{"pictures": {"grey.tri": {"tile": 8}}}' >"$d/golden.json"
expect 65 "grey.tri: --tile: applies to --engine core only" "$trisim" golden "$d"
printf '{"pictures": ' >"$d/golden.json"
expect 65 "golden.json: byte 14: expected JSON" "$trisim" golden "$d"
cp "$tmp/manifest" "$d/golden.json"
cp "$golden/grey-bilinear.bin" "$d/grey.bin"
expect 65 "would share the golden grey.png" "$trisim" golden "$d"
rm "$d/grey.bin"
cp "$d/grey.png" "$tmp/grey.saved"
echo "not a PNG" >"$d/grey.png"
expect 65 "grey.png" "$trisim" golden "$d"
expect 0 "" "$trisim" golden "$d" --update
check "--update replaces a golden that is not a PNG" grep -q "updated $d/grey.png" "$tmp/out"
cp "$tmp/grey.saved" "$d/grey.png"
expect 66 "found none" "$trisim" golden "$tmp/diffs"
expect 66 "cannot read the directory" "$trisim" golden "$tmp/nosuch"

# An update that cannot write one golden writes none: logo.png is a link to a missing file, so
# its temporary file cannot be made after those of grey.png and photo.png (name order).
cp "$d/photo.png" "$tmp/photo.before"
rm "$d/logo.png"
ln -s "$tmp/nosuch/logo.png" "$d/logo.png"
sed 's|"dither": true, ||' "$tmp/manifest" >"$d/golden.json"  # photo.png changes too
expect 73 "logo.png: cannot write" "$trisim" golden "$d" --update
check "failed update: grey.png is the old golden" cmp -s "$d/grey.png" "$tmp/grey.before"
check "failed update: photo.png is the old golden" cmp -s "$d/photo.png" "$tmp/photo.before"
check "failed update: no temporary file left" bash -c "! ls -a '$d' | grep -q '\\.tmp\\.'"
rm "$d/logo.png"
expect 0 "" "$trisim" golden "$d" --update
check "update after the failure" grep -q "3 goldens written" "$tmp/out"
expect 0 "" "$trisim" golden "$d"

# An update killed (SIGTERM) while its temporary files are being written leaves either every old
# golden (killed before the renames) or every new one (the renames hold the signal back), never a
# mix, and no temporary file. The kill comes as soon as the second golden's temporary file exists.
k=$tmp/kill
mkdir -p "$k" "$tmp/old" "$tmp/new"
names="a b c d e f g h"  # the writes of c to h and the renames are the window for the kill
for n in $names; do cp "$golden/rgb-zienkiewicz.bin" "$k/$n.bin"; done
manifest() { printf '{"defaults": {"width": 640, "height": 640, "fit": "inside", "background": %d}}' "$1" >"$k/golden.json"; }
manifest 2
expect 0 "" "$trisim" golden "$k" --update
cp "$k"/*.png "$tmp/new/"
manifest 1
expect 0 "" "$trisim" golden "$k" --update
cp "$k"/*.png "$tmp/old/"
manifest 2
caught=0
for attempt in 1 2 3 4 5; do
  "$trisim" golden "$k" --update >/dev/null 2>&1 &
  pid=$!
  while kill -0 "$pid" 2>/dev/null && ! compgen -G "$k/b.png.tmp.*" >/dev/null; do :; done  # builtins only: a tight poll
  kill -TERM "$pid" 2>/dev/null
  wait "$pid"
  code=$?
  old=0 new=0
  for n in $names; do
    cmp -s "$k/$n.png" "$tmp/old/$n.png" && old=$((old + 1))
    cmp -s "$k/$n.png" "$tmp/new/$n.png" && new=$((new + 1))
  done
  check "killed update (attempt $attempt, exit $code): all old ($old of 8) or all new ($new of 8)" \
    test "$old" -eq 8 -o "$new" -eq 8
  check "killed update (attempt $attempt): no temporary file left" bash -c "! ls -a '$k' | grep -q '\\.tmp\\.'"
  cp "$tmp/old"/*.png "$k/"
  [ "$code" -eq 143 ] && { caught=1; echo "killed during the update: $old old, $new new"; break; }
done
check "a kill landed during the update (exit 143) in some attempt" test "$caught" -eq 1

finish
