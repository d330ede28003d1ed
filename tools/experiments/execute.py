# SPDX-License-Identifier: MIT
"""Turning a plan into cached results: derived inputs, encodings, quality runs and timing runs."""
import json
import os
import shutil
import tempfile
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional

import numpy as np

import trifile
from pictures import neighbour_contrast
from plan import Enc, Source
from runner import Cache, EXIT_USAGE, Tools, atomic_write_bytes, atomic_write_text, file_sha256, first_line, \
    key_of, run_tool

# Bump when the analysis stored with a quality run changes, so cached runs are recomputed.
ANALYSIS_VERSION = 1
# Methods whose per-pixel error is analysed by triangle size contrast (the patch-artifact finding).
ANALYSED_METHODS = ("bilinear", "bezier", "coons")
ENCODE_TIMEOUT = 3600
RENDER_TIMEOUT = 3600


@dataclass(frozen=True)
class Run:
    enc: Enc
    method: str
    variant: str
    engine: str
    keep_render: bool = False
    analyse: bool = False


@dataclass(frozen=True)
class TimeRun:
    enc: Enc
    method: str
    variant: str
    engine: str
    runs: int  # timed renders of one `trisim bench` call


def luma(rgb: np.ndarray) -> np.ndarray:
    """BT.601 luma rounded half away from zero, as host_sim/model/image.cpp's to_grey."""
    y = 0.299 * rgb[..., 0] + 0.587 * rgb[..., 1] + 0.114 * rgb[..., 2]
    return np.floor(np.minimum(255.0, y) + 0.5).astype(np.uint8)


def load_image(path) -> np.ndarray:
    from PIL import Image
    with Image.open(path) as im:
        return np.asarray(im.convert("L" if im.mode == "L" else "RGB"))


def png_bytes(array: np.ndarray) -> bytes:
    import io
    from PIL import Image
    buf = io.BytesIO()
    Image.fromarray(array).save(buf, format="PNG")
    return buf.getvalue()


class Executor:
    def __init__(self, tools: Tools, cache: Cache, progress):
        self.tools = tools
        self.cache = cache
        self.progress = progress
        self.locks: Dict[str, threading.Lock] = {}
        self.locks_lock = threading.Lock()
        self.enc_results: Dict[Enc, dict] = {}
        self.run_results: Dict[Run, dict] = {}
        self.time_results: Dict[TimeRun, dict] = {}
        # (method, variant, engine) combinations trisim refused (exit 64) in this run, with its message:
        # later runs of the same combination are skipped instead of asking again.
        self.unsupported: Dict[tuple, str] = {}

    def _lock(self, key):
        with self.locks_lock:
            return self.locks.setdefault(key, threading.Lock())

    def input_image(self, source: Source, grey: bool) -> Path:
        """The file triencode and trisim read: the original, its luma, or a crop (derived once)."""
        if not grey and source.crop is None:
            return source.path
        if grey and source.channels == 1 and source.crop is None:
            return source.path
        desc = {"kind": "derived", "image": file_sha256(source.path), "grey": grey, "crop": source.crop}
        key = key_of(desc)
        out = self.cache.path("images", key, ".png")
        with self._lock(key):
            if not out.exists():
                pixels = load_image(source.path)
                if source.crop:
                    x, y, w, h = source.crop
                    pixels = pixels[y:y + h, x:x + w]
                if grey and pixels.ndim == 3:
                    pixels = luma(pixels)
                atomic_write_bytes(out, png_bytes(np.ascontiguousarray(pixels)))
        return out

    def encode(self, enc: Enc) -> dict:
        if enc in self.enc_results:
            return self.enc_results[enc]
        if self.cache.offline:
            result = self._encode_cached_only(enc)
        elif enc.mode == "split":
            result = self._compose_split(enc)
        else:
            result = self._encode_plain(enc)
        self.enc_results[enc] = result
        return result

    def _encode_args(self, enc: Enc, image: Path, out: Path, space_override=None, n=None):
        args = [self.tools.triencode, image, "-n", n or enc.n, "-o", out, "--json", "-q"]
        if enc.mode in ("co", "separate"):
            args += ["--color", enc.mode, "--space", space_override or enc.space]
            if enc.mode == "co":
                args += ["--cotri", enc.cotri]
        return args

    def _encode_desc(self, enc: Enc, image: Path, mode=None, n=None):
        return {"kind": "encode", "tool": self.tools.triencode_sha, "image": file_sha256(image),
                "mode": mode or enc.mode, "space": enc.space, "n": n or enc.n,
                "cotri": enc.cotri if (mode or enc.mode) == "co" else None}

    def _encode_plain(self, enc: Enc, mode=None, n=None) -> dict:
        image = self.input_image(enc.source, enc.grey)
        desc = self._encode_desc(enc, image, mode, n)
        key = key_of(desc)
        tri_path = self.cache.path("tri", key, ".tri")
        with self._lock(key):
            cached = self.cache.load("enc", key)
            if cached is not None and (cached["status"] != "ok" or tri_path.exists()):
                return cached
            if self.cache.offline:
                return {"status": "missing", "error": "not in the cache"}
            tri_path.parent.mkdir(parents=True, exist_ok=True)
            e = Enc(**{**enc.__dict__, "mode": mode or enc.mode, "n": n or enc.n})
            code, out, err, cpu = run_tool(self._encode_args(e, image, tri_path), timeout=ENCODE_TIMEOUT)
            result = {"key": key, "tri": str(tri_path), "image_file": str(image), "cpu_s": cpu}
            if code == 0:
                try:
                    summary = json.loads(out.strip().splitlines()[-1])
                    result.update(status="ok", vertices=summary.get("vertices"), triangles=summary.get("triangles"),
                                  seconds=summary.get("seconds"), psnr_linear=summary.get("psnr_linear"))
                except (ValueError, IndexError) as exc:
                    result.update(status="failed", error=f"triencode printed no JSON summary ({exc})")
            else:
                result.update(status="failed", error=f"triencode exit {code}: {first_line(err)}")
            self.cache.store("enc", key, result)
            return result

    def _compose_split(self, enc: Enc) -> dict:
        """Separate YCbCr triangulations with n_y vertices in Y and n_c in each of Cb and Cr,
        composed from two triencode runs (its -n is one count for all three layers)."""
        n_y, n_c = enc.parts
        a = self._encode_plain(enc, mode="separate", n=n_y)
        b = self._encode_plain(enc, mode="separate", n=n_c)
        desc = {"kind": "split", "y": a.get("key"), "c": b.get("key"), "version": 1}
        key = key_of(desc)
        tri_path = self.cache.path("tri", key, ".tri")
        with self._lock(key):
            cached = self.cache.load("enc", key)
            if cached is not None and (cached["status"] != "ok" or tri_path.exists()):
                return cached
            result = {"key": key, "tri": str(tri_path), "image_file": a.get("image_file")}
            if a["status"] != "ok" or b["status"] != "ok":
                result.update(status="missing" if "missing" in (a["status"], b["status"]) else "failed",
                              error=a.get("error") or b.get("error"))
                if result["status"] == "missing":
                    return result
            else:
                ta, tb = trifile.read_tri(a["tri"]), trifile.read_tri(b["tri"])
                layers = [ta.layers[0], tb.layers[1], tb.layers[2]]
                atomic_write_text(tri_path, trifile.write_layered(ta.width, ta.height, "ycbcr", layers))
                result.update(status="ok", vertices=sum(len(l.points) for l in layers),
                              triangles=sum(len(l.triangles) for l in layers))
            self.cache.store("enc", key, result)
            return result

    def _encode_cached_only(self, enc: Enc) -> dict:
        try:
            if enc.mode == "split":
                return self._compose_split(enc)
            image = self.input_image(enc.source, enc.grey)
            key = key_of(self._encode_desc(enc, image))
        except OSError as exc:
            return {"status": "missing", "error": str(exc)}
        cached = self.cache.load("enc", key)
        return cached if cached else {"status": "missing", "error": "not in the cache"}

    def _run_desc(self, run, enc_result, original: Path, purpose: str, rep: int = 0):
        desc = {"kind": purpose, "tool": self.tools.trisim_sha, "tri": file_sha256(enc_result["tri"]),
                "original": file_sha256(original), "method": run.method, "variant": run.variant,
                "engine": run.engine}
        if purpose == "quality":
            desc["analysis"] = ANALYSIS_VERSION if run.analyse else None
        else:
            desc["rep"] = rep
        return desc

    def process(self, enc: Enc, runs: List[Run]):
        """Encodes enc and performs its quality runs, ticking the progress bar once per item.
        Runs missing from the cache are rendered by one trisim call per (variant, engine)."""
        e = self.encode(enc)
        self.progress.update(1)
        pending = {}
        for run in runs:
            if e["status"] != "ok":
                self.run_results[run] = {"status": "failed" if e["status"] == "failed" else "missing",
                                         "error": "encoding: " + str(e.get("error"))}
                self.progress.update(1)
                continue
            original = Path(e["image_file"])
            key = key_of(self._run_desc(run, e, original, "quality"))
            render_path = self.cache.path("renders", key, ".png")
            cached = self.cache.load("runs", key)
            if cached is not None and (not run.keep_render or cached["status"] != "ok" or render_path.exists()):
                self.run_results[run] = cached
                self.progress.update(1)
            elif self.cache.offline:
                self.run_results[run] = {"status": "missing", "error": "not in the cache"}
                self.progress.update(1)
            elif (run.method, run.variant, run.engine) in self.unsupported:
                self.run_results[run] = {"status": "unsupported",
                                         "error": self.unsupported[(run.method, run.variant, run.engine)]}
                self.progress.update(1)
            else:
                pending.setdefault((run.variant, run.engine), []).append((run, key, render_path))
        geometry = None
        for (variant, engine), batch in pending.items():
            if geometry is None and any(run.analyse for run, _, _ in batch):
                geometry = TriangleGeometry(e["tri"])
            self._quality_batch(e, Path(e["image_file"]), variant, engine, batch, geometry)

    def _compare(self, e, original, methods, variant, engine, save_dir):
        args = [self.tools.trisim, "compare", e["tri"], "--method", *methods, "--engine", engine,
                "--original", original, "--json", "--save", save_dir]
        if variant:
            args += ["--variant", variant]
        return run_tool(args, timeout=RENDER_TIMEOUT * len(methods))

    def _quality_batch(self, e, original, variant, engine, batch, geometry):
        tmp = tempfile.mkdtemp(prefix="tristream-exp-")
        try:
            load = os.getloadavg()[0]
            code, out, err, cpu = self._compare(e, original, [run.method for run, _, _ in batch], variant, engine,
                                                tmp)
            lines = {}
            for line in out.splitlines():
                try:
                    j = json.loads(line)
                    lines[j["method"]] = j
                except (ValueError, KeyError, TypeError):
                    pass
            for run, key, render_path in batch:
                j = lines.get(run.method)
                # CPU seconds of the whole process, shared equally by the methods of a batch.
                sub_cpu = cpu / len(batch) if cpu is not None else None
                m_code, m_err = code, err
                if j is None and len(batch) > 1:
                    # The batch failed before this method: run it alone for its own status and message.
                    m_code, out2, m_err, sub_cpu = self._compare(e, original, [run.method], variant, engine, tmp)
                    if m_code == 0:
                        try:
                            j = json.loads(out2.strip().splitlines()[-1])
                        except (ValueError, IndexError):
                            m_err = "no JSON line in the output"
                result = {"load1": load, "cpu_s": sub_cpu, "batch": len(batch), "key": key}
                if j is None:
                    result.update(status="unsupported" if m_code == EXIT_USAGE else "failed",
                                  error=f"trisim compare exit {m_code}: {first_line(m_err)}")
                    if m_code == EXIT_USAGE:
                        self.unsupported[(run.method, run.variant, run.engine)] = result["error"]
                else:
                    result.update(status="ok", **{k: j.get(k) for k in ("mse", "psnr", "ssim", "ms", "width",
                                                                         "height", "vertices", "triangles",
                                                                         "ssim_window", "psnr_vs_reference",
                                                                         "max_abs_diff_vs_reference")
                                                   if k in j})
                    self._after_render(run, result, Path(tmp) / f"{run.method}.png", original, render_path,
                                       geometry if run.analyse else None)
                self.cache.store("runs", key, result)
                self.run_results[run] = result
                self.progress.update(1)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)

    def _after_render(self, run, result, render, original, render_path, geometry):
        if run.enc.study != "grey":
            code, out, err = None, "", ""  # the 8x8 window is the thesis's greyscale convention only
        else:
            code, out, err, _ = run_tool([self.tools.trisim, "metrics", render, original, "--ssim-window", "8x8",
                                          "--json"], timeout=RENDER_TIMEOUT)
        if code is None:
            result["ssim_8x8"] = None
        elif code == 0:
            result["ssim_8x8"] = json.loads(out.strip().splitlines()[-1])["ssim"]
        else:
            result["ssim_8x8"] = None
            result["note"] = f"trisim metrics 8x8 exit {code}: {first_line(err)}"
        if geometry is not None:
            result["analysis"] = geometry.error_by_contrast(load_image(render), load_image(original))
        if run.keep_render:
            render_path.parent.mkdir(parents=True, exist_ok=True)
            tmp_copy = render_path.with_name("." + render_path.name + ".tmp")
            shutil.copyfile(render, tmp_copy)
            os.replace(tmp_copy, render_path)
            result["render"] = str(render_path)

    def render_of(self, run: Run) -> Optional[Path]:
        r = self.run_results.get(run)
        if r and r.get("status") == "ok" and r.get("render") and Path(r["render"]).exists():
            return Path(r["render"])
        return None

    def time_run(self, t: TimeRun):
        e = self.encode(t.enc)
        if e["status"] != "ok":
            self.time_results[t] = {"status": e["status"], "error": "encoding: " + str(e.get("error"))}
            return
        if (t.method, t.variant, t.engine) in self.unsupported:
            self.time_results[t] = {"status": "unsupported", "error": self.unsupported[(t.method, t.variant,
                                                                                         t.engine)]}
            return
        original = Path(e["image_file"])
        key = key_of({**self._run_desc(t, e, original, "time", t.runs), "timer": "bench"})
        cached = self.cache.load("time", key)
        if cached is not None or self.cache.offline:
            self.time_results[t] = cached or {"status": "missing", "error": "not in the cache"}
            return
        # trisim's own timing of the render alone (after a warm-up render): the fastest wall time
        # and the median CPU time of t.runs renders, without reading files or computing metrics.
        args = [self.tools.trisim, "bench", e["tri"], "--method", t.method, "--engine", t.engine,
                "--runs", str(t.runs), "--json"]
        if t.variant:
            args += ["--variant", t.variant]
        load = os.getloadavg()[0]
        code, out, err, _ = run_tool(args, timeout=RENDER_TIMEOUT)
        result = {"load1": load, "key": key}
        if code == 0:
            j = json.loads(out.strip().splitlines()[-1])
            result.update(status="ok", ms=j["ms_min"], cpu_ms=j["cpu_ms_median"], runs=j["runs"],
                          vertices=e.get("vertices"), triangles=e.get("triangles"))
        else:
            result.update(status="unsupported" if code == EXIT_USAGE else "failed",
                          error=f"trisim bench exit {code}: {first_line(err)}")
            if code == EXIT_USAGE:
                self.unsupported[(t.method, t.variant, t.engine)] = result["error"]
        self.cache.store("time", key, result)
        self.time_results[t] = result


class TriangleGeometry:
    """Per-pixel triangle of a single-layer triangulation and each triangle's size contrast: the
    largest area ratio with an edge neighbour (>= 1). Used to test the thesis's claim that the patch
    methods show artifacts where triangles of very different sizes meet (section 6.1.1)."""

    def __init__(self, tri_path):
        import matplotlib.tri as mtri
        t = trifile.read_tri(tri_path)
        if len(t.layers) != 1 or t.layers[0].triangles is None:
            raise ValueError(f"{tri_path}: expected one layer with explicit triangles")
        layer = t.layers[0]
        pts, tris = layer.points, layer.triangles
        a, b, c = pts[tris[:, 0]], pts[tris[:, 1]], pts[tris[:, 2]]
        area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
        contrast = neighbour_contrast(tris, area)
        self.q50, self.q90 = np.quantile(contrast, [0.5, 0.9])
        finder = mtri.Triangulation(pts[:, 0], pts[:, 1], tris).get_trifinder()
        yy, xx = np.mgrid[0:t.height, 0:t.width]
        owner_px = finder(xx.ravel().astype(float), yy.ravel().astype(float)).reshape(t.height, t.width)
        inside = owner_px >= 0
        pixel_contrast = np.where(inside, contrast[np.maximum(owner_px, 0)], np.nan)
        self.high = inside & (pixel_contrast >= self.q90)
        self.low = inside & (pixel_contrast <= self.q50)

    def error_by_contrast(self, render: np.ndarray, original: np.ndarray) -> dict:
        err = np.abs(render.astype(float) - original.astype(float))
        if err.ndim == 3:
            err = err.mean(axis=2)
        return {"mae_high": float(err[self.high].mean()), "mae_low": float(err[self.low].mean()),
                "px_high": int(self.high.sum()), "px_low": int(self.low.sum()),
                "contrast_q50": float(self.q50), "contrast_q90": float(self.q90)}
