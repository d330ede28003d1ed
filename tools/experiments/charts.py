# SPDX-License-Identifier: MIT
"""Charts of the report, drawn by matplotlib (Debian's python3-matplotlib) into PNG files."""
import io
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from runner import atomic_write_bytes  # noqa: E402

PALETTE = {
    "bilinear": "#1f77b4", "zienkiewicz": "#d62728", "bezier": "#2ca02c", "bezier (thesis)": "#98df8a",
    "coons": "#9467bd", "coons (thesis)": "#c5b0d5", "voronoi": "#8c564b", "natural": "#ff7f0e",
    "clough-tocher": "#17becf",
}
EXTRA = ["#e377c2", "#7f7f7f", "#bcbd22", "#aec7e8", "#ffbb78"]
WRITTEN = set()  # every figure written by this run (the report removes older ones)
METRIC_LABEL = {"mse": "MSE", "psnr": "PSNR [dB]", "ssim": "SSIM (Gaussian 11x11)", "ssim_8x8": "SSIM (8x8 box)"}


def colour_of(name):
    if name in PALETTE:
        return PALETTE[name]
    base = name.split(" [")[0]
    if base in PALETTE:
        return PALETTE[base]
    return EXTRA[sum(map(ord, name)) % len(EXTRA)]


def save(fig, path: Path) -> Path:
    """PNG, or JPEG (quality 90) for photographic pictures named *.jpg to keep the page small."""
    buf = io.BytesIO()
    if Path(path).suffix == ".jpg":
        fig.savefig(buf, format="jpeg", dpi=100, bbox_inches="tight", pil_kwargs={"quality": 90})
    else:
        fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    plt.close(fig)
    atomic_write_bytes(path, buf.getvalue())
    WRITTEN.add(Path(path).resolve())
    return path


def _bars(ax, labels, values, errors=None, metric=""):
    x = np.arange(len(labels))
    colours = [colour_of(l) for l in labels]
    yerr = None
    if errors is not None:
        lo = [v - e[0] for v, e in zip(values, errors)]
        hi = [e[1] - v for v, e in zip(values, errors)]
        yerr = [lo, hi]
    ax.bar(x, values, color=colours, yerr=yerr, capsize=3, edgecolor="black", linewidth=0.4)
    ax.set_xticks(x)
    ax.set_xticklabels(labels, rotation=35, ha="right", fontsize=8)
    ax.set_ylabel(METRIC_LABEL.get(metric, metric))
    # Bars start at zero (a bar's length is its value), so small differences look small; the
    # tables and the CSV files give the exact values.
    finite = [v for v in values if v is not None and np.isfinite(v)]
    if finite:
        hi_lim = max(finite) if errors is None else max(e[1] for e in errors if np.isfinite(e[1]))
        ax.set_ylim(0, hi_lim * 1.08 if hi_lim > 0 else 1)
    ax.grid(axis="y", alpha=0.3)


def method_bars(path, title, per_method, metrics=("mse", "psnr", "ssim"), spread=True):
    """per_method: {label: {metric: [values over images]}}; bars of the mean, whiskers min..max."""
    labels = list(per_method)
    fig, axes = plt.subplots(1, len(metrics), figsize=(4.2 * len(metrics), 3.6))
    axes = np.atleast_1d(axes)
    for ax, metric in zip(axes, metrics):
        vals = [per_method[l].get(metric, []) for l in labels]
        means = [float(np.mean(v)) if v else np.nan for v in vals]
        errs = [(float(np.min(v)), float(np.max(v))) if v else (np.nan, np.nan) for v in vals] if spread else None
        if spread and all(len(v) <= 1 for v in vals):
            errs = None
        _bars(ax, labels, means, errs, metric)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return save(fig, path)


def lines_vs_count(path, title, series, metrics=("psnr", "ssim"), xlabel="vertices (thesis scale, 512x512)",
                   logx=False, hline=None):
    """series: {label: {metric: [(x, y), ...]}}."""
    fig, axes = plt.subplots(1, len(metrics), figsize=(5.2 * len(metrics), 3.8))
    axes = np.atleast_1d(axes)
    for ax, metric in zip(axes, metrics):
        for label, data in series.items():
            pts = sorted(p for p in data.get(metric, []) if p[1] is not None and np.isfinite(p[1]))
            if not pts:
                continue
            style = "--" if "thesis" in label and "(thesis)" not in label else "-"
            ax.plot([p[0] for p in pts], [p[1] for p in pts], style, marker="o", ms=3.5, label=label,
                    color=colour_of(label))
        if hline is not None and metric == "psnr":
            ax.axhline(hline, color="grey", lw=0.8, ls=":")
        if logx:
            ax.set_xscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(METRIC_LABEL.get(metric, metric))
        ax.grid(alpha=0.3)
    axes[-1].legend(fontsize=7, loc="best")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return save(fig, path)


def grouped_bars(path, title, groups, series_order, values, metrics=("psnr", "ssim"), colours=None,
                 xlabel=""):
    """values[(group, series)][metric] = number; one cluster of bars per group."""
    fig, axes = plt.subplots(len(metrics), 1, figsize=(max(6, 0.9 * len(groups) * len(series_order) / 2 + 3),
                                                       3.0 * len(metrics)))
    axes = np.atleast_1d(axes)
    width = 0.8 / max(1, len(series_order))
    x = np.arange(len(groups))
    for ax, metric in zip(axes, metrics):
        for i, s in enumerate(series_order):
            ys = [values.get((g, s), {}).get(metric, np.nan) for g in groups]
            ys = [np.nan if y is None else y for y in ys]
            col = (colours or {}).get(s, colour_of(s))
            ax.bar(x + (i - (len(series_order) - 1) / 2) * width, ys, width, label=s, color=col,
                   edgecolor="black", linewidth=0.3)
        ax.set_xticks(x)
        ax.set_xticklabels(groups, fontsize=8, rotation=20 if len(groups) > 5 else 0,
                           ha="right" if len(groups) > 5 else "center")
        ax.set_ylabel(METRIC_LABEL.get(metric, metric))
        finite = [v[metric] for v in values.values() if v.get(metric) is not None and np.isfinite(v[metric])]
        if finite:  # from zero, as in _bars
            ax.set_ylim(0, max(finite) * 1.08 if max(finite) > 0 else 1)
        ax.grid(axis="y", alpha=0.3)
        if xlabel:
            ax.set_xlabel(xlabel)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.suptitle(title, fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    fig.legend(handles, labels, fontsize=7, ncol=min(7, len(series_order)), loc="upper center",
               bbox_to_anchor=(0.5, 0.955), frameon=False)
    return save(fig, path)


def time_chart(path, title, ours, thesis):
    """ours/thesis: {method: [(vertices, seconds)]}; log-scale seconds."""
    fig, ax = plt.subplots(figsize=(11, 6.5))
    for label, pts in ours.items():
        pts = sorted(pts)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "-o", ms=3.5, color=colour_of(label),
                label=f"{label} (here)")
    for label, pts in thesis.items():
        pts = sorted(pts)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "--", marker="x", ms=4, color=colour_of(label),
                alpha=0.7, label=f"{label} (thesis, 2009)")
    ax.set_yscale("log")
    ax.set_xlabel("vertices (512x512 image)")
    ax.set_ylabel("seconds per image")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=9, ncol=2, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    return save(fig, path)


def collect(rows, key, metric):
    """{key(row): [row[metric] ...]} over rows with a finite metric."""
    out = defaultdict(list)
    for r in rows:
        v = r.get(metric)
        if v is None or v == "":
            continue
        v = float(v)
        if np.isfinite(v):
            out[key(r)].append(v)
    return out
