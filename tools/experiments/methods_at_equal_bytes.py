#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The gradient methods against bilinear at equal compressed-blob bytes (issue 43).

Usage: methods_at_equal_bytes.py BIN_DIR OUT_DIR [--images DIR] [--densities 0.5,1,2] [--jobs N] [--quick]
                                 [--report-only]

For each image and density (bilinear's vertices as a share of the pixels, N = round(density W H)):
- bilinear: triencode -n N, its compressed blob's bytes B (tripack --compress), and two more
  encodings at 0.7 N and 0.5 N, the points its PSNR is interpolated between (linearly in
  log(bytes));
- zienkiewicz: triencode --max-bytes B -m zienkiewicz (values and gradients fitted for it, the
  most vertices whose compressed blob fits B), its bytes and PSNR;
- clough-tocher: triencode -n (zienkiewicz's count) -m clough-tocher; its bytes are those of its
  data packed as a zienkiewicz blob (the same values and gradients a vertex; the core does not draw
  clough-tocher).
Each method's PSNR is that of its reference render (triencode's); its difference to bilinear is
taken at the method's own bytes. Writes OUT_DIR/methods.csv and prints, per density, the mean and
median difference of each method, how many pictures it beats bilinear by 0.5 dB or more, and the
verdict of issue 43: whether the best method beats bilinear by at least 0.5 dB on most pictures.
Images: every PNG under --images DIR (default $TRISTREAM_IMAGES), else the shipped ones in data/;
--quick: the demo image at 1 %.
"""
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

from script import EXIT_CANTCREAT, EXIT_NOINPUT, Script, png_size  # noqa: E402

SCRIPT = Script("methods_at_equal_bytes")
fail, note = SCRIPT.fail, SCRIPT.note
DENSITIES = (0.5, 1.0, 2.0)
METHODS = ("zienkiewicz", "clough-tocher")
BILINEAR_SHARES = (1.0, 0.7, 0.5)  # bilinear's encodings, as shares of N
GOAL_DB = 0.5  # issue 43: the best method beats bilinear by at least this at equal bytes
COLUMNS = ["image", "density_pct", "method", "vertices", "bytes", "psnr", "bilinear_psnr_at_bytes",
           "difference_db", "status", "error"]


def parse_args(argv):
    p = SCRIPT.parser(prog="methods_at_equal_bytes.py", description=__doc__.split("\n\n")[0])
    p.add_argument("bin_dir", help="directory with triencode and tripack (e.g. build/bin)")
    p.add_argument("out_dir", help="output directory (e.g. out/methods)")
    p.add_argument("--images", default=os.environ.get("TRISTREAM_IMAGES") or None,
                   help="the images: every PNG under DIR (default: $TRISTREAM_IMAGES; without it the shipped ones)")
    p.add_argument("--densities", help="bilinear's vertices as percentages of the pixels (default 0.5,1,2)")
    p.add_argument("--quick", action="store_true", help="the demo image alone at 1 %% (for ctest)")
    p.add_argument("--jobs", type=int, default=1, help="images measured at once (default 1)")
    p.add_argument("--report-only", action="store_true", help="measure nothing: the table of OUT_DIR/methods.csv")
    args = p.parse_args(argv)
    if args.jobs < 1:
        p.error("--jobs: expected a positive number")
    text = args.densities or ("1" if args.quick else ",".join(f"{d:g}" for d in DENSITIES))
    args.densities = SCRIPT.densities(p, text, 50)
    return args


# --- measuring ------------------------------------------------------------------------------


def run(args, what):
    p = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{what}: exit {p.returncode}: {p.stderr.strip()[:400]}")
    return p.stdout


def encode(bin_dir, tmp, image, options):
    """triencode's JSON summary and the .tri it wrote."""
    tri = Path(tmp) / "x.tri"
    out = run([Path(bin_dir) / "triencode", image, "-o", tri, "-q", "--json", *options], "triencode")
    return json.loads(out), tri


def compressed_bytes(bin_dir, tmp, tri, method):
    blob = Path(tmp) / "x.bin"
    run([Path(bin_dir) / "tripack", tri, "-o", blob, "-m", method, "--compress"], "tripack --compress")
    return blob.stat().st_size


def interpolate(points, x):
    """PSNR at bytes x, linear in log(bytes) between the two nearest points of (bytes, psnr)
    (extrapolated from the end pair outside them)."""
    pts = sorted(points)
    lo, hi = pts[0], pts[1]
    for a, b in zip(pts, pts[1:]):
        lo, hi = a, b
        if x <= b[0]:
            break
    t = (math.log(x) - math.log(lo[0])) / (math.log(hi[0]) - math.log(lo[0]))
    return lo[1] + t * (hi[1] - lo[1])


def measure(case):
    """One image at one density: a row per method."""
    path, name, density, bin_dir = case
    width, height = png_size(path)
    n = max(4, round(density / 100.0 * width * height))
    rows = []
    try:
        with tempfile.TemporaryDirectory(prefix="methods-") as tmp:
            curve = []
            for share in BILINEAR_SHARES:
                j, tri = encode(bin_dir, tmp, path, ["-n", max(4, round(share * n))])
                curve.append((compressed_bytes(bin_dir, tmp, tri, "bilinear"), j["psnr"]))
            budget = curve[0][0]
            rows.append(dict(image=name, density_pct=density, method="bilinear", vertices=n, bytes=budget,
                             psnr=round(curve[0][1], 4), bilinear_psnr_at_bytes=round(curve[0][1], 4),
                             difference_db=0.0, status="ok", error=""))
            j, tri = encode(bin_dir, tmp, path, ["--max-bytes", budget, "-m", "zienkiewicz"])
            nz = j["vertices"]
            found = {"zienkiewicz": (nz, j["blob_bytes"], j["psnr"])}
            j, tri = encode(bin_dir, tmp, path, ["-n", nz, "-m", "clough-tocher"])
            found["clough-tocher"] = (nz, compressed_bytes(bin_dir, tmp, tri, "zienkiewicz"), j["psnr"])
            for method in METHODS:
                v, size, q = found[method]
                at = interpolate(curve, size)
                rows.append(dict(image=name, density_pct=density, method=method, vertices=v, bytes=size,
                                 psnr=round(q, 4), bilinear_psnr_at_bytes=round(at, 4),
                                 difference_db=round(q - at, 4), status="ok", error=""))
    except (RuntimeError, OSError, ValueError, KeyError, ArithmeticError) as e:
        rows.append(dict.fromkeys(COLUMNS, "") | dict(image=name, density_pct=density, method="all",
                                                      status="failed", error=str(e)))
    return rows


# --- inputs and outputs -------------------------------------------------------------------


def summary(rows):
    """The table per density: mean and median difference, wins by GOAL_DB, and the verdict."""
    lines = [f"{'density %':>9} {'method':<14} {'images':>6} {'mean dB':>8} {'median dB':>9} {'>= +0.5 dB':>10}"]
    verdicts = []
    for d in sorted({float(r["density_pct"]) for r in rows if r["status"] == "ok"}):
        best_wins = {}
        for method in METHODS:
            diffs = {r["image"]: float(r["difference_db"]) for r in rows
                     if r["status"] == "ok" and r["method"] == method and float(r["density_pct"]) == d}
            if not diffs:
                continue
            wins = sum(1 for x in diffs.values() if x >= GOAL_DB)
            for image, x in diffs.items():
                best_wins[image] = max(best_wins.get(image, -math.inf), x)
            lines.append(f"{d:>9g} {method:<14} {len(diffs):>6} {statistics.mean(diffs.values()):>+8.2f} "
                         f"{statistics.median(diffs.values()):>+9.2f} {wins:>6} of {len(diffs)}")
        won = sum(1 for x in best_wins.values() if x >= GOAL_DB)
        verdicts.append((d, won, len(best_wins)))
    lines.append("")
    for d, won, total in verdicts:
        held = won * 2 > total
        lines.append(f"{d:g} %: the better of the two beats bilinear by {GOAL_DB} dB or more on {won} of {total} "
                     f"pictures: the goal {'holds' if held else 'does not hold'}")
    return "\n".join(lines)


def main(argv):
    args = parse_args(argv)
    out = Path(args.out_dir)
    csv_path = out / "methods.csv"
    if args.report_only:
        rows = SCRIPT.read_csv(csv_path, COLUMNS)
    else:
        bin_dir = Path(args.bin_dir)
        for tool in ("triencode", "tripack"):
            if not (bin_dir / tool).is_file():
                fail(EXIT_NOINPUT, f"{bin_dir / tool}: not found (build the tools first: make tools)")
        images = SCRIPT.find_images(REPO, args.quick, args.images)
        cases = [(str(path), name, d, str(bin_dir)) for path, name, _, _ in images for d in args.densities]
        rows = []
        with ProcessPoolExecutor(max_workers=args.jobs) as pool:
            for k, result in enumerate(pool.map(measure, cases), 1):
                rows.extend(result)
                note(f"{k}/{len(cases)} {result[0]['image']} {result[0]['density_pct']} %")
        try:
            out.mkdir(parents=True, exist_ok=True)
            SCRIPT.write_csv(csv_path, COLUMNS, rows)
        except OSError as e:
            fail(EXIT_CANTCREAT, f"{csv_path}: cannot write: {e.strerror}")
    failed = [r for r in rows if r["status"] != "ok"]
    for r in failed:
        note(f"{r['image']} at {r['density_pct']} %: {r['error']}")
    print(summary(rows))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
