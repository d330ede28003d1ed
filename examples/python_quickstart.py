#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""tristream from Python, cell by cell: a photograph in, a triangulation out, two renders and their
PSNR, the blob firmware would link. Run with the module on the path:

    make python && PYTHONPATH=build/python /usr/bin/python3 examples/python_quickstart.py [OUT_DIR]
"""
import sys
import tempfile
from pathlib import Path

import numpy as np
import tristream

# %% The picture: a numpy array of uint8, (H, W) grey or (H, W, 3) RGB.
root = Path(__file__).resolve().parents[1]
image = tristream.read_image(root / "data" / "demo" / "kodim23.png")
print(f"image {image.shape[1]}x{image.shape[0]}, {image.dtype}")

# %% Encode: 2,000 vertices (triencode -n 2000), or max_bytes=B for a blob budget.
tri = tristream.encode(image, 2000)
print(tri)
print("first vertices (x, y):", tri.vertices[:3].tolist(), "values:", tri.values[:3].tolist())

# %% Render with two methods and measure them against the original.
for method in ("bilinear", "zienkiewicz"):
    render = tristream.render(tri, method)
    print(f"{method:12s} PSNR {tristream.psnr(render, image):6.2f} dB  SSIM {tristream.ssim(render, image):.4f}")

# %% The fixed-point core renders the blob firmware links; its frame is close to the reference.
blob = tristream.pack(tri, "bilinear", compress=True)
frame = tristream.render(blob, format="rgb565be")
print(f"compressed blob {len(blob)} bytes; core frame (RGB565) PSNR {tristream.psnr(frame, image):.2f} dB")

# %% The reference in doubles: the interpolant before rounding (NaN outside the triangulation).
field = tristream.render(tri, "clough-tocher", dtype="float64")
print(f"clough-tocher values from {np.nanmin(field):.2f} to {np.nanmax(field):.2f}")

# %% Files: the .tri and a PNG of the render.
out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(tempfile.mkdtemp(prefix="tristream-"))
out.mkdir(parents=True, exist_ok=True)
tristream.write_tri(out / "kodim23.tri", tri)
tristream.write_png(out / "kodim23.bilinear.png", tristream.render(tri, "bilinear"))
print(f"wrote {out / 'kodim23.tri'} and {out / 'kodim23.bilinear.png'}")
