#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Bad input, faults and scale (issue 17) across trisim, tripack and triencode: limits checked
# before allocating, non-regular inputs, encoder outputs its reader accepts, lost stdout.
# Usage: test_bad_input_cli.sh BIN_DIR
set -uo pipefail
bin=$1
source "$(dirname "$0")/cli_checks.sh"

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
# An input file over 1 GiB (sparse: no disk is used) is refused before it is read.
truncate -s 1025M "$tmp/big.tri"
expect 65 "the limit for an input file" "$bin/tripack" "$tmp/big.tri" -o "$tmp/x.bin"
rm -f "$tmp/big.tri"
# A PNG header that claims 30000 x 30000 pixels is refused before decoding.
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x75\x30\x00\x00\x75\x30\x08\x00\x00\x00\x00\x00\x00\x00\x00' >"$tmp/claims.png"
expect 65 "the limit for" "$bin/triencode" "$tmp/claims.png" -n 10 -o "$tmp/x.tri"
expect 65 "the limit for an image" "$bin/trisim" metrics "$tmp/claims.png" "$tmp/claims.png"
# Images: a damaged JPEG says so (not another format's error), formats the README does not list
# are refused naming those it does, whatever the file's name.
printf '\xff\xd8\xff\xdb\x00\x43\x00\x01\x02\x03' >"$tmp/cut.jpg"
expect 65 "cut.jpg: byte 10: not a valid JPEG: Premature end of JPEG file" "$bin/triencode" "$tmp/cut.jpg" -n 10 -o "$tmp/x.tri"
check "triencode left a .tri for a damaged JPEG" test ! -e "$tmp/x.tri"
printf 'GIF89a\x01\x00\x01\x00\x80\x00\x00\xff\x00\x00\x00\x00\x00,\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02\x44\x01\x00;' >"$tmp/one.png"
expect 65 "one.png: byte 0: expected a PNG, JPEG, BMP or PNM (PGM or PPM) image, found a GIF image" \
  "$bin/trisim" metrics "$tmp/one.png" "$tmp/one.png"
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
weird_bin=$(printf '%s/n\xff\xfe.bin' "$tmp")
expect 0 "" "$bin/tripack" "$tmp/small.tri" --json -o "$weird_bin"
check "tripack --json with a non-UTF-8 name is not valid JSON naming it" \
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["output"].endswith("n\\xFF\\xFE.bin"), j' "$tmp/out"

# Item 10: options out of range or that would be ignored are usage errors with short messages.
expect 64 "expected at least 4" "$bin/triencode" "$tmp/small.png" -n -5 -o "$tmp/x.tri"
expect 64 "found 'nan'" "$bin/triencode" "$tmp/small.png" -e nan -o "$tmp/x.tri"
expect 64 "found 'nan'" "$bin/triencode" "$tmp/small.png" -n 8 --sigma nan -o "$tmp/x.tri"
expect 64 "expected a number above 0" "$bin/triencode" "$tmp/small.png" -e 0 -o "$tmp/x.tri"
check "the --error message prints DBL_MAX in full" bash -c "! grep -q 17976931348623157 '$tmp/err'"
expect 64 "--space" "$bin/triencode" "$tmp/small.png" -n 8 --space ycbcr -o "$tmp/x.tri"
expect 64 "--relocate" "$bin/triencode" "$tmp/small.png" -n 8 --values pixel --relocate 2 -o "$tmp/x.tri"
expect 64 "--tile" "$bin/trisim" render "$tmp/small.tri" --tile 8 -o "$tmp/x.png"
expect 64 "--format" "$bin/trisim" render "$tmp/small.tri" --format rgb565be -o "$tmp/x.png"
expect 64 "--raw" "$bin/trisim" render "$tmp/small.tri" --raw -o "$tmp/x.raw"
expect 64 "--variant" "$bin/trisim" render "$tmp/small.tri" --engine core --variant thesis -o "$tmp/x.png"
expect 64 "--dither" "$bin/trisim" render "$tmp/small.tri" --engine core --format rgb888 --dither -o "$tmp/x.png"
expect 64 "--tile" "$bin/trisim" compare "$tmp/small.tri" --tile 8 --original "$tmp/small.png"
# The core's data errors name the file.
sed 's/^size 24 16$/size 4000 16/' "$tmp/small.tri" >"$tmp/wide4000.tri"
expect 65 "wide4000.tri: " "$bin/trisim" render "$tmp/wide4000.tri" --engine core -o "$tmp/x.png"

# Issue 18 item 12: with the core, render writes what the pixel format produces. A grey mesh in
# RGB565 is an RGB PNG of the decoded 5-6-5 values (not grey), and --raw gives the frame's bytes.
expect 0 "" "$bin/trisim" render "$tmp/small.tri" --engine core --format rgb565be -o "$tmp/565.png"
expect 0 "" "$bin/trisim" render "$tmp/small.tri" --engine core --format rgb565be --raw -o "$tmp/565be.raw"
expect 0 "" "$bin/trisim" render "$tmp/small.tri" --engine core --format rgb565le --raw -o "$tmp/565le.raw"
expect 0 "" "$bin/trisim" render "$tmp/small.tri" --engine core --format l8 --raw -o "$tmp/l8.raw"
expect 0 "" "$bin/trisim" render "$tmp/small.tri" --engine core --format xrgb8888 --raw -o "$tmp/x8888.raw"
check "the RGB565 PNG is not the decoded raw frame, or the raw frames are not the formats' bytes" python3 - "$tmp" <<'PY'
import struct, sys, zlib
d = sys.argv[1]
def png(path):  # 8-bit RGB or grey PNG -> (width, height, channels, rows of bytes)
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            ch = {0: 1, 2: 3}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, stride, prev = zlib.decompress(idat), [], w * ch, bytearray(w * ch)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b, c = prev[i], prev[i - ch] if i >= ch else 0
            p = a + b - c
            pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else (b if abs(p - b) <= abs(p - c) else c)][f]
            line[i] = (line[i] + pred) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, ch, rows
w, h, ch, rows = png(d + "/565.png")
be, le = open(d + "/565be.raw", "rb").read(), open(d + "/565le.raw", "rb").read()
l8, x8888 = open(d + "/l8.raw", "rb").read(), open(d + "/x8888.raw", "rb").read()
assert (w, h, ch) == (24, 16, 3), (w, h, ch)
assert len(be) == len(le) == w * h * 2 and len(l8) == w * h and len(x8888) == w * h * 4
assert all(be[i] == le[i ^ 1] for i in range(len(be))), "rgb565le is not rgb565be byte-swapped"
not_grey = 0
for y in range(h):
    for x in range(w):
        word = be[2 * (y * w + x)] << 8 | be[2 * (y * w + x) + 1]
        r, g, b = word >> 11, (word >> 5) & 63, word & 31
        want = ((r * 255 + 15) // 31, (g * 255 + 31) // 63, (b * 255 + 15) // 31)
        got = tuple(rows[y][3 * x:3 * x + 3])
        assert got == want, (x, y, got, want)
        not_grey += got[0] != got[1]
        v = l8[y * w + x]
        assert x8888[4 * (y * w + x):4 * (y * w + x) + 3] == bytes([v, v, v]), "xrgb8888 of grey is not B=G=R=L8"
assert not_grey > 0, "the RGB565 render is grey"
PY

finish
