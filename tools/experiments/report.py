# SPDX-License-Identifier: MIT
"""The report: CSV files, charts, pictures and one self-contained index.html."""
import base64
import csv
import html
import io
import os
from collections import defaultdict
from pathlib import Path

import numpy as np

import charts
import findings
import pictures
import trifile
from execute import Run, load_image
from runner import atomic_write_text

# Figure 6.22 of the thesis: seconds per 512x512 image, 1.86 GHz Core2Duo E6300, .NET.
THESIS_TIMES = {
    "bilinear": {2000: 0.0391, 4000: 0.0531, 5000: 0.0610, 7000: 0.0688, 10000: 0.0906, 12000: 0.0938,
                 15000: 0.1313},
    "zienkiewicz": {2000: 0.0656, 4000: 0.0813, 5000: 0.0891, 7000: 0.1141, 10000: 0.1344, 12000: 0.1594,
                    15000: 0.1860},
    "voronoi": {2000: 0.6095, 4000: 0.6531, 5000: 0.6502, 7000: 0.6656, 10000: 0.6830, 12000: 0.6938,
                15000: 0.7127},
    "natural": {2000: 3.0807, 4000: 3.2422, 5000: 3.3354, 7000: 3.4234, 10000: 3.5322, 12000: 3.5922,
                15000: 3.6463},
    "bezier": {2000: 4.8888, 4000: 9.5922, 5000: 12.091, 7000: 16.75, 10000: 24.070, 12000: 29.064,
               15000: 37.597},
    "coons": {2000: 17.2735, 4000: 33.8125, 5000: 43.4367, 7000: 56.6, 10000: 83.2392, 12000: 98.2891,
              15000: 128.57},
}

FIELDS = ["study", "image", "group", "width", "height", "colour", "mode", "space", "cotri", "nominal_vertices",
          "vertices", "triangles", "method", "variant", "engine", "status", "mse", "psnr", "ssim", "ssim_window",
          "ssim_8x8", "ms", "cpu_s", "load1", "mae_high", "mae_low", "psnr_vs_reference",
          "max_abs_diff_vs_reference", "error"]
TIME_FIELDS = ["image", "width", "height", "nominal_vertices", "vertices", "triangles", "method", "variant",
               "engine", "runs", "status", "ms", "cpu_ms", "load1", "error"]
SEP_CO_COLOURS = {"separate": "#1f77b4", "co-triangulation": "#d62728"}
MODE_COLOURS = {"separate-rgb": "#1f77b4", "separate-ycbcr": "#9ecae1", "co-rgb": "#d62728",
                "co-ycbcr": "#fc9272", "co-rgb-thesis": "#7f0000"}


def label(method, variant, engine):
    return method + (f" ({variant})" if variant else "") + ("" if engine == "reference" else f" [{engine}]")


def quality_rows(work, executor):
    rows = []
    for enc, runs in work.items():
        e = executor.enc_results.get(enc, {})
        for run in runs:
            r = executor.run_results.get(run, {"status": "missing"})
            a = r.get("analysis") or {}
            rows.append({
                "study": enc.study, "image": enc.image, "group": enc.group, "width": enc.source.width,
                "height": enc.source.height, "colour": enc.label, "mode": enc.mode, "space": enc.space,
                "cotri": enc.cotri if enc.mode == "co" else "", "nominal_vertices": enc.nominal,
                "vertices": r.get("vertices", e.get("vertices")), "triangles": r.get("triangles", e.get("triangles")),
                "method": run.method, "variant": run.variant, "engine": run.engine, "status": r.get("status"),
                "mse": r.get("mse"), "psnr": r.get("psnr"), "ssim": r.get("ssim"),
                "ssim_window": r.get("ssim_window"), "ssim_8x8": r.get("ssim_8x8"), "ms": r.get("ms"),
                "cpu_s": r.get("cpu_s"), "load1": r.get("load1"), "mae_high": a.get("mae_high"),
                "mae_low": a.get("mae_low"), "error": r.get("error", ""),
                "psnr_vs_reference": r.get("psnr_vs_reference"),
                "max_abs_diff_vs_reference": r.get("max_abs_diff_vs_reference"),
                "_render": r.get("render"), "_tri": e.get("tri"), "_original": e.get("image_file"),
            })
    return rows


def time_rows(timing, executor):
    rows = []
    for t in timing:
        r = executor.time_results.get(t, {"status": "missing"})
        rows.append({"image": t.enc.image, "width": t.enc.source.width, "height": t.enc.source.height,
                     "nominal_vertices": t.enc.nominal, "vertices": r.get("vertices"),
                     "triangles": r.get("triangles"), "method": t.method, "variant": t.variant,
                     "engine": t.engine, "runs": t.runs, "status": r.get("status"), "ms": r.get("ms"),
                     "cpu_ms": r.get("cpu_ms"), "load1": r.get("load1"), "error": r.get("error", "")})
    return rows


def write_csv(path: Path, rows, fields):
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=fields, extrasaction="ignore", lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in fields})
    atomic_write_text(path, buf.getvalue())
    return path


def time_table(trows):
    """{label: {nominal: (mean over images of the fastest render's wall s, of the median render CPU s,
    images)}}, from trisim bench's timing of the renders alone."""
    per = defaultdict(lambda: defaultdict(list))
    for r in trows:
        if r["status"] == "ok" and r.get("cpu_ms") is not None:
            per[label(r["method"], r["variant"], r["engine"])][r["nominal_vertices"]].append(
                (r["ms"] / 1000.0, r["cpu_ms"] / 1000.0))
    return {lab: {n: (float(np.mean([x[0] for x in vals])), float(np.mean([x[1] for x in vals])), len(vals))
                  for n, vals in d.items()} for lab, d in per.items()}


class Html:
    def __init__(self):
        self.parts = []

    def add(self, s):
        self.parts.append(s)

    def h(self, level, text, anchor=None):
        a = f' id="{anchor}"' if anchor else ""
        self.add(f"<h{level}{a}>{html.escape(text)}</h{level}>")

    def p(self, text, raw=False):
        self.add(f"<p>{text if raw else html.escape(text)}</p>")

    def img(self, path: Path, caption: str, width=None):
        data = base64.b64encode(Path(path).read_bytes()).decode()
        style = f' style="max-width:{width}px"' if width else ""
        mime = "image/jpeg" if Path(path).suffix == ".jpg" else "image/png"
        self.add(f'<figure><img src="data:{mime};base64,{data}" alt="{html.escape(caption)}"{style}>'
                 f"<figcaption>{html.escape(caption)} <span class=file>({html.escape(Path(path).name)})</span>"
                 f"</figcaption></figure>")

    def table(self, header, rows, cls=""):
        out = [f'<table class="{cls}"><thead><tr>' + "".join(f"<th>{html.escape(str(h))}</th>" for h in header)
               + "</tr></thead><tbody>"]
        for row in rows:
            out.append("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>")
        out.append("</tbody></table>")
        self.add("".join(out))


CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;
color:#222;line-height:1.45}
h1{font-size:1.6em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;margin:1em 0;font-size:.85em}td,th{border:1px solid #ccc;padding:.25em .5em;
text-align:right;vertical-align:top}th{background:#f3f3f3}td:first-child,th:first-child{text-align:left}
table.findings td{text-align:left}table.findings td:nth-child(4){text-align:right}
table.findings td:nth-child(5){white-space:nowrap;font-weight:600}
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #ddd}figcaption{font-size:.85em;color:#555}
.file{color:#999}.agrees{color:#1a7f37}.disagrees{color:#c62828}.mixed{color:#b26a00}.mostly{color:#4d7f1a}
.not,.no{color:#666}
code{background:#f4f4f4;padding:0 .2em}.note{background:#fff8e1;padding:.5em 1em;border-left:3px solid #f0b400}
"""


def fmt(v, digits=3):
    if v is None or v == "":
        return "–"
    if isinstance(v, float) and not np.isfinite(v):
        return "∞"
    return f"{v:.{digits}f}"


def mean_of(rows, metric):
    vals = [float(r[metric]) for r in rows if r.get(metric) not in (None, "")]
    return float(np.mean(vals)) if vals else None


def write_time_csv(out_dir: Path, ttable):
    """time.csv: per method and count the seconds here, the thesis's and their ratio."""
    trows_out = []
    for lab, d in ttable.items():
        base = lab.split(" ")[0]
        for n, (wall, cpu, images) in sorted(d.items()):
            th = THESIS_TIMES.get(base, {}).get(n) if "[" not in lab else None
            trows_out.append({"method": lab, "nominal_vertices": n, "seconds": wall, "cpu_seconds": cpu,
                              "images": images, "thesis_seconds": th, "thesis_over_here": th / wall if th else None,
                              "thesis_over_cpu": th / cpu if th and cpu else None})
    write_csv(out_dir / "time.csv", trows_out, ["method", "nominal_vertices", "seconds", "cpu_seconds", "images",
                                                 "thesis_seconds", "thesis_over_here", "thesis_over_cpu"])


def partial_note_html(rows, trows):
    """A note naming the results not computed yet, or "" when every run has a result."""
    missing = defaultdict(int)
    for r in rows:
        if r["status"] == "missing":
            missing[r["study"]] += 1
    missing_t = sum(1 for r in trows if r["status"] == "missing")
    if not (missing or missing_t):
        return ""
    return ('<p class=note>This report is partial: results not computed yet (written with '
            '--report-only or interrupted): '
            + html.escape(", ".join(f"{n} {s} runs" for s, n in sorted(missing.items()))
                          + (f", {missing_t} timing runs" if missing_t else ""))
            + ". Running the same command without --report-only computes them.</p>")


def header_section(doc, plan, ctx, partial_note):
    doc.add(f"<!DOCTYPE html><html lang=en><head><meta charset=utf-8><title>tristream: chapter 6 reproduced "
            f"({plan.name} set)</title><style>{CSS}</style></head><body>")
    doc.h(1, f"tristream: the thesis's chapter 6 reproduced ({plan.name} set)")
    doc.p(f"Run started {html.escape(ctx['started'])}; computing took {ctx['elapsed_s']:.0f} s"
          f"{' (report written from the cache only)' if ctx['report_only'] else ''}. Machine: "
          f"{html.escape(ctx['machine'])}. Load average (1 min) {ctx['load_start'][0]:.2f} at the start and "
          f"{ctx['load_end'][0]:.2f} at the end (the machine is shared; wall-clock times include that load). "
          f"Repository commit {html.escape(ctx['commit'])}; trisim sha256 {ctx['trisim_sha']}…, triencode sha256 "
          f"{ctx['triencode_sha']}…. Command: <code>{html.escape(ctx['command'])}</code>; {ctx['jobs']} job(s).",
          raw=True)
    cb = ctx.get("computed_by")
    if ctx["report_only"]:
        doc.p("This page was written from cached results only (--report-only)"
              + (f"; the last run that computed this set started {html.escape(cb['started'])}, computed for "
                 f"{cb['elapsed_s']:.0f} s with {cb['jobs']} job(s), load average {cb['load_start'][0]:.2f} at the "
                 f"start and {cb['load_end'][0]:.2f} at the end (command: <code>{html.escape(cb['command'])}</code>)."
                 if cb else "; the run that computed them left no record."), raw=True)
    doc.add("<p>Contents: <a href=#conventions>conventions</a> · <a href=#findings>findings</a> · "
            "<a href=#grey>greyscale</a> · <a href=#colour>colour</a> · <a href=#time>time</a> · "
            "<a href=#pictures>pictures</a> · <a href=#notes>notes, not supported, failures</a> · "
            "<a href=#files>files</a></p>")
    if partial_note:
        doc.add(partial_note)


def absent_methods(tools):
    return [m for m in METHOD_ORDER if m not in tools.methods]


def conventions_section(doc, plan, tools):
    doc.h(2, "Conventions", "conventions")
    missing_methods = absent_methods(tools)
    conv = [
        f"Methods run: {', '.join(tools.methods)} (from <code>trisim compare --help</code>)"
        + (f"; not built, so absent: {', '.join(missing_methods)}" if missing_methods else "")
        + ". Bezier and Coons run in their default (exact per-pixel) form; their <i>thesis</i> variant (step "
          "sampling 0.006 / 0.007 with sum and count buffers) is run where stated.",
        f"Engines: {', '.join(tools.engines)}"
        + ("" if "core" in tools.engines else " (the fixed-point core engine is not offered by this trisim, so "
                                              "core results are absent)") + ".",
        "Triangulations: <code>triencode</code>'s greedy insertion (Garland-Heckbert, triangles ranked by total "
        "squared error, candidates on a Gaussian-smoothed copy, sigma 1), vertex values = pixel values. Greyscale "
        "experiments encode the BT.601 luma of colour images (computed as trisim's to_grey does) and compare "
        "against that luma.",
        "Vertex counts are the thesis's for a 512x512 image; other sizes get n = round(N x W x H / 512²) (768x512: "
        "x1.5, 512x480: x0.9375). Tables and charts label rows by the thesis-scale N; the CSV files also give "
        "the actual count.",
        "Colour: a co-triangulation with T vertices (one triangulation, three values per vertex; <code>--cotri "
        "greedy</code> unless marked thesis) against separate triangulations with T/3 vertices per channel, so the "
        "totals are equal. Spaces RGB and YCbCr (JPEG BT.601, full range). Figure 6.13's Y/Cb/Cr allocations "
        "are composed from two separate encodings (the Y layer of one, the Cb and Cr layers of the other).",
        "Metrics: MSE and PSNR over all pixels and channels; SSIM as Wang et al. 2004 (11x11 Gaussian window, "
        "sigma 1.5, K1 0.01, K2 0.03, population covariance, mean of the channels) unless labelled 8x8, the "
        "thesis's box window, which every greyscale run also reports (column ssim_8x8).",
        "The triangulations are made for linear interpolation: greedy insertion ranks triangles by the error of "
        "the linear interpolant, so bilinear is the method its vertex choice serves; every other method is "
        "measured on those same vertices.",
        "Time: trisim bench's timing of the render alone (no reading, no metrics): the fastest wall time and the "
        "median CPU time over its timed renders, then the mean over images. The thesis timed 512x512 images on a "
        "1.86 GHz Core2Duo E6300 under .NET.",
    ]
    doc.add("<ul>" + "".join(f"<li>{c}</li>" for c in conv) + "</ul>")
    for note in plan.notes:
        doc.add(f'<p class=note>{html.escape(note)}</p>')



def findings_section(doc, grey, colour, ttable):
    fl = findings.grey_findings(grey) + findings.colour_findings(colour)
    tfind_table = {lab: {n: v[1] for n, v in d.items()} for lab, d in ttable.items() if "[" not in lab}  # CPU s
    timed_images = {}
    for lab, d in ttable.items():
        for n, v in d.items():
            timed_images[n] = max(timed_images.get(n, 0), v[2])
    fl += findings.time_findings(tfind_table, THESIS_TIMES, timed_images)
    doc.h(2, "Findings against the thesis", "findings")
    doc.p("Each line quotes a conclusion of the thesis and sets the numbers measured here beside it; the verdict "
          "is computed from the share of cases that agree (at least 75%: agrees; over 50%: mostly agrees; 25-50%: "
          f"mixed; under 25%: disagrees). A verdict needs at least {findings.MIN_CASES} cases (the column "
          "<i>cases</i> counts them; what a case is, the line says): below that it reads <i>not enough data</i>. "
          "A claim the thesis makes about one image (Fruits, Lena) is not compared when that image is not in "
          "the set.", raw=True)
    doc.table(["topic", "thesis", "here", "cases", "verdict"],
              [[html.escape(f["topic"]), html.escape(f["thesis"]), html.escape(f["here"]), str(f.get("cases", "–")),
                f'<span class="{f["verdict"].split()[0]}">{html.escape(f["verdict"])}</span>'] for f in fl],
              cls="findings")


def greyscale_section(doc, grey, plan, chart_dir):
    doc.h(2, "Greyscale images (thesis 6.1.1)", "grey")
    images = sorted({(r["image"], r["group"], r["width"], r["height"]) for r in grey})
    doc.p(f"{len(images)} image{'s' if len(images) != 1 else ''}: "
          + ", ".join(f"{i} ({g}, {w}x{h})" for i, g, w, h in images) + ". Counts: "
          + ", ".join(f"{n:,}" for n in plan.grey_counts) + " (thesis scale).")
    ok_grey = [r for r in grey if r["status"] == "ok"]
    ref_grey = [r for r in ok_grey if r["engine"] == "reference"]
    grey_bar_charts(doc, ref_grey, plan, chart_dir)
    grey_count_charts(doc, ref_grey, chart_dir)
    grey_tables(doc, ok_grey, images, plan)
    engines_section(doc, ok_grey, plan, chart_dir)


def grey_bar_charts(doc, ref_grey, plan, chart_dir):
    """Like figures 6.1-6.8: the metrics per method at each count, and per featured image."""
    for n in plan.grey_counts:
        sel = [r for r in ref_grey if r["nominal_vertices"] == n]
        if not sel:
            continue
        per = defaultdict(lambda: defaultdict(list))
        for r in sel:
            for m in ("mse", "psnr", "ssim", "ssim_8x8"):
                if r.get(m) is not None:
                    per[label(r["method"], r["variant"], r["engine"])][m].append(float(r[m]))
        per = {k: per[k] for k in order_labels(per)}
        count = len({r["image"] for r in sel})
        scope = (f"mean over {count} images, whiskers min..max" if count > 1 else
                 f"{sel[0]['image']} ({sel[0]['vertices']} vertices here)")
        path = charts.method_bars(chart_dir / f"grey_bars_{n}.png",
                                  f"Greyscale, {n:,} vertices (thesis scale): {scope}", per)
        doc.img(path, f"Like figures 6.1, 6.2, 6.4, 6.7, 6.8: MSE, PSNR and SSIM per method at {n:,} vertices.")
    # Featured images on their own, unless they are the only image (the charts above are theirs).
    featured = [img for img, lab, n in plan.picture_cases if lab == "grey"]
    if len({r["image"] for r in ref_grey}) <= 1:
        featured = []
    for img in featured:
        for n in plan.grey_counts[:1] + [c for c in plan.grey_counts if c == 5000]:
            sel = [r for r in ref_grey if r["image"] == img and r["nominal_vertices"] == n]
            if not sel:
                continue
            per = {label(r["method"], r["variant"], r["engine"]): {m: [float(r[m])] for m in ("mse", "psnr", "ssim")
                                                                    if r.get(m) is not None} for r in sel}
            per = {k: per[k] for k in order_labels(per)}
            path = charts.method_bars(chart_dir / f"grey_bars_{img}_{n}.png",
                                      f"{img}, {n:,} vertices (thesis scale; {sel[0]['vertices']} here)", per,
                                      spread=False)
            doc.img(path, f"{img} at {n:,} vertices.")


def grey_count_charts(doc, ref_grey, chart_dir):
    """Like figure 6.11: PSNR and SSIM against the vertex count."""
    series = defaultdict(lambda: defaultdict(list))
    by = defaultdict(lambda: defaultdict(list))
    for r in ref_grey:
        for m in ("psnr", "ssim", "ssim_8x8"):
            if r.get(m) is not None:
                by[(label(r["method"], r["variant"], r["engine"]), m)][r["nominal_vertices"]].append(float(r[m]))
    for (lab, m), d in by.items():
        series[lab][m] = [(n, float(np.mean(v))) for n, v in d.items()]
    series = {k: series[k] for k in order_labels(series)}
    names = sorted({r["image"] for r in ref_grey})
    scope = f"mean over {len(names)} images" if len(names) > 1 else (names[0] if names else "")
    if series:
        path = charts.lines_vs_count(chart_dir / "grey_vs_vertices.png",
                                     f"Greyscale ({scope}) against the vertex count", series,
                                     metrics=("psnr", "ssim", "ssim_8x8"), hline=30)
        doc.img(path, "Like figure 6.11: PSNR and SSIM against the vertex count (dotted: 30 dB).")
    for img in [i for i in ("fruits",) if any(r["image"] == i for r in ref_grey)]:
        s2 = defaultdict(dict)
        for r in ref_grey:
            if r["image"] == img:
                for m in ("psnr", "ssim"):
                    s2[label(r["method"], r["variant"], r["engine"])].setdefault(m, []).append(
                        (r["nominal_vertices"], float(r[m])))
        s2 = {k: s2[k] for k in order_labels(s2)}
        path = charts.lines_vs_count(chart_dir / f"grey_vs_vertices_{img}.png",
                                     f"{img} (the thesis's figure 6.11 image)", s2, hline=30)
        doc.img(path, f"Figure 6.11's image: {img}.")


def grey_tables(doc, ok_grey, images, plan):
    """Mean PSNR / SSIM per method and count, and per image at the middle count."""
    labs = order_labels({label(r["method"], r["variant"], r["engine"]) for r in ok_grey})
    trs = []
    for lab in labs:
        cells = [html.escape(lab)]
        for n in plan.grey_counts:
            sel = [r for r in ok_grey if label(r["method"], r["variant"], r["engine"]) == lab
                   and r["nominal_vertices"] == n]
            cells.append(f"{fmt(mean_of(sel, 'psnr'), 2)} / {fmt(mean_of(sel, 'ssim'))} / "
                         f"{fmt(mean_of(sel, 'ssim_8x8'))}" if sel else "–")
        trs.append(cells)
    scope = "mean over the images" if len(images) > 1 else (images[0][0] if images else "")
    doc.p(f"PSNR [dB] / SSIM (Gaussian) / SSIM (8x8) ({scope}), per vertex count:")
    doc.table(["method"] + [f"{n:,}" for n in plan.grey_counts], trs)
    if len(images) <= 1:
        return  # the table above is the one image's
    mid = 5000 if 5000 in plan.grey_counts else plan.grey_counts[len(plan.grey_counts) // 2]
    per_image = []
    for img, group, w, h in images:
        cells = [html.escape(img)]
        sel = {label(r["method"], r["variant"], r["engine"]): r for r in ok_grey
               if r["image"] == img and r["nominal_vertices"] == mid}
        best = max((float(r["psnr"]) for r in sel.values() if r.get("psnr") is not None), default=None)
        for lab in labs:
            r = sel.get(lab)
            if r is None:
                cells.append("–")
                continue
            text = f"{fmt(r['psnr'], 2)} / {fmt(r['ssim'])}"
            cells.append(f"<b>{text}</b>" if best is not None and r.get("psnr") == best else text)
        per_image.append(cells)
    doc.p(f"Per image at {mid:,} vertices (thesis scale): PSNR [dB] / SSIM (Gaussian); the best PSNR in bold.",
          raw=True)
    doc.table(["image"] + labs, per_image)


def notes_section(doc, rows, trows, tools, partial_note):
    doc.h(2, "Notes, combinations not supported and failures", "notes")
    if partial_note:
        doc.add(partial_note)
    # A method an engine does not offer is refused by trisim with a usage error: listed once per
    # method and engine as "not supported". Anything else that did not succeed is a failure.
    unsupported = {}
    failed = defaultdict(list)
    for r, what in [(r, f"{r['image']} {r['colour']} {r['nominal_vertices']}") for r in rows] + \
                   [(r, f"{r['image']} {r['nominal_vertices']} (timing)") for r in trows]:
        if r["status"] == "unsupported":
            unsupported.setdefault(label(r["method"], r["variant"], r["engine"]), r["error"] or "")
        elif r["status"] not in ("ok", "missing"):
            failed[(r["status"], label(r["method"], r["variant"], r["engine"]), r["error"])].append(what)
    if unsupported:
        doc.p("Not supported (the engine does not offer the method; every case of these is skipped): "
              + "; ".join(f"<b>{html.escape(m)}</b> ({html.escape(e)})" for m, e in sorted(unsupported.items()))
              + ".", raw=True)
    doc.h(3, "Failures")
    if not failed:
        doc.p("None: every run that was computed succeeded." if partial_note else "None: every run succeeded.")
    else:
        doc.table(["status", "method", "message", "cases"],
                  [[html.escape(s), html.escape(m), html.escape(e or ""),
                    f"{len(c)}: " + html.escape(", ".join(c[:6]) + (" …" if len(c) > 6 else ""))]
                   for (s, m, e), c in sorted(failed.items())])
    if absent_methods(tools):
        doc.p("Methods not built by this trisim (so absent from every table): " + ", ".join(absent_methods(tools))
              + ".")


def files_section(doc):
    doc.h(2, "Files", "files")
    files = ["results.csv", "greyscale.csv", "colour.csv", "time.csv", "time_runs.csv"]
    doc.add("<ul>" + "".join(f'<li><a href="{f}">{f}</a></li>' for f in files)
            + "<li>charts/*.png, pictures/*.jpg and *.png: the figures above</li>"
            "<li>cache/: triangulations and results, reused by the next run unless --force</li></ul>")


def write_report(out_dir: Path, plan, tools, executor, work, timing, ctx):
    out_dir = Path(out_dir)
    chart_dir = out_dir / "charts"
    pic_dir = out_dir / "pictures"
    rows = quality_rows(work, executor)
    trows = time_rows(timing, executor)
    grey = [r for r in rows if r["study"] == "grey"]
    colour = [r for r in rows if r["study"] in ("colour", "split")]
    write_csv(out_dir / "results.csv", rows, FIELDS)
    write_csv(out_dir / "greyscale.csv", grey, FIELDS)
    write_csv(out_dir / "colour.csv", colour, FIELDS)
    write_csv(out_dir / "time_runs.csv", trows, TIME_FIELDS)
    ttable = time_table(trows)
    write_time_csv(out_dir, ttable)
    partial_note = partial_note_html(rows, trows)

    doc = Html()
    header_section(doc, plan, ctx, partial_note)
    conventions_section(doc, plan, tools)
    findings_section(doc, grey, colour, ttable)
    greyscale_section(doc, grey, plan, chart_dir)
    colour_section(doc, [r for r in colour if r["status"] == "ok"], plan, chart_dir)
    time_section(doc, ttable, trows, plan, chart_dir)
    pictures_section(doc, rows, plan, pic_dir)
    notes_section(doc, rows, trows, tools, partial_note)
    files_section(doc)
    doc.add("</body></html>")
    atomic_write_text(out_dir / "index.html", "\n".join(doc.parts))
    for folder in (chart_dir, pic_dir):
        if folder.is_dir():
            for f in folder.iterdir():
                if f.suffix in (".png", ".jpg") and f.resolve() not in charts.WRITTEN:
                    f.unlink()  # a figure of an earlier run that this run did not draw


METHOD_ORDER = ["bilinear", "zienkiewicz", "bezier", "coons", "voronoi", "natural", "clough-tocher"]


def order_labels(labels):
    def key(lab):
        base = lab.split(" ")[0]
        return (METHOD_ORDER.index(base) if base in METHOD_ORDER else len(METHOD_ORDER), lab)
    return sorted(labels, key=key)


def engines_section(doc, ok_grey, plan, chart_dir):
    engines = sorted({r["engine"] for r in ok_grey} - {"reference"})
    doc.h(3, "Engines")
    if not engines:
        doc.p("Only the reference engine produced results; the fixed-point core engine is compared here once "
              "trisim offers it (--engine core).")
        return
    ref = {(r["image"], r["nominal_vertices"], r["method"]): r for r in ok_grey
           if r["engine"] == "reference" and not r["variant"]}
    rows = []
    series = defaultdict(lambda: defaultdict(list))
    for eng in engines:
        for r in ok_grey:
            if r["engine"] != eng:
                continue
            base = ref.get((r["image"], r["nominal_vertices"], r["method"]))
            if base is None or r.get("psnr") is None or base.get("psnr") is None:
                continue
            d = float(r["psnr"]) - float(base["psnr"])
            series[f"{r['method']} [{eng}]"][r["nominal_vertices"]].append(d)
            rows.append((eng, r["method"], r["nominal_vertices"], d, float(r["ssim"]) - float(base["ssim"])))
    direct = defaultdict(lambda: defaultdict(list))
    for r in ok_grey:
        if r["engine"] != "reference" and r.get("max_abs_diff_vs_reference") is not None:
            direct[f"{r['method']} [{r['engine']}]"][r["nominal_vertices"]].append(
                (float(r["max_abs_diff_vs_reference"]),
                 float(r["psnr_vs_reference"]) if r.get("psnr_vs_reference") is not None else float("inf")))
    table = []
    for lab, d in series.items():
        for n, vals in sorted(d.items()):
            dv = direct.get(lab, {}).get(n, [])
            table.append([html.escape(lab), f"{n:,}", f"{np.mean(vals):+.4f}", f"{np.min(vals):+.4f}",
                          f"{np.max(vals):+.4f}",
                          f"{max(x[0] for x in dv):.0f}" if dv else "–",
                          f"{min(x[1] for x in dv):.2f}" if dv else "–", str(len(vals))])
    doc.p("Each engine against the reference engine on the same triangulations (greyscale): PSNR against the "
          "original minus the reference's (dB), and, as trisim reports them, the largest absolute pixel difference "
          "from the reference render and the lowest PSNR of the engine's render against the reference render:")
    doc.table(["method [engine]", "vertices", "mean ΔPSNR", "min ΔPSNR", "max ΔPSNR", "max |core - reference|",
               "min PSNR vs reference", "images"], table)


def colour_section(doc, ok, plan, chart_dir):
    doc.h(2, "Colour images (thesis 6.1.2, 6.1.3)", "colour")
    if not ok:
        doc.p("No colour results.")
        return
    col = [r for r in ok if r["study"] == "colour" and r["engine"] == "reference" and not r["variant"]]
    images = sorted({(r["image"], r["width"], r["height"]) for r in col})
    doc.p(f"{len(images)} image{'s' if len(images) != 1 else ''}: "
          + ", ".join(f"{i} ({w}x{h})" for i, w, h in images) + ". Totals (thesis scale): "
          + ", ".join(f"{n:,}" for n in plan.colour_totals) + ".")
    methods = order_labels({r["method"] for r in col})
    over = f"mean over {len(images)} images" if len(images) > 1 else (images[0][0] if images else "")
    # 6.12: separate RGB, per method, per total.
    for mode_label in ("separate-rgb", "separate-ycbcr", "co-rgb", "co-ycbcr"):
        vals = {}
        for n in plan.colour_totals:
            for m in methods:
                sel = [r for r in col if r["colour"] == mode_label and r["nominal_vertices"] == n and r["method"] == m]
                if sel:
                    vals[(f"{n:,}", m)] = {"psnr": mean_of(sel, "psnr"), "ssim": mean_of(sel, "ssim")}
        if vals:
            path = charts.grouped_bars(chart_dir / f"colour_methods_{mode_label}.png",
                                       f"{mode_label} ({over}) per total vertex count",
                                       [f"{n:,}" for n in plan.colour_totals], methods, vals,
                                       xlabel="total vertices (thesis scale)")
            cap = "Like figure 6.12" if mode_label == "separate-rgb" else "As figure 6.12"
            doc.img(path, f"{cap}: each method on {mode_label} triangulations.")
    # 6.13: Y vs CbCr allocation.
    split = [r for r in ok if r["study"] == "split" and r["engine"] == "reference" and not r["variant"]]
    if split:
        groups = []
        for ny, nc in plan.splits:
            g = f"Y{ny}/C{nc}"
            groups.append(g)
        vals = {}
        for g in groups:
            for m in methods:
                sel = [r for r in split if r["method"] == m and r["colour"].endswith(" " + g)]
                if sel:
                    vals[(g, m)] = {"psnr": mean_of(sel, "psnr"), "ssim": mean_of(sel, "ssim")}
        path = charts.grouped_bars(chart_dir / "colour_ycbcr_split.png",
                                   f"Separate YCbCr: vertices in Y against Cb and Cr (thesis scale; {over})",
                                   groups, methods, vals)
        doc.img(path, "Like figure 6.13: Y with 3,000 or 7,000 vertices, Cb and Cr with 1,000 or 20,000 each "
                      "(scaled by area).")
    # 6.14 and 6.17-6.20: modes against each other for bilinear and zienkiewicz.
    modes = [m for m in ("separate-rgb", "separate-ycbcr", "co-rgb", "co-ycbcr", "co-rgb-thesis")
             if any(r["colour"] == m for r in col)]
    for m in [x for x in ("zienkiewicz", "bilinear") if x in methods]:
        vals = {}
        for n in plan.colour_totals:
            for mode in modes:
                sel = [r for r in col if r["colour"] == mode and r["nominal_vertices"] == n and r["method"] == m]
                if sel:
                    vals[(f"{n:,}", mode)] = {"psnr": mean_of(sel, "psnr"), "ssim": mean_of(sel, "ssim")}
        path = charts.grouped_bars(chart_dir / f"colour_modes_{m}.png",
                                   f"{m}: separate against co-triangulation, RGB against YCbCr (equal totals)",
                                   [f"{n:,}" for n in plan.colour_totals], modes, vals, colours=MODE_COLOURS,
                                   xlabel="total vertices (thesis scale)")
        doc.img(path, f"Like figures 6.14 and 6.17-6.20, {m}: PSNR and SSIM ({over}).")
    # Per image like 6.17-6.20 (RGB), at the largest total with both.
    for img, _, _ in images:
        for space in ("rgb",):
            totals = [n for n in plan.colour_totals
                      if any(r["image"] == img and r["colour"] == f"separate-{space}" and r["nominal_vertices"] == n
                             for r in col)
                      and any(r["image"] == img and r["colour"] == f"co-{space}" and r["nominal_vertices"] == n
                              for r in col)]
            if not totals:
                continue
            n = totals[len(totals) // 2]
            vals = {}
            for m in methods:
                for mode, name in ((f"separate-{space}", "separate"), (f"co-{space}", "co-triangulation")):
                    sel = [r for r in col if r["image"] == img and r["colour"] == mode and r["nominal_vertices"] == n
                           and r["method"] == m]
                    if sel:
                        vals[(m, name)] = {"psnr": mean_of(sel, "psnr"), "ssim": mean_of(sel, "ssim")}
            path = charts.grouped_bars(chart_dir / f"colour_sep_co_{img}_{space}_{n}.png",
                                       f"{img} ({space.upper()}): separate (3 x {n // 3:,}) against co-triangulation "
                                       f"({n:,}), thesis scale", methods, ["separate", "co-triangulation"], vals,
                                       colours=SEP_CO_COLOURS)
            doc.img(path, f"Like figures 6.17-6.20: {img}, separate (blue) against co-triangulation (red).")
    # Table.
    trs = []
    for mode in modes:
        for m in [x for x in ("bilinear", "zienkiewicz", "natural") if x in methods]:
            cells = [html.escape(mode), html.escape(m)]
            for n in plan.colour_totals:
                sel = [r for r in col if r["colour"] == mode and r["nominal_vertices"] == n and r["method"] == m]
                cells.append(f"{fmt(mean_of(sel, 'psnr'), 2)} / {fmt(mean_of(sel, 'ssim'))}" if sel else "–")
            trs.append(cells)
    doc.p(f"PSNR [dB] / SSIM (Gaussian) ({over}), per total vertex count (thesis scale):")
    doc.table(["triangulation", "method"] + [f"{n:,}" for n in plan.colour_totals], trs)


def time_section(doc, ttable, trows, plan, chart_dir):
    doc.h(2, "Time (thesis 6.2)", "time")
    if not ttable:
        doc.p("No timing results.")
        return
    images = sorted({(r["image"], r["width"], r["height"]) for r in trows if r["status"] == "ok"})
    loads = [r["load1"] for r in trows if r.get("load1") is not None]
    doc.p(f"Images: {', '.join(f'{i} ({w}x{h})' for i, w, h in images)}. Each time is trisim's own timing of "
          f"the render alone (<code>trisim bench</code>: a warm-up render, then {plan.time_repeats} timed renders "
          f"per default method and 1 for the thesis variants; no file reading, no metrics): the fastest wall time "
          f"and the median CPU time, then the mean over images. Wall time on this shared machine includes "
          f"waiting for the CPU (load average during the timing runs: median "
          f"{np.median(loads) if loads else float('nan'):.2f} on {os.cpu_count()} CPUs); CPU time does not. The "
          f"thesis's seconds (figure 6.22, 1.86 GHz Core2Duo E6300, .NET) are given where it timed that count.",
          raw=True)
    labs = order_labels(ttable)
    trs = []
    for n in sorted({n for d in ttable.values() for n in d}):
        for lab in labs:
            here = ttable[lab].get(n)
            if not here:
                continue
            th = THESIS_TIMES.get(lab.split(" ")[0], {}).get(n) if "[" not in lab else None
            trs.append([f"{n:,}", html.escape(lab), fmt(here[0], 4), fmt(here[1], 4), fmt(th, 4) if th else "–",
                        f"{th / here[1]:.0f}x" if th and here[1] else "–", str(here[2])])
    doc.table(["vertices", "method", "wall s (fastest)", "CPU s (median)", "thesis s", "thesis ÷ CPU",
               "images"], trs)
    ours = {lab: [(n, v[1]) for n, v in d.items()] for lab, d in ttable.items()}
    thesis = {m: list(d.items()) for m, d in THESIS_TIMES.items()}
    path = charts.time_chart(chart_dir / "time.png", "Seconds per 512x512 image: render CPU time here (solid) "
                                                     "and the thesis (dashed)", ours, thesis)
    doc.img(path, "Like figure 6.22, as a chart (log scale): the CPU time of the render here against the thesis.")


def dark_edge_rows(image, limit=8):
    """The number of rows at the bottom of `image` that are black (every value below 2), up to limit."""
    rows = 0
    while rows < min(limit, image.shape[0] - 1) and int(np.asarray(image[image.shape[0] - 1 - rows]).max()) < 2:
        rows += 1
    return rows


def pictures_section(doc, rows, plan, pic_dir):
    doc.h(2, "Pictures", "pictures")
    doc.p("The triangulation over the image, the Voronoi diagram of its vertices (scipy.spatial.Voronoi), each "
          "method's render (reference engine) and its absolute error (mean over channels; one colour scale, "
          f"clipped at {pictures.ERROR_VMAX}). Two details are chosen from the data: where the patch methods "
          "lose most against bilinear, and where triangles of very different sizes meet (the thesis's explanation "
          "of the patch artifacts).")
    for img, lab, nominal in plan.picture_cases:
        sel = [r for r in rows if r["image"] == img and r["colour"] == lab and r["nominal_vertices"] == nominal
               and r["study"] in ("grey", "colour") and r["engine"] == "reference" and not r["variant"]
               and r["status"] == "ok" and r.get("_render") and Path(r["_render"]).exists()]
        if not sel:
            doc.p(f"{img} {lab} {nominal:,}: no renders available.")
            continue
        tri = trifile.read_tri(sel[0]["_tri"])
        original = load_image(sel[0]["_original"])
        stem = f"{img}_{lab}_{nominal}"
        h, w = original.shape[:2]
        doc.h(3, f"{img}, {lab}, {nominal:,} vertices (thesis scale; {tri.vertex_count():,} here, {w}x{h})")
        path = pictures.triangulation_figure(pic_dir / f"{stem}_triangulation.jpg", tri, original,
                                             f"{img}: triangulation ({lab})")
        doc.img(path, "The triangulation over the image" + (" (each layer in its own colour)"
                                                             if len(tri.layers) > 1 else "") + ".")
        path = pictures.voronoi_figure(pic_dir / f"{stem}_voronoi.jpg", tri, original, f"{img}: Voronoi diagram")
        doc.img(path, "The Voronoi diagram of the vertices.")
        renders = {}
        for m in order_labels({r["method"] for r in sel}):
            r = next(x for x in sel if x["method"] == m)
            stats = f"PSNR {fmt(r['psnr'], 2)} dB, SSIM {fmt(r['ssim'])}"
            renders[m] = (load_image(r["_render"]), stats)
        path = pictures.renders_figure(pic_dir / f"{stem}_renders.jpg", original, renders,
                                       f"{img} ({lab}, {tri.vertex_count():,} vertices): renders and absolute errors")
        doc.img(path, "Each method's render and its absolute error.")
        dark = dark_edge_rows(original)
        if dark:
            doc.add("<p class=note>" + html.escape(
                f"The shipped {img}.png has {'a black last row' if dark == 1 else f'{dark} black last rows'}: the "
                f"bright line along the bottom of the error maps comes from the image, not from the methods (no "
                f"triangulation follows a line that thin). The metrics include {'it' if dark == 1 else 'them'}.")
                    + "</p>")
        windows = [("artifacts", pictures.excess_error_window(original, renders, 112),
                    "the window where Bezier and Coons exceed bilinear's absolute error the most"),
                   ("sizes", pictures.detail_window(tri, w, h, 112),
                    "the window where neighbouring triangles differ most in area (border triangles left out)")]
        for name, window, why in windows:
            if window is None:
                continue
            path = pictures.detail_figure(pic_dir / f"{stem}_detail_{name}.png", original, tri, renders, window,
                                          f"{img}: detail at x={window[0]}, y={window[1]} "
                                          f"({window[2]}x{window[3]})")
            doc.img(path, f"Detail (zoomed), {why}: original, triangulation, each method, and the absolute "
                          f"errors.")
