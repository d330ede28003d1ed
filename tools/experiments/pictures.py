# SPDX-License-Identifier: MIT
"""Pictures of the report: the triangulation over the image, the Voronoi diagram, each method's
render and its absolute-error heat map, full size and as a zoomed detail."""
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from scipy.ndimage import uniform_filter  # noqa: E402

import trifile  # noqa: E402
from charts import save  # noqa: E402

LAYER_COLOURS = {"grey": ["#00e5ff"], "rgb": ["#00e5ff"], "ycbcr": ["#00e5ff"],
                 "r": "#ff3030", "g": "#30d030", "b": "#3080ff", "y": "#ffffff", "cb": "#3080ff", "cr": "#ff3030"}
ERROR_VMAX = 48  # heat maps share one scale so methods can be compared by eye


def _show(ax, img, extent=None):
    if img.ndim == 2:
        ax.imshow(img, cmap="gray", vmin=0, vmax=255, interpolation="nearest", extent=extent)
    else:
        ax.imshow(img, interpolation="nearest", extent=extent)
    ax.set_xticks([])
    ax.set_yticks([])


def _mesh_lines(layer: trifile.Layer):
    tris = layer.triangles
    if tris is None:
        from scipy.spatial import Delaunay
        tris = Delaunay(layer.points).simplices
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = np.unique(np.sort(edges, axis=1), axis=0)
    return layer.points[edges]


def layer_colour(tri: trifile.TriFile, layer: trifile.Layer):
    c = LAYER_COLOURS.get(layer.name)
    return c[0] if isinstance(c, list) else (c or "#00e5ff")


def triangulation_figure(path: Path, tri: trifile.TriFile, original: np.ndarray, title: str, window=None):
    h, w = original.shape[:2]
    scale = 1.0 if window is None else 3.0
    fig_w = (w if window is None else window[2]) * scale / 100
    fig_h = (h if window is None else window[3]) * scale / 100
    fig, ax = plt.subplots(figsize=(max(3, min(fig_w, 9)), max(2, min(fig_h, 9) * (min(fig_w, 9) / fig_w))))
    _show(ax, (original * 0.7).astype(np.uint8), extent=(-0.5, w - 0.5, h - 0.5, -0.5))
    lw = 0.25 if window is None else 0.6
    for layer in tri.layers:
        ax.add_collection(LineCollection(_mesh_lines(layer), colors=layer_colour(tri, layer), linewidths=lw,
                                         alpha=0.85, label=layer.name))
    if window is not None:
        x, y, ww, hh = window
        ax.set_xlim(x - 0.5, x + ww - 0.5)
        ax.set_ylim(y + hh - 0.5, y - 0.5)
    if len(tri.layers) > 1:
        ax.legend(loc="lower right", fontsize=7, framealpha=0.6)
    ax.set_title(title, fontsize=9)
    return save(fig, path)


def voronoi_figure(path: Path, tri: trifile.TriFile, original: np.ndarray, title: str):
    """Voronoi diagram (scipy.spatial.Voronoi) of the first layer's vertices, clipped to the image."""
    from scipy.spatial import Voronoi
    h, w = original.shape[:2]
    layer = tri.layers[0]
    vor = Voronoi(layer.points)
    centre = layer.points.mean(axis=0)
    far = 2.0 * max(w, h)
    segments = []
    for (p, q), ridge in zip(vor.ridge_points, vor.ridge_vertices):
        ridge = np.asarray(ridge)
        if np.all(ridge >= 0):
            segments.append(vor.vertices[ridge])
            continue
        i = ridge[ridge >= 0][0]
        t = layer.points[q] - layer.points[p]
        n = np.array([-t[1], t[0]]) / np.linalg.norm(t)
        midpoint = (layer.points[p] + layer.points[q]) / 2
        direction = np.sign(np.dot(midpoint - centre, n)) * n
        segments.append([vor.vertices[i], vor.vertices[i] + direction * far])
    fig_w = min(w / 100, 9)
    fig, ax = plt.subplots(figsize=(fig_w, fig_w * h / w))
    shown = original if original.ndim == 2 else original
    _show(ax, (shown * 0.55 + 255 * 0.45).astype(np.uint8), extent=(-0.5, w - 0.5, h - 0.5, -0.5))
    ax.add_collection(LineCollection(segments, colors="#202020", linewidths=0.3))
    ax.plot(layer.points[:, 0], layer.points[:, 1], ".", ms=0.8, color="#d62728")
    ax.set_xlim(-0.5, w - 0.5)
    ax.set_ylim(h - 0.5, -0.5)
    extra = f" (layer {layer.name} of {len(tri.layers)})" if len(tri.layers) > 1 else ""
    ax.set_title(title + extra, fontsize=9)
    return save(fig, path)


def detail_window(tri: trifile.TriFile, width: int, height: int, size: int):
    """The size x size window (away from the border) where triangles meet neighbours of the most
    different sizes: the largest mean log area ratio with an edge neighbour over the triangles
    whose centroid lies in the window (first layer). Triangles touching the image border are
    left out: they are slivers by construction. Patch artifacts show here if anywhere."""
    layer = tri.layers[0]
    tris = layer.triangles
    if tris is None:
        from scipy.spatial import Delaunay
        tris = Delaunay(layer.points).simplices
    p = layer.points
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    contrast = neighbour_contrast(tris, area)
    on_border = np.zeros(len(p), bool)
    on_border |= (p[:, 0] <= 0) | (p[:, 1] <= 0) | (p[:, 0] >= width - 1) | (p[:, 1] >= height - 1)
    interior = ~on_border[tris].any(axis=1)
    centroid = (a + b + c) / 3
    score = np.zeros((height, width))
    count = np.zeros((height, width))
    ix = np.clip(centroid[:, 0].round().astype(int), 0, width - 1)
    iy = np.clip(centroid[:, 1].round().astype(int), 0, height - 1)
    np.add.at(score, (iy[interior], ix[interior]), np.log(contrast[interior]))
    np.add.at(count, (iy[interior], ix[interior]), 1)
    size = min(size, width, height)
    s = uniform_filter(score, size, mode="constant")
    n = uniform_filter(count, size, mode="constant") * size * size
    mean = np.where(n >= 6, s * size * size / np.maximum(n, 1e-9), -1)
    half = size // 2
    margin = min(8, (width - size) // 2, (height - size) // 2)
    # Window centres cx with margin <= cx - half and cx - half + size <= width - margin.
    valid = mean[half + margin:height - size + half - margin + 1, half + margin:width - size + half - margin + 1]
    vy, vx = np.unravel_index(np.argmax(valid), valid.shape)
    return (int(vx) + margin, int(vy) + margin, size, size)


def excess_error_window(original: np.ndarray, renders: dict, size: int, margin: int = 8):
    """The size x size window where the patch methods (bezier, coons) exceed bilinear's absolute
    error the most on average: where their artifacts are. None without those renders."""
    if "bilinear" not in renders or not any(m in renders for m in ("bezier", "coons")):
        return None
    h, w = original.shape[:2]
    size = min(size, w - 2 * margin, h - 2 * margin)
    base = abs_error(renders["bilinear"][0], original)
    excess = sum(abs_error(renders[m][0], original) - base for m in ("bezier", "coons") if m in renders)
    mean = uniform_filter(excess, size, mode="constant")
    half = size // 2
    valid = mean[half + margin:h - size + half - margin + 1, half + margin:w - size + half - margin + 1]
    vy, vx = np.unravel_index(np.argmax(valid), valid.shape)
    return (int(vx) + margin, int(vy) + margin, size, size)


def neighbour_contrast(tris: np.ndarray, area: np.ndarray) -> np.ndarray:
    """Per triangle, the largest area ratio (>= 1) with a triangle sharing an edge; 1 without one."""
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = np.sort(edges, axis=1)
    owner = np.tile(np.arange(len(tris)), 3)
    _, inverse, counts = np.unique(edges, axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()
    contrast = np.ones(len(tris))
    shared = counts[inverse] == 2
    order = np.argsort(inverse[shared], kind="stable")
    pairs = owner[shared][order].reshape(-1, 2)
    ratio = area[pairs[:, 0]] / np.maximum(area[pairs[:, 1]], 1e-12)
    ratio = np.maximum(ratio, 1.0 / np.maximum(ratio, 1e-12))
    np.maximum.at(contrast, pairs[:, 0], ratio)
    np.maximum.at(contrast, pairs[:, 1], ratio)
    return contrast


def abs_error(render: np.ndarray, original: np.ndarray) -> np.ndarray:
    e = np.abs(render.astype(float) - original.astype(float))
    return e.mean(axis=2) if e.ndim == 3 else e


def renders_figure(path: Path, original: np.ndarray, renders: dict, title: str):
    """Rows: the original, then each method; columns: the image and its absolute error (mean over
    channels), full size; one colour scale for every heat map."""
    h, w = original.shape[:2]
    rows = len(renders) + 1
    cell_w = 4.0
    cell_h = cell_w * h / w
    fig, axes = plt.subplots(rows, 2, figsize=(2 * cell_w + 0.4, rows * (cell_h + 0.3) + 0.9), squeeze=False,
                             layout="constrained")
    _show(axes[0, 0], original)
    axes[0, 0].set_title("original", fontsize=8)
    axes[0, 1].axis("off")
    last = None
    for (label, (render, stats)), (ax_r, ax_e) in zip(renders.items(), axes[1:]):
        _show(ax_r, render)
        ax_r.set_title(f"{label}: {stats}", fontsize=8)
        last = ax_e.imshow(abs_error(render, original), cmap="inferno", vmin=0, vmax=ERROR_VMAX,
                           interpolation="nearest")
        ax_e.set_xticks([])
        ax_e.set_yticks([])
        ax_e.set_title(f"{label}: |render - original|", fontsize=8)
    if last is not None:
        fig.colorbar(last, ax=axes[0, 1], location="bottom", fraction=0.5, aspect=12,
                     label=f"absolute error (clipped at {ERROR_VMAX})")
    fig.suptitle(title, fontsize=10)
    return save(fig, path)


def detail_figure(path: Path, original: np.ndarray, tri: trifile.TriFile, renders: dict, window, title: str):
    """The detail window, zoomed: original, triangulation, then each method; errors below."""
    x, y, ww, hh = window
    crop = (slice(y, y + hh), slice(x, x + ww))
    cols = 2 + len(renders)
    fig, axes = plt.subplots(2, cols, figsize=(2.1 * cols, 4.5), squeeze=False)
    _show(axes[0, 0], original[crop])
    axes[0, 0].set_title("original", fontsize=8)
    _show(axes[0, 1], original[crop], extent=(x - 0.5, x + ww - 0.5, y + hh - 0.5, y - 0.5))
    for layer in tri.layers:
        axes[0, 1].add_collection(LineCollection(_mesh_lines(layer), colors=layer_colour(tri, layer),
                                                 linewidths=0.5))
    axes[0, 1].set_xlim(x - 0.5, x + ww - 0.5)
    axes[0, 1].set_ylim(y + hh - 0.5, y - 0.5)
    axes[0, 1].set_title("triangulation", fontsize=8)
    axes[1, 0].axis("off")
    axes[1, 1].axis("off")
    last = None
    for i, (label, (render, _)) in enumerate(renders.items()):
        _show(axes[0, 2 + i], render[crop])
        axes[0, 2 + i].set_title(label, fontsize=8)
        last = axes[1, 2 + i].imshow(abs_error(render, original)[crop], cmap="inferno", vmin=0, vmax=ERROR_VMAX,
                                     interpolation="nearest")
        axes[1, 2 + i].set_xticks([])
        axes[1, 2 + i].set_yticks([])
        axes[1, 2 + i].set_title("|error|", fontsize=8)
    if last is not None:
        fig.colorbar(last, ax=axes[1, :].tolist(), shrink=0.8, orientation="horizontal", fraction=0.08)
    fig.suptitle(title, fontsize=10)
    return save(fig, path)
