#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the examples and checks what their panel shows against trisim's run of the same core:
# display_bands and display_dma (two band buffers, DMA simulated: a buffer written during its transfer fails) must equal `trisim render --engine core` of the whole image (RGB565 big-endian,
# dithered; the pixels do not depend on the tiling), display_zoom the 320 x 240 crop at (470, 110)
# of the 960 x 640 render, display_fit the 240 x 320 render with --fit inside (and its border). Usage: check_examples.sh BIN_DIR SOURCE_DIR OUT_DIR
set -euo pipefail
bin=$1
src=$2
out=$3
mkdir -p "$out"
tri=$src/data/demo/kodim23.rgb.tri

"$bin/display_bands" "$out/display_bands.ppm"
"$bin/trisim" render "$tri" --engine core -m zienkiewicz --format rgb565be --dither -o "$out/display_bands.ref.png"
"$bin/display_zoom" "$out/display_zoom.ppm"
"$bin/display_dma" "$out/display_dma.ppm"
"$bin/trisim" render "$tri" --engine core -m bilinear --format rgb565be --width 960 --height 640 -o "$out/zoom.ref.png"
"$bin/display_fit" "$out/display_fit.ppm"
"$bin/trisim" render "$tri" --engine core -m bilinear --format rgb565be --width 240 --height 320 --fit inside \
  --background 40 -o "$out/fit.ref.png"

/usr/bin/python3 -c 'import PIL' 2>/dev/null ||
  { echo "check_examples: needs Python's PIL (python3-pil: tools/install-deps.sh experiments)" >&2; exit 1; }
/usr/bin/python3 - "$out" <<'PY'
import sys
from PIL import Image
out = sys.argv[1]
def same(a, b, what):
    if a.size != b.size or a.tobytes() != b.tobytes():
        differing = sum(p != q for p, q in zip(a.getdata(), b.getdata())) if a.size == b.size else -1
        sys.exit(f"check_examples: {what}: {a.size} vs {b.size}, {differing} pixels differ")
same(Image.open(f"{out}/display_bands.ppm").convert("RGB"), Image.open(f"{out}/display_bands.ref.png").convert("RGB"),
     "display_bands against trisim render --engine core")
same(Image.open(f"{out}/display_dma.ppm").convert("RGB"), Image.open(f"{out}/display_bands.ref.png").convert("RGB"),
     "display_dma (two band buffers) against trisim render --engine core")
same(Image.open(f"{out}/display_zoom.ppm").convert("RGB"),
     Image.open(f"{out}/zoom.ref.png").convert("RGB").crop((470, 110, 790, 350)),
     "display_zoom against the crop of trisim's 960x640 render")
fit = Image.open(f"{out}/display_fit.ppm").convert("RGB")
same(fit, Image.open(f"{out}/fit.ref.png").convert("RGB"), "display_fit against trisim's render --fit inside")
# The border: rows 0 to 79 and 240 to 319 are the background (40 in RGB565: 41, 40, 41), the rest the picture.
border = [fit.getpixel((x, y)) for y in list(range(80)) + list(range(240, 320)) for x in range(240)]
if set(border) != {(41, 40, 41)} or fit.getpixel((120, 80)) == (41, 40, 41):
    sys.exit(f"check_examples: display_fit: border {sorted(set(border))[:4]}")
print("check_examples: display_bands, display_dma, display_zoom and display_fit show the core's pixels")
PY
