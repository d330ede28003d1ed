#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Rate-distortion of the project's blobs against JPEG, WebP and JPEG 2000 at equal PSNR.

Usage: rate_distortion.py BIN_DIR OUT_DIR [--images DIR] [--densities 0.5,1,2,5] [--quick] [--jobs N]
                          [--report-only]

For each image and vertex density (a share of the pixels): triencode, tripack (blob v1, and
tripack --compress when this tripack has it), trisim render of the blob (the core, bilinear),
PSNR against the original; then for each codec the smallest file found whose decoded PSNR is at
least the blob's (a binary search over its quality parameter). Writes OUT_DIR/rd.csv and
OUT_DIR/rd.png and prints the median ratios blob bytes / codec bytes per group (grey, colour)
and density. Images: the shipped ones (data/**/*.png) and every PNG under --images DIR (default
$TRISTREAM_IMAGES; without it only the shipped ones, and it says so); --quick: the demo image
at two densities.
"""
import hashlib
import io
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(HERE))

from script import EXIT_CANTCREAT, EXIT_DATA, EXIT_NOINPUT, EXIT_SOFTWARE, Script  # noqa: E402

SCRIPT = Script("rate_distortion")
fail, note = SCRIPT.fail, SCRIPT.note
DENSITIES = (0.5, 1.0, 2.0, 5.0)
QUICK_DENSITIES = (0.5, 1.0)
CODECS = ("jpeg", "webp", "jp2")
CODEC_LABEL = {"jpeg": "JPEG (baseline, optimize, 4:2:0)", "webp": "WebP (lossy, method 6)",
               "jp2": "JPEG 2000 (9/7, codestream)"}
BLOBS = ("v1", "compressed")
COLUMNS = ["image", "group", "width", "height", "density_pct", "vertices", "triangles", "psnr_blob",
           "raw_bytes", "v1_bytes", "compressed_bytes", "compressed_render"]
for _c in CODECS:
    COLUMNS += [f"{_c}_param", f"{_c}_bytes", f"{_c}_psnr"]
for _b in BLOBS:
    COLUMNS += [f"{_b}_over_{_c}" for _c in CODECS]
COLUMNS += ["status", "error"]


def parse_args(argv):
    p = SCRIPT.parser(prog="rate_distortion.py", description=__doc__.split("\n\n")[0])
    p.add_argument("bin_dir", help="directory with triencode, tripack and trisim (e.g. build/bin)")
    p.add_argument("out_dir", help="output directory (e.g. out/rd)")
    p.add_argument("--images", default=os.environ.get("TRISTREAM_IMAGES") or None,
                   help="more images: every PNG under DIR (default: $TRISTREAM_IMAGES)")
    p.add_argument("--densities", help="vertices as percentages of the pixels, comma-separated "
                                       "(default 0.5,1,2,5; --quick: 0.5,1)")
    p.add_argument("--quick", action="store_true", help="the demo image alone at two densities (for ctest)")
    p.add_argument("--jobs", type=int, default=1, help="cases measured at once (default 1)")
    p.add_argument("--report-only", action="store_true",
                   help="measure nothing: the chart and the medians from OUT_DIR/rd.csv of an earlier run")
    args = p.parse_args(argv)
    if args.jobs < 1:
        p.error("--jobs: expected a positive number")
    text = args.densities or ",".join(str(d) for d in (QUICK_DENSITIES if args.quick else DENSITIES))
    try:
        args.densities = [float(d) for d in text.split(",")]
    except ValueError:
        p.error(f"--densities: expected numbers separated by commas, found '{text}'")
    if not all(0 < d <= 100 for d in args.densities):
        p.error(f"--densities: expected percentages above 0 and at most 100, found '{text}'")
    return args


def load_dependencies():
    missing = []
    for module, package in (("numpy", "python3-numpy"), ("PIL", "python3-pil"),
                            ("matplotlib", "python3-matplotlib")):
        try:
            __import__(module)
        except ImportError:
            missing.append(package)
    if missing:
        fail(EXIT_NOINPUT, f"missing Python modules; install the Debian packages: apt-get install -y "
                           f"{' '.join(missing)} (and run with /usr/bin/python3)")
    from PIL import features
    absent = [name for name in ("jpg", "webp", "jpg_2000") if not features.check(name)]
    if absent:
        fail(EXIT_NOINPUT, f"this Pillow lacks codecs {', '.join(absent)} (Debian's python3-pil has them)")


# --- measuring ------------------------------------------------------------------------------


def luma(rgb):
    """BT.601 luma rounded half away from zero, as host_sim/model/image.cpp's to_grey."""
    import numpy as np
    y = 0.299 * rgb[..., 0] + 0.587 * rgb[..., 1] + 0.114 * rgb[..., 2]
    return np.floor(np.minimum(255.0, y) + 0.5).astype(np.uint8)


def as_array(image, grey):
    """8-bit samples: luma for a grey comparison, RGB otherwise."""
    import numpy as np
    if grey:
        return np.asarray(image.convert("L")) if image.mode in ("L", "P", "1") else luma(
            np.asarray(image.convert("RGB")).astype(np.float64))
    return np.asarray(image.convert("RGB"))


def psnr(a, b):
    """PSNR over every sample, as host_sim/metrics (inf for identical arrays)."""
    import numpy as np
    mse = float(np.mean((a.astype(np.float64) - b.astype(np.float64)) ** 2))
    return math.inf if mse == 0 else 10.0 * math.log10(255.0 * 255.0 / mse)


def encode(codec, image, grey, param):
    """The codec's bytes of `image` (a PIL image, L or RGB) at quality parameter `param`."""
    buf = io.BytesIO()
    if codec == "jpeg":
        # Baseline (not progressive), Huffman tables optimized, 4:2:0 chroma (libjpeg-turbo).
        image.save(buf, format="JPEG", quality=int(param), optimize=True, progressive=False, subsampling=2)
    elif codec == "webp":
        image.save(buf, format="WEBP", quality=int(param), method=6, lossless=False)
    else:
        # The 9/7 wavelet with the colour transform; `param` is the compression ratio; a raw
        # codestream (no JP2 boxes).
        image.save(buf, format="JPEG2000", quality_mode="rates", quality_layers=[float(param)],
                   irreversible=True, mct=1 if image.mode == "RGB" else 0, no_jp2=True)
    return buf.getvalue()


def decode(data):
    from PIL import Image
    with Image.open(io.BytesIO(data)) as im:
        im.load()
        return im.copy()


def smallest_at_psnr(evaluate, low, high, target, integer, steps=16):
    """The smallest output with PSNR >= target over parameters [low, high], where a larger
    parameter means more bytes (quality; for JPEG 2000 the inverse of the ratio, given as
    log). `evaluate(param)` returns (bytes, psnr). Binary search for the boundary; every
    candidate evaluated is kept, so the smallest passing one is returned even where PSNR is not
    quite monotone. Returns (param, bytes, psnr), or None when even `high` falls short."""
    seen = {}

    def at(p):
        if p not in seen:
            seen[p] = evaluate(p)
        return seen[p]

    if at(high)[1] < target:
        return None
    lo, hi = low, high
    if at(lo)[1] >= target:
        hi = lo
    else:
        for _ in range(steps):
            if (integer and hi - lo <= 1) or (not integer and hi - lo <= 1e-3):
                break
            mid = (lo + hi) // 2 if integer else 0.5 * (lo + hi)
            if at(mid)[1] >= target:
                hi = mid
            else:
                lo = mid
    best = min((p for p, (n, q) in seen.items() if q >= target), key=lambda p: (seen[p][0], -seen[p][1]))
    return best, seen[best][0], seen[best][1]


def codec_at_psnr(codec, image, original, grey, target):
    """(parameter, bytes, psnr) of the smallest file of `codec` at PSNR >= target, or None."""
    def evaluate(p):
        param = math.exp(-p) if codec == "jp2" else p
        data = encode(codec, image, grey, param)
        return len(data), psnr(as_array(decode(data), grey), original)

    if codec == "jpeg":
        found = smallest_at_psnr(evaluate, 1, 100, target, integer=True)
    elif codec == "webp":
        found = smallest_at_psnr(evaluate, 0, 100, target, integer=True)
    else:  # search -log(ratio) over ratios 2000 .. 1.2
        found = smallest_at_psnr(evaluate, -math.log(2000.0), -math.log(1.2), target, integer=False, steps=18)
    if found is None:
        return None
    p, n, q = found
    return (round(math.exp(-p), 3) if codec == "jp2" else p), n, q


def run(args, what):
    p = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{what}: exit {p.returncode}: {p.stderr.strip()[:400]}")
    return p.stdout


def has_compress(tripack):
    p = subprocess.run([str(tripack), "--help"], capture_output=True, text=True)
    return p.returncode == 0 and "--compress" in p.stdout


def measure(case):
    """One image at one density: the row of the CSV."""
    from PIL import Image
    path, name, density, bin_dir, compress = case
    with Image.open(path) as im:
        grey = im.mode in ("L", "LA", "1")
        image = im.convert("L" if grey else "RGB")
    width, height = image.size
    original = as_array(image, grey)
    row = dict.fromkeys(COLUMNS, "")
    row.update(image=name, group="grey" if grey else "colour", width=width, height=height, density_pct=density,
               raw_bytes=width * height * (1 if grey else 3))
    vertices = max(4, round(density / 100.0 * width * height))
    b = Path(bin_dir)
    try:
        with tempfile.TemporaryDirectory(prefix="rd-") as tmp:
            tri, v1, packed, render = (Path(tmp) / f for f in ("x.tri", "x.bin", "x-compressed.bin", "x.png"))
            run([b / "triencode", path, "-n", vertices, "-o", tri] + (["--grey"] if grey else []), "triencode")
            run([b / "tripack", tri, "-o", v1, "-m", "bilinear"], "tripack")
            row["v1_bytes"] = v1.stat().st_size
            run([b / "trisim", "render", v1, "-o", render], "trisim render")
            with Image.open(render) as r:
                rendered = as_array(r, grey)
            row["psnr_blob"] = round(psnr(rendered, original), 4)
            j = json.loads(run([b / "trisim", "compare", v1, "--json"], "trisim compare").splitlines()[0])
            row["vertices"], row["triangles"] = j["vertices"], j["triangles"]
            if compress:
                # The same mesh as the v1 blob: its render (trisim expands it with the core) must be
                # the v1 blob's, pixel for pixel; otherwise, or when trisim cannot open it, the case fails.
                run([b / "tripack", tri, "-o", packed, "-m", "bilinear", "--compress"], "tripack --compress")
                row["compressed_bytes"] = packed.stat().st_size
                run([b / "trisim", "render", packed, "-o", render], "trisim render of the compressed blob")
                with Image.open(render) as r:
                    differ = int((as_array(r, grey) != rendered).sum())
                if differ:
                    raise RuntimeError(f"the compressed blob renders differently from the v1 blob ({differ} samples)")
                row["compressed_render"] = "identical"
        target = row["psnr_blob"]
        for codec in CODECS:
            found = codec_at_psnr(codec, image, original, grey, target)
            if found is None:
                row[f"{codec}_param"] = "unreached"
                continue
            param, size, q = found
            row[f"{codec}_param"], row[f"{codec}_bytes"], row[f"{codec}_psnr"] = param, size, round(q, 4)
            for blob in BLOBS:
                if row[f"{blob}_bytes"] != "":
                    row[f"{blob}_over_{codec}"] = round(row[f"{blob}_bytes"] / size, 4)
        row["status"] = "ok"
    except (RuntimeError, OSError) as e:
        row["status"], row["error"] = "failed", str(e)
    return row


# --- inputs and outputs -------------------------------------------------------------------


def find_images(quick, images_dir):
    """(path, name) of every image measured, each distinct file once (by content)."""
    shipped = [REPO / "data/demo/kodim23.png"] if quick else sorted((REPO / "data").rglob("*.png"))
    found = [(p, str(p.relative_to(REPO))) for p in shipped]
    if not quick and images_dir:
        root = Path(images_dir)
        if not root.is_dir():
            fail(EXIT_NOINPUT, f"{root}: expected a directory of images (--images or $TRISTREAM_IMAGES)")
        more = sorted(root.rglob("*.png"))
        if not more:
            fail(EXIT_NOINPUT, f"{root}: expected PNG images, found none")
        found += [(p, str(p.relative_to(root))) for p in more]
    elif not quick:
        note("TRISTREAM_IMAGES is unset (and no --images): only the images shipped in data/ are measured")
    seen, out = set(), []
    for path, name in found:
        digest = hashlib.sha256(path.read_bytes()).hexdigest()
        if digest not in seen:
            seen.add(digest)
            out.append((path, name))
    return out


def write_csv(path, rows):
    SCRIPT.write_csv(path, COLUMNS, rows)


def medians(rows):
    """{(group, density or 'all', blob, codec): (median, min, max, count, unreached)} of the ratios;
    a case where the codec never reaches the blob's PSNR (even at its best quality) is left out
    of that codec's median and counted as unreached."""
    out = {}
    groups = sorted({r["group"] for r in rows})
    densities = sorted({r["density_pct"] for r in rows})
    for g in groups:
        for d in densities + ["all"]:
            for blob in BLOBS:
                for codec in CODECS:
                    v = [r[f"{blob}_over_{codec}"] for r in rows
                         if r["group"] == g and (d == "all" or r["density_pct"] == d)
                         and r[f"{blob}_over_{codec}"] != ""]
                    unreached = sum(1 for r in rows if r["group"] == g and (d == "all" or r["density_pct"] == d)
                                    and r[f"{blob}_bytes"] != "" and r[f"{codec}_param"] == "unreached")
                    if v:
                        out[(g, d, blob, codec)] = (statistics.median(v), min(v), max(v), len(v), unreached)
    return out


def write_chart(path, rows, table):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    from runner import atomic_write_bytes
    groups = sorted({r["group"] for r in rows})
    densities = sorted({r["density_pct"] for r in rows})
    colours = {"jpeg": "#1f77b4", "webp": "#d62728", "jp2": "#2ca02c"}
    fig, axes = plt.subplots(1, len(groups), figsize=(6 * len(groups), 4.2), squeeze=False)
    for ax, g in zip(axes[0], groups):
        for blob, style in (("v1", "-"), ("compressed", "--")):
            for codec in CODECS:
                pts = [(d, table[(g, d, blob, codec)][0]) for d in densities if (g, d, blob, codec) in table]
                if pts:
                    n = table[(g, "all", blob, codec)][3]
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], style, marker="o", color=colours[codec],
                            label=f"blob {blob} / {CODEC_LABEL[codec]} ({n} cases)")
        ax.axhline(1.0, color="black", linewidth=0.8)
        ax.axhline(2.0, color="grey", linewidth=0.8, linestyle=":", label="2x (the target of issue 19)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xticks(densities)
        ax.set_xticklabels([f"{d:g} %" for d in densities])
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("vertices (share of the pixels)")
        ax.set_ylabel("median bytes: blob / codec at equal PSNR")
        ax.set_title(f"{g} ({len({r['image'] for r in rows if r['group'] == g})} images)")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    plt.close(fig)
    atomic_write_bytes(path, buf.getvalue())


def summary(table, failed):
    lines = ["median blob bytes / codec bytes at equal PSNR (range; cases; cases where the codec never reaches "
             "the blob's PSNR), bilinear core render"]
    for (g, d, blob, codec), (med, lo, hi, n, unreached) in sorted(table.items(), key=lambda kv: (
            kv[0][0], kv[0][1] == "all", kv[0][1] if kv[0][1] != "all" else 0, kv[0][2], kv[0][3])):
        density = "all" if d == "all" else f"{d:g} %"
        more = f"; {unreached} unreached" if unreached else ""
        lines.append(f"  {g:6} {density:>6}  {blob:10} / {codec:4}  {med:7.2f}x  ({lo:.2f} to {hi:.2f}; {n}{more})")
    if failed:
        lines.append(f"  {failed} case(s) failed: see the status and error columns of rd.csv")
    return "\n".join(lines)


def read_csv(path):
    """Rows of an earlier run, numbers as numbers (as measure() makes them)."""
    rows = SCRIPT.read_csv(path, COLUMNS)
    for i, r in enumerate(rows, start=2):
        try:
            r["density_pct"] = float(r["density_pct"])
            for k in COLUMNS:
                if (k.endswith("_bytes") or "_over_" in k) and r[k] != "":
                    r[k] = float(r[k])
        except ValueError:
            fail(EXIT_DATA, f"{path}:{i}: expected numbers in the density, bytes and ratio columns")
    return rows


def report(out, rows):
    """Writes the chart, prints the medians; returns the exit code."""
    table = medians([r for r in rows if r["status"] == "ok"])
    try:
        if table:
            write_chart(out / "rd.png", rows, table)
    except OSError as e:
        fail(EXIT_CANTCREAT, f"{out}: cannot write: {e}")
    print(f"wrote {out / 'rd.csv'}" + (f" and {out / 'rd.png'}" if table else " (no case succeeded: no chart)"))
    failed = sum(r["status"] != "ok" for r in rows)
    for r in rows:
        if r["status"] != "ok":
            note(f"{r['image']} at {r['density_pct']:g} %: {r['error']}")
    print(summary(table, failed))
    return EXIT_SOFTWARE if failed else 0


def main(argv):
    args = parse_args(argv)
    load_dependencies()
    if args.report_only:
        out = Path(args.out_dir)
        return report(out, read_csv(out / "rd.csv"))
    bin_dir = Path(args.bin_dir)
    for tool in ("triencode", "tripack", "trisim"):
        t = bin_dir / tool
        if not (t.is_file() and os.access(t, os.X_OK)):
            fail(EXIT_NOINPUT, f"{t}: expected an executable (build it with 'make tools'), found none")
    compress = has_compress(bin_dir / "tripack")
    if not compress:
        note("this tripack has no --compress: only v1 blobs are measured")
    images = find_images(args.quick, args.images)
    cases = [(str(p), name, d, str(bin_dir), compress) for p, name in images for d in args.densities]
    note(f"{len(images)} image(s) x {len(args.densities)} densities = {len(cases)} cases")
    out = Path(args.out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        fail(EXIT_CANTCREAT, f"{out}: cannot create: {e.strerror}")
    rows = []
    with ProcessPoolExecutor(max_workers=args.jobs) as pool:
        for row in pool.map(measure, cases):
            rows.append(row)
            if sys.stderr.isatty():
                note(f"{len(rows)}/{len(cases)}: {row['image']} at {row['density_pct']:g} %: {row['status']}")
    try:
        write_csv(out / "rd.csv", rows)
    except OSError as e:
        fail(EXIT_CANTCREAT, f"{out}: cannot write: {e}")
    return report(out, rows)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
