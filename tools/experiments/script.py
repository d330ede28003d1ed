# SPDX-License-Identifier: MIT
"""What the measuring scripts (rate_distortion.py, baselines.py) share: messages and exits named by
the script, an argument parser whose errors exit 64, and CSV tables read and written whole."""
import argparse
import csv
import io
import struct
import sys
from pathlib import Path

from runner import EXIT_USAGE, atomic_write_text

EXIT_DATA, EXIT_NOINPUT, EXIT_SOFTWARE, EXIT_CANTCREAT = 65, 66, 70, 73


class Script:
    """Messages on stderr prefixed with the script's name."""

    def __init__(self, name):
        self.name = name

    def fail(self, code, message):
        print(f"{self.name}: {message}", file=sys.stderr)
        sys.exit(code)

    def note(self, message):
        print(f"{self.name}: {message}", file=sys.stderr)

    def parser(self, **kwargs):
        """An ArgumentParser that prints the usage and exits EXIT_USAGE on a bad argument."""
        script = self

        class Parser(argparse.ArgumentParser):
            def error(self, message):
                self.print_usage(sys.stderr)
                script.fail(EXIT_USAGE, message)

        return Parser(**kwargs)

    def write_csv(self, path, columns, rows):
        """The rows (dicts) under a header of `columns`, written whole or not at all."""
        buf = io.StringIO()
        w = csv.DictWriter(buf, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow(r)
        atomic_write_text(path, buf.getvalue())

    def read_csv(self, path, columns):
        """The rows of a table that write_csv wrote, as strings; fails when it cannot be read or
        lacks one of `columns`."""
        try:
            with open(path, newline="") as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            self.fail(EXIT_NOINPUT, f"{path}: cannot read: {e.strerror}")
        if not rows or set(columns) - set(rows[0]):
            self.fail(EXIT_DATA, f"{path}: expected the columns {', '.join(columns)}")
        return rows

    def densities(self, parser, text, upper):
        """Percentages separated by commas, each above 0 and at most `upper`; a usage error otherwise."""
        try:
            values = [float(d) for d in text.split(",")]
        except ValueError:
            parser.error(f"--densities: expected numbers separated by commas, found '{text}'")
        if not all(0 < d <= upper for d in values):
            parser.error(f"--densities: expected percentages above 0 and at most {upper:g}, found '{text}'")
        return values

    def find_images(self, repo, quick, images_dir):
        """(path, name, width, height) of every PNG measured: the demo image with `quick`, every PNG
        under `images_dir` (named by its path there), else the ones shipped in the repository's data/."""
        if quick or not images_dir:
            if not quick:
                self.note("TRISTREAM_IMAGES is unset (and no --images): only the images shipped in data/ are measured")
            paths = [repo / "data/demo/kodim23.png"] if quick else sorted((repo / "data").rglob("*.png"))
            found = [(p, str(p.relative_to(repo))) for p in paths]
        else:
            root = Path(images_dir)
            if not root.is_dir():
                self.fail(EXIT_NOINPUT, f"{root}: expected a directory of images (--images or $TRISTREAM_IMAGES)")
            found = [(p, str(p.relative_to(root))) for p in sorted(root.rglob("*.png"))]
            if not found:
                self.fail(EXIT_NOINPUT, f"{root}: expected PNG images, found none")
        out = []
        for path, name in found:
            size = png_size(path)
            if size is None:
                self.fail(EXIT_DATA, f"{path}: expected a PNG image")
            out.append((path, name, *size))
        return out


def png_size(path):
    """(width, height) from a PNG's IHDR chunk; None when the file is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])
