# SPDX-License-Identifier: MIT
"""A reader of the .tri text format (docs/FORMAT.md) for the report's pictures and analyses.

Only files written by triencode are read here, and trisim has already validated each of them
when it rendered it; this reader still checks the structure it relies on and raises ValueError
naming the file and line on anything unexpected.
"""
from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np


@dataclass
class Layer:
    name: str
    points: np.ndarray          # (N, 2) x, y in pixel units
    values: np.ndarray          # (N, C)
    triangles: Optional[np.ndarray] = None  # (M, 3) or None when the file leaves it to Delaunay


@dataclass
class TriFile:
    width: int
    height: int
    channels: str               # grey, rgb or ycbcr
    layers: List[Layer] = field(default_factory=list)

    def vertex_count(self) -> int:
        return sum(len(layer.points) for layer in self.layers)


def _tokens(path):
    with open(path, "r", encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if line:
                yield number, line.split()


def read_tri(path) -> TriFile:
    lines = list(_tokens(path))
    pos = 0

    def take(keyword=None, count=None):
        nonlocal pos
        if pos >= len(lines):
            raise ValueError(f"{path}: unexpected end of file, expected {keyword or 'data'}")
        number, toks = lines[pos]
        if keyword is not None and toks[0] != keyword:
            raise ValueError(f"{path}:{number}: expected '{keyword}', found '{toks[0]}'")
        if count is not None and len(toks) != count:
            raise ValueError(f"{path}:{number}: expected {count} tokens, found {len(toks)}")
        pos += 1
        return toks

    def peek():
        return lines[pos][1][0] if pos < len(lines) else None

    take("tri", 2)
    _, w, h = take("size", 3)
    _, channels = take("channels", 2)
    tri = TriFile(int(w), int(h), channels)

    def read_mesh(name, nvalues):
        n = int(take("vertices", 2)[1])
        rows = np.array([[float(t) for t in take(count=2 + nvalues)] for _ in range(n)], dtype=float)
        triangles = None
        if peek() == "triangles":
            m = int(take("triangles", 2)[1])
            if m > 0:
                triangles = np.array([[int(t) for t in take(count=3)] for _ in range(m)], dtype=np.int64)
        return Layer(name, rows[:, :2], rows[:, 2:], triangles)

    if peek() == "layers":
        count = int(take("layers", 2)[1])
        for _ in range(count):
            name = take("layer", 2)[1]
            tri.layers.append(read_mesh(name, 1))
    else:
        tri.layers.append(read_mesh(channels, 1 if channels == "grey" else 3))
    if pos != len(lines):
        raise ValueError(f"{path}:{lines[pos][0]}: expected the end of the file, found '{lines[pos][1][0]}'")
    return tri


def write_layered(width, height, space, layers) -> str:
    """The text of a layered (separate-triangulation) file made of three single-channel layers."""
    names = {"rgb": ["r", "g", "b"], "ycbcr": ["y", "cb", "cr"]}[space]
    out = [f"tri 1", f"size {width} {height}", f"channels {space}", "layers 3"]
    for name, layer in zip(names, layers):
        out.append(f"layer {name}")
        out.append(f"vertices {len(layer.points)}")
        for (x, y), v in zip(layer.points, layer.values):
            out.append(f"{x:.17g} {y:.17g} {v[0]:.17g}")
        tris = layer.triangles if layer.triangles is not None else np.zeros((0, 3), dtype=np.int64)
        out.append(f"triangles {len(tris)}")
        out.extend(f"{a} {b} {c}" for a, b, c in tris)
    return "\n".join(out) + "\n"
