#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Reproduces the thesis's chapter 6 (quality and time of the interpolation methods) as a report.

Usage: run_experiments.py BIN_DIR OUT_DIR [--set quick|full] [--force] [--jobs N] [--images DIR]

Writes OUT_DIR/index.html (self-contained), CSV files and charts. Results are cached under
OUT_DIR/cache keyed by their inputs (image bytes, options, tool binaries) and reused unless
--force. The full set reads every image under --images DIR (default $TRISTREAM_IMAGES; any
layout), and refuses a DIR without one (exit 65); without DIR it runs on data/demo/kodim23.png alone.
The quick set reads only data/demo/kodim23.png. On a terminal a progress bar, otherwise a line per case.
"""
import argparse
import os
import platform
import subprocess
import sys
import time
from collections import defaultdict
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

sys.dont_write_bytecode = True  # keep the source tree free of __pycache__
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

EXIT_USAGE, EXIT_DATA, EXIT_NOINPUT, EXIT_CANTCREAT = 64, 65, 66, 73


def fail(code, message):
    print(f"run_experiments: {message}", file=sys.stderr)
    sys.exit(code)


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        fail(EXIT_USAGE, message)


def parse_args(argv):
    p = Parser(prog="run_experiments.py", description=__doc__.split("\n\n")[0])
    p.add_argument("bin_dir", help="directory with trisim and triencode (e.g. build/bin)")
    p.add_argument("out_dir", help="report directory (e.g. out/report)")
    p.add_argument("--set", dest="set_name", choices=["quick", "full"], default="quick",
                   help="experiment set (default: quick)")
    p.add_argument("--images", default=os.environ.get("TRISTREAM_IMAGES") or None,
                   help="test photographs for the full set, in grey/, colour/ and kodak/ "
                        "(default: $TRISTREAM_IMAGES; without it only the shipped demo image)")
    p.add_argument("--force", action="store_true", help="recompute everything instead of reusing the cache")
    p.add_argument("--report-only", action="store_true",
                   help="compute nothing: write the report from the results already in the cache")
    p.add_argument("--jobs", type=int, default=1,
                   help="triangulations processed at once (default 1; timings are cleanest with 1)")
    args = p.parse_args(argv)
    if args.jobs < 1:
        p.error("--jobs: expected a positive number")
    return args


def load_dependencies():
    missing = []
    for module, package in (("numpy", "python3-numpy"), ("scipy", "python3-scipy"), ("PIL", "python3-pil"),
                            ("matplotlib", "python3-matplotlib"), ("tqdm", "python3-tqdm")):
        try:
            __import__(module)
        except ImportError:
            missing.append(package)
    if missing:
        fail(EXIT_NOINPUT, f"missing Python modules; install the Debian packages: apt-get install -y "
                           f"{' '.join(missing)} (and run with /usr/bin/python3)")


def machine_description():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = ""
    try:
        for line in open("/proc/meminfo", encoding="utf-8"):
            if line.startswith("MemTotal"):
                mem = f"{int(line.split()[1]) / 1048576:.0f} GiB RAM"
                break
    except OSError:
        pass
    return f"{cpu}, {os.cpu_count()} logical CPUs, {mem}, {platform.system()} {platform.release()}, " \
           f"Python {platform.python_version()}"


def git_commit(repo):
    try:
        out = subprocess.run(["git", "-C", str(repo), "rev-parse", "--short", "HEAD"], capture_output=True,
                             text=True, timeout=10)
        dirty = subprocess.run(["git", "-C", str(repo), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, timeout=10)
        if out.returncode == 0:
            return out.stdout.strip() + (" (working tree has uncommitted changes)" if dirty.stdout.strip() else "")
    except (OSError, subprocess.SubprocessError):
        pass
    return "unknown"


def build_work(plan, tools):
    """The encodings, their quality runs and the timing runs of a plan."""
    from execute import ANALYSED_METHODS, Run, TimeRun
    from plan import Enc, scaled

    work = defaultdict(list)     # Enc -> [Run]
    pictures = set((img, label, nominal) for img, label, nominal in plan.picture_cases)

    def add_runs(enc, thesis_variants=False, analyse=False):
        keep = (enc.image, enc.label, enc.nominal) in pictures
        runs = []
        for method in tools.methods:
            for engine in tools.engines:
                runs.append(Run(enc, method, "", engine, keep,
                                analyse and engine == "reference" and method in ANALYSED_METHODS))
            if thesis_variants and method in THESIS_VARIANTS:
                runs.append(Run(enc, method, "thesis", "reference", False, analyse and method in ANALYSED_METHODS))
        work[enc].extend(runs)

    from plan import THESIS_VARIANTS
    for s in plan.grey_sources:
        for n in plan.grey_counts:
            enc = Enc("grey", s.name, s.group, s, True, "grey", "grey", scaled(n, s.width, s.height), n)
            add_runs(enc, thesis_variants=s.name in plan.thesis_variants_for, analyse=True)
    for s in plan.colour_sources:
        for total in plan.colour_totals:
            t = scaled(total, s.width, s.height)
            for space in ("rgb", "ycbcr"):
                add_runs(Enc("colour", s.name, s.group, s, False, "co", space, t, total))
                add_runs(Enc("colour", s.name, s.group, s, False, "separate", space, max(4, round(t / 3)), total))
        for total in plan.cotri_thesis_totals:
            t = scaled(total, s.width, s.height)
            add_runs(Enc("colour", s.name, s.group, s, False, "co", "rgb", t, total, cotri="thesis"))
    for s in plan.split_sources:
        for ny, nc in plan.splits:
            parts = (scaled(ny, s.width, s.height), scaled(nc, s.width, s.height))
            add_runs(Enc("split", s.name, s.group, s, False, "split", "ycbcr", 0, ny + 2 * nc, parts=parts,
                         parts_nominal=(ny, nc)))
    timing = []
    for s in plan.time_sources:
        for n in plan.time_counts:
            enc = Enc("time", s.name, s.group, s, True, "grey", "grey", scaled(n, s.width, s.height), n)
            for method in tools.methods:
                for engine in tools.engines:
                    timing.append(TimeRun(enc, method, "", engine, plan.time_repeats))
                if method in THESIS_VARIANTS:
                    timing.append(TimeRun(enc, method, "thesis", "reference", 1))
    return work, timing


def main(argv):
    args = parse_args(argv)
    load_dependencies()
    from tqdm import tqdm

    import report
    from execute import Executor
    from plan import make_plan
    from runner import Cache, ToolError, Tools

    repo = HERE.parent.parent
    out_dir = Path(args.out_dir)
    try:
        tools = Tools(Path(args.bin_dir))
    except ToolError as exc:
        fail(EXIT_NOINPUT, str(exc))
    try:
        plan = make_plan(args.set_name, repo, Path(args.images) if args.images else None)
    except (OSError, ValueError) as exc:
        fail(EXIT_DATA, str(exc))
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
        probe = out_dir / ".write-probe"
        probe.write_text("")
        probe.unlink()
    except OSError as exc:
        fail(EXIT_CANTCREAT, f"{out_dir}: cannot write the report there ({exc.strerror})")

    work, timing = build_work(plan, tools)
    total = len(work) + sum(len(r) for r in work.values()) + len(timing)
    started = time.time()
    load_start = os.getloadavg()
    cache = Cache(out_dir / "cache", force=args.force, offline=args.report_only)
    # On a terminal a progress bar; otherwise (a log, CI) one line per case as it ends.
    lines = not sys.stderr.isatty()
    cases = len(work) + len(timing)
    done = 0

    def case_line(what):
        nonlocal done
        done += 1
        if lines:
            print(f"experiments ({plan.name}): case {done}/{cases} done after {time.time() - started:.0f} s: {what}",
                  file=sys.stderr, flush=True)

    with tqdm(total=total, disable=True if lines else None, file=sys.stderr, unit="item", dynamic_ncols=True,
              desc=f"experiments ({plan.name})") as bar:
        executor = Executor(tools, cache, bar)
        with ThreadPoolExecutor(max_workers=args.jobs) as pool:
            futures = {pool.submit(executor.process, enc, runs): (enc, runs) for enc, runs in work.items()}
            for f in as_completed(futures):
                f.result()
                enc, runs = futures[f]
                case_line(f"{enc.study} {enc.image} {enc.label}, {enc.nominal:,} vertices ({len(runs)} runs)")
        # Timing runs come last and one at a time, so that they do not compete with each other.
        for t in timing:
            executor.time_run(t)
            bar.update(1)
            case_line(f"time {t.enc.image} {t.method}{' ' + t.variant if t.variant else ''} {t.engine}, "
                      f"{t.enc.nominal:,} vertices")
    elapsed = time.time() - started
    from runner import file_sha256
    changed = [str(t) for t, sha in ((tools.trisim, tools.trisim_sha), (tools.triencode, tools.triencode_sha))
               if file_sha256(t) != sha]
    if changed:
        plan.notes.append(f"{', '.join(changed)} changed during the run (rebuilt?): results were keyed by the "
                          f"binaries found at the start; run again to recompute them with the new ones.")
        print(f"run_experiments: warning: {', '.join(changed)} changed during the run", file=sys.stderr)
    context = {
        "set": plan.name, "machine": machine_description(), "commit": git_commit(repo),
        "trisim_sha": tools.trisim_sha[:16], "triencode_sha": tools.triencode_sha[:16],
        "methods": tools.methods, "engines": tools.engines, "elapsed_s": elapsed,
        "load_start": load_start, "load_end": os.getloadavg(), "jobs": args.jobs,
        "started": time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime(started)),
        "command": " ".join([Path(sys.argv[0]).name] + list(argv)), "report_only": args.report_only,
    }
    # The last computing run of this set, so that a --report-only page can say when and how the results
    # were computed.
    import json
    from runner import atomic_write_json
    last_run = out_dir / "cache" / f"last-run-{plan.name}.json"
    if args.report_only:
        try:
            context["computed_by"] = json.loads(last_run.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            context["computed_by"] = None
    else:
        atomic_write_json(last_run, {k: context[k] for k in ("started", "elapsed_s", "load_start", "load_end",
                                                             "jobs", "command", "trisim_sha", "triencode_sha")})
    try:
        report.write_report(out_dir, plan, tools, executor, work, timing, context)
    except OSError as exc:
        fail(EXIT_CANTCREAT, f"{out_dir}: cannot write the report ({exc})")
    failures = sum(1 for r in executor.run_results.values() if r.get("status") in ("failed",))
    print(f"run_experiments: {plan.name} set: {total} items in {elapsed:.0f} s; report in {out_dir / 'index.html'}"
          + (f"; {failures} runs failed (listed in the report)" if failures else ""), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
