#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Expected metric values for tests/metrics/test_metrics.cpp, computed by scikit-image.

Run with Debian's python (python3-skimage):
    /usr/bin/python3 tests/metrics/make_expected.py            # expected.json from data/*.png
    /usr/bin/python3 tests/metrics/make_expected.py --crops --kodak DIR
                                  # first re-create data/*.png from the Kodak images in DIR
                                  # (default: $TRISTREAM_IMAGES/kodak)
The crops are small pieces of Kodak photographs (free to use). Degraded versions: Gaussian
noise (fixed seed) and a Gaussian blur, rounded back to 8 bits.
"""
import argparse
import json
import os
import sys

import numpy as np
from PIL import Image
from scipy import ndimage
from skimage.metrics import structural_similarity
from skimage.util import view_as_windows

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")

# (name, Kodak file, left, top): 96x64 crops of textured areas.
CROPS = [
    ("kodim08", "kodim08.png", 300, 180),
    ("kodim13", "kodim13.png", 420, 260),
    ("kodim23", "kodim23.png", 150, 180),
]
W, H = 96, 64


def save(name, array):
    Image.fromarray(array).save(os.path.join(DATA, name + ".png"), optimize=True)


def make_crops(kodak):
    rng = np.random.default_rng(20261123)
    for name, file, left, top in CROPS:
        full = np.asarray(Image.open(os.path.join(kodak, file)).convert("RGB"))
        crop = full[top:top + H, left:left + W].copy()
        noisy = np.clip(np.rint(crop + rng.normal(0.0, 12.0, crop.shape)), 0, 255).astype(np.uint8)
        blurred = np.clip(np.rint(ndimage.gaussian_filter(crop.astype(np.float64), (1.2, 1.2, 0))),
                          0, 255).astype(np.uint8)
        save(name, crop)
        save(name + "_noise", noisy)
        save(name + "_blur", blurred)
    # One grey set (BT.601 luma, rounded), from the first crop.
    name = CROPS[0][0]
    crop = np.asarray(Image.open(os.path.join(DATA, name + ".png")))
    grey = np.clip(np.rint(crop @ np.array([0.299, 0.587, 0.114])), 0, 255).astype(np.uint8)
    noisy = np.clip(np.rint(grey + rng.normal(0.0, 20.0, grey.shape)), 0, 255).astype(np.uint8)
    blurred = np.clip(np.rint(ndimage.gaussian_filter(grey.astype(np.float64), 2.0)),
                      0, 255).astype(np.uint8)
    save(name + "_grey", grey)
    save(name + "_grey_noise", noisy)
    save(name + "_grey_blur", blurred)


def load(name):
    a = np.asarray(Image.open(os.path.join(DATA, name + ".png")))
    assert a.dtype == np.uint8 and a.ndim in (2, 3), name
    return a


def box_ssim_bruteforce(a, b, k):
    """Mean SSIM over every k x k box window inside the image, population covariance."""
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    planes = [(a, b)] if a.ndim == 2 else [(a[..., c], b[..., c]) for c in range(a.shape[2])]
    result = []
    for pa, pb in planes:
        wa = view_as_windows(pa.astype(np.float64), (k, k)).reshape(-1, k * k)
        wb = view_as_windows(pb.astype(np.float64), (k, k)).reshape(-1, k * k)
        ux, uy = wa.mean(1), wb.mean(1)
        vx = ((wa - ux[:, None]) ** 2).mean(1)
        vy = ((wb - uy[:, None]) ** 2).mean(1)
        vxy = ((wa - ux[:, None]) * (wb - uy[:, None])).mean(1)
        s = (2 * ux * uy + c1) * (2 * vxy + c2) / ((ux ** 2 + uy ** 2 + c1) * (vx + vy + c2))
        result.append(s.mean())
    return float(np.mean(result))


def expected(a_name, b_name):
    a, b = load(a_name), load(b_name)
    axis = None if a.ndim == 2 else -1
    d = a.astype(np.float64) - b.astype(np.float64)
    mse = float(np.mean(d * d))
    psnr = 10 * np.log10(255.0 ** 2 / mse)
    gauss = structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
                                  use_sample_covariance=False, data_range=255, channel_axis=axis)
    box7 = structural_similarity(a, b, win_size=7, gaussian_weights=False,
                                 use_sample_covariance=False, data_range=255, channel_axis=axis)
    # skimage's box window must be odd; check that the brute-force definition used for the
    # thesis's 8x8 window agrees with skimage where both exist.
    box7_brute = box_ssim_bruteforce(a, b, 7)
    if abs(box7 - box7_brute) > 1e-12:
        sys.exit(f"{a_name}/{b_name}: skimage box 7 {box7} != brute force {box7_brute}")
    box8 = box_ssim_bruteforce(a, b, 8)
    return {"a": a_name, "b": b_name, "mse": mse, "psnr": float(psnr),
            "ssim_gaussian11": float(gauss), "ssim_box7": float(box7), "ssim_box8": box8}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--crops", action="store_true", help="re-create data/*.png from Kodak")
    images = os.environ.get("TRISTREAM_IMAGES")
    default_kodak = os.path.join(images, "kodak") if images else None
    parser.add_argument("--kodak", default=default_kodak,
                        help="directory with kodim08.png, kodim13.png, kodim23.png (default: $TRISTREAM_IMAGES/kodak)")
    args = parser.parse_args()
    if args.crops:
        if not args.kodak:
            parser.error("--crops needs --kodak DIR or TRISTREAM_IMAGES")
        os.makedirs(DATA, exist_ok=True)
        make_crops(args.kodak)
    pairs = []
    for name, *_ in CROPS:
        pairs += [(name, name + "_noise"), (name, name + "_blur"), (name + "_noise", name + "_blur")]
    grey = CROPS[0][0] + "_grey"
    pairs += [(grey, grey + "_noise"), (grey, grey + "_blur")]
    out = {"generator": "tests/metrics/make_expected.py with scikit-image " +
                        __import__("skimage").__version__,
           "pairs": [expected(a, b) for a, b in pairs]}
    tmp = os.path.join(DATA, "expected.json.tmp")
    with open(tmp, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    os.replace(tmp, os.path.join(DATA, "expected.json"))


if __name__ == "__main__":
    main()
