#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""triencode against the literature's baseline, greedy point removal (GPR), at equal vertex counts.

Usage: baselines.py BIN_DIR OUT_DIR [--images DIR] [--densities 0.5,1,2,3,4] [--jobs N] [--quick]
                    [--force] [--report-only]

For each image and vertex density (a share of the pixels, N = round(density W H), at least 4):
triencode -n N (its defaults), tribaseline gpr -n N --values lsq (GPR + LSQ) and --values pixel
(GPR), each the PSNR of its 8-bit linear interpolant and its wall time. Writes
OUT_DIR/baselines.csv and prints, per density, the mean PSNR of each, the mean difference
triencode minus GPR + LSQ and minus GPR, the image where triencode does worst against GPR + LSQ,
and the mean times; then whether issue 43's target holds (triencode's mean at least 1.0 dB above
GPR + LSQ at every density, no image more than 0.3 dB below). Images: every PNG under --images DIR
(default $TRISTREAM_IMAGES), else the ones shipped in data/; --quick: the demo image at 1 %.
Each result is cached in OUT_DIR/cache/ under the SHA-256 of the tool's and the image's bytes and
the options, so a rebuilt triencode reruns triencode alone (GPR takes seconds an image and is
rerun only when tribaseline changes); --force runs everything again.
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

from script import EXIT_CANTCREAT, EXIT_DATA, EXIT_NOINPUT, EXIT_SOFTWARE, EXIT_USAGE, Script  # noqa: E402,F401 (EXIT_USAGE: for the tests)

SCRIPT = Script("baselines")
fail, note = SCRIPT.fail, SCRIPT.note
DENSITIES = (0.5, 1.0, 2.0, 3.0, 4.0)
# (column prefix, label, command after the tool: the encoders compared)
ENCODERS = (
    ("triencode", "triencode", ("triencode",)),
    ("gpr_lsq", "GPR + LSQ", ("tribaseline", "gpr", "--values", "lsq")),
    ("gpr", "GPR", ("tribaseline", "gpr", "--values", "pixel")),
)
TARGET_MEAN_DB, TARGET_WORST_DB = 1.0, -0.3  # issue 43
COLUMNS = ["image", "width", "height", "density_pct", "vertices", "encoder", "psnr", "seconds", "status", "error"]


def parse_args(argv):
    p = SCRIPT.parser(prog="baselines.py", description=__doc__.split("\n\n")[0])
    p.add_argument("bin_dir", help="directory with triencode and tribaseline (e.g. build/bin)")
    p.add_argument("out_dir", help="output directory (e.g. out/baselines)")
    p.add_argument("--images", default=os.environ.get("TRISTREAM_IMAGES") or None,
                   help="the images: every PNG under DIR (default: $TRISTREAM_IMAGES; without it the shipped ones)")
    p.add_argument("--densities", help="vertices as percentages of the pixels, comma-separated (default 0.5,1,2,3,4)")
    p.add_argument("--quick", action="store_true", help="the demo image alone at 1 %% (for ctest)")
    p.add_argument("--jobs", type=int, default=1, help="encodings run at once (default 1)")
    p.add_argument("--force", action="store_true", help="run every encoding again, ignoring OUT_DIR/cache/")
    p.add_argument("--report-only", action="store_true",
                   help="run nothing: the table from OUT_DIR/baselines.csv of an earlier run")
    args = p.parse_args(argv)
    if args.jobs < 1:
        p.error("--jobs: expected a positive number")
    text = args.densities or ("1" if args.quick else ",".join(f"{d:g}" for d in DENSITIES))
    args.densities = SCRIPT.densities(p, text, 100)
    return args


# --- measuring ------------------------------------------------------------------------------


def vertex_count(width, height, density):
    """N for a density in percent: the nearest count, half away from zero, at least 4."""
    return max(4, int(math.floor(density / 100.0 * width * height + 0.5)))


def cache_path(cache_dir, command, path, n, bin_dir):
    """Where the result of `command` on image `path` with N vertices is cached: keyed by the bytes
    of the tool and the image and the options."""
    from runner import file_sha256, key_of
    key = key_of({"tool": file_sha256(Path(bin_dir) / command[0]), "image": file_sha256(path),
                  "options": list(command[1:]), "vertices": n})
    return Path(cache_dir) / f"{key}.json"


def measure(case):
    """One encoder on one image at one density: the row of the CSV (from the cache when there)."""
    path, name, width, height, density, encoder, bin_dir, cache_dir, force = case
    prefix, _, command = next(e for e in ENCODERS if e[0] == encoder)
    n = vertex_count(width, height, density)
    row = dict.fromkeys(COLUMNS, "")
    row.update(image=name, width=width, height=height, density_pct=density, vertices=n, encoder=prefix)
    cached = cache_path(cache_dir, command, path, n, bin_dir)
    if not force and cached.is_file():
        try:
            row.update({k: v for k, v in json.loads(cached.read_text()).items() if k in ("psnr", "seconds")},
                       status="ok")
            return row
        except (OSError, ValueError):
            pass  # unreadable: measured again
    run_case(row, path, n, command, bin_dir)
    if row["status"] == "ok":
        from runner import atomic_write_json
        atomic_write_json(cached, {"psnr": row["psnr"], "seconds": row["seconds"]})
    return row


def run_case(row, path, n, command, bin_dir):
    """Runs the encoder; fills the row's psnr, seconds and status (or error)."""
    with tempfile.TemporaryDirectory(prefix="baselines-") as tmp:
        args = [str(Path(bin_dir) / command[0]), *command[1:], str(path), "-n", str(n), "-q", "--json",
                "-o", str(Path(tmp) / "x.tri")]
        p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        row.update(status="failed", error=f"{command[0]}: exit {p.returncode}: {p.stderr.strip()[:400]}")
        return
    try:
        j = json.loads(p.stdout.splitlines()[0])
        psnr = math.inf if j["psnr_linear"] is None else float(j["psnr_linear"])
        row.update(psnr=round(psnr, 4), seconds=round(float(j["seconds"]), 3), status="ok")
        if int(j["vertices"]) != n:
            row.update(status="failed", error=f"{command[0]}: {j['vertices']} vertices, expected {n}")
    except (ValueError, KeyError, IndexError) as e:
        row.update(status="failed", error=f"{command[0]}: unreadable summary ({e})")


# --- inputs and outputs -------------------------------------------------------------------


def write_csv(path, rows):
    SCRIPT.write_csv(path, COLUMNS, rows)


def read_csv(path):
    """Rows of an earlier run, numbers as numbers (as measure() makes them)."""
    rows = SCRIPT.read_csv(path, COLUMNS)
    for i, r in enumerate(rows, start=2):
        try:
            r["density_pct"] = float(r["density_pct"])
            if r["status"] == "ok":
                r["psnr"], r["seconds"] = float(r["psnr"]), float(r["seconds"])
        except ValueError:
            fail(EXIT_DATA, f"{path}:{i}: expected numbers in the density, psnr and seconds columns")
    return rows


# --- the table ------------------------------------------------------------------------------


def by_case(rows):
    """{(density, image): {encoder: row}} of the successful rows."""
    cases = {}
    for r in rows:
        if r["status"] == "ok":
            cases.setdefault((r["density_pct"], r["image"]), {})[r["encoder"]] = r
    return cases


def density_line(d, complete):
    """The table's line for density d over the images with every encoder measured; and whether
    issue 43's target holds there."""
    psnr = {e: statistics.mean(c[e]["psnr"] for c in complete.values()) for e, _, _ in ENCODERS}
    secs = {e: statistics.mean(c[e]["seconds"] for c in complete.values()) for e, _, _ in ENCODERS}
    vs_lsq = {img: c["triencode"]["psnr"] - c["gpr_lsq"]["psnr"] for img, c in complete.items()}
    vs_gpr = [c["triencode"]["psnr"] - c["gpr"]["psnr"] for c in complete.values()]
    worst = min(vs_lsq, key=lambda img: (vs_lsq[img], img))
    mean_lsq = statistics.mean(vs_lsq.values())
    met = mean_lsq >= TARGET_MEAN_DB and vs_lsq[worst] >= TARGET_WORST_DB
    line = (f"{d:>6g} %  {len(complete):>3}  {psnr['triencode']:7.2f} {psnr['gpr_lsq']:7.2f} {psnr['gpr']:7.2f}  "
            f"{mean_lsq:+7.2f} {statistics.mean(vs_gpr):+7.2f}  {vs_lsq[worst]:+7.2f} {worst:<24.24}  "
            f"{secs['triencode']:6.2f} {secs['gpr_lsq']:6.2f} {secs['gpr']:6.2f}  {'yes' if met else 'no'}")
    return line, met


def table(rows):
    """The printed table, and whether the target holds at every density measured."""
    cases = by_case(rows)
    header = (f"{'density':>8}  {'n':>3}  {'mean PSNR (dB)':^23}  {'triencode minus':^15}  "
              f"{'worst vs GPR+LSQ':<32}  {'mean seconds':^20}  target\n"
              f"{'':>8}  {'':>3}  {'triencode':>7} {'GPR+LSQ':>7} {'GPR':>7}  {'GPR+LSQ':>7} {'GPR':>7}  "
              f"{'dB':>7} {'image':<24}  {'tri':>6} {'G+LSQ':>6} {'GPR':>6}")
    lines, all_met = [header], True
    for d in sorted({d for d, _ in cases}):
        complete = {img: c for (dd, img), c in cases.items() if dd == d and len(c) == len(ENCODERS)}
        if not complete:
            continue
        line, met = density_line(d, complete)
        lines.append(line)
        all_met = all_met and met
    lines.append(f"target (issue 43): triencode's mean >= GPR + LSQ's + {TARGET_MEAN_DB:g} dB at every density, "
                 f"no image below {TARGET_WORST_DB:+g} dB: {'met' if all_met and len(lines) > 1 else 'not met'}")
    return "\n".join(lines), all_met


def report(out, rows):
    print(f"wrote {out / 'baselines.csv'}")
    failed = [r for r in rows if r["status"] != "ok"]
    for r in failed:
        note(f"{r['image']} at {r['density_pct']:g} % ({r['encoder']}): {r['error']}")
    text, _ = table(rows)
    print(text)
    if failed:
        print(f"{len(failed)} encoding(s) failed: see the status and error columns of baselines.csv")
    return EXIT_SOFTWARE if failed else 0


def main(argv):
    args = parse_args(argv)
    out = Path(args.out_dir)
    if args.report_only:
        return report(out, read_csv(out / "baselines.csv"))
    bin_dir = Path(args.bin_dir)
    for tool in ("triencode", "tribaseline"):
        t = bin_dir / tool
        if not (t.is_file() and os.access(t, os.X_OK)):
            fail(EXIT_NOINPUT, f"{t}: expected an executable (build it with 'make tools'), found none")
    images = SCRIPT.find_images(REPO, args.quick, args.images)
    cases = [(str(p), name, w, h, d, e, str(bin_dir), str(out / "cache"), args.force) for p, name, w, h in images
             for d in args.densities for e, _, _ in ENCODERS]
    note(f"{len(images)} image(s) x {len(args.densities)} densities x {len(ENCODERS)} encoders = {len(cases)} runs")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        fail(EXIT_CANTCREAT, f"{out}: cannot create: {e.strerror}")
    rows = []
    with ProcessPoolExecutor(max_workers=args.jobs) as pool:
        for row in pool.map(measure, cases):
            rows.append(row)
            if sys.stderr.isatty():
                note(f"{len(rows)}/{len(cases)}: {row['image']} at {row['density_pct']:g} % "
                     f"({row['encoder']}): {row['status']}")
    try:
        write_csv(out / "baselines.csv", rows)
    except OSError as e:
        fail(EXIT_CANTCREAT, f"{out}: cannot write: {e}")
    return report(out, rows)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
