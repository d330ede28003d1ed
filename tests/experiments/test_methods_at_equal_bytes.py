#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Tests of the methods' comparison at equal bytes (tools/experiments/methods_at_equal_bytes.py): the
interpolation of bilinear's curve, the table and verdict, and a run end to end on a small picture
(skipped when the tools are not in $TRISTREAM_BIN, default build/bin)."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True
REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tools/experiments"))

import methods_at_equal_bytes as mb  # noqa: E402

BIN = Path(os.environ.get("TRISTREAM_BIN", REPO / "build/bin"))
TOOLS = all((BIN / t).is_file() for t in ("triencode", "tripack"))


def row(image, density, method, difference):
    return dict(image=image, density_pct=density, method=method, vertices=10, bytes=100, psnr=30.0,
                bilinear_psnr_at_bytes=30.0 - difference, difference_db=difference, status="ok", error="")


class TableTest(unittest.TestCase):
    def test_interpolation_is_linear_in_log_bytes(self):
        curve = [(1000, 30.0), (700, 29.0), (500, 28.0)]
        self.assertAlmostEqual(mb.interpolate(curve, 1000), 30.0)
        self.assertAlmostEqual(mb.interpolate(curve, 500), 28.0)
        # half-way in log(bytes) between 700 and 1000
        self.assertAlmostEqual(mb.interpolate(curve, (700 * 1000) ** 0.5), 29.5)
        # below the curve: extrapolated from its first pair
        self.assertAlmostEqual(mb.interpolate(curve, 250), 28.0 - mb.math.log(2) / mb.math.log(1.4))

    def test_verdict_takes_the_better_method_per_picture(self):
        rows = [row("a", 1.0, "zienkiewicz", 0.6), row("a", 1.0, "clough-tocher", -1.0),
                row("b", 1.0, "zienkiewicz", -1.0), row("b", 1.0, "clough-tocher", 0.7),
                row("c", 1.0, "zienkiewicz", 0.4), row("c", 1.0, "clough-tocher", 0.1)]
        text = mb.summary(rows)
        self.assertIn("on 2 of 3 pictures: the goal holds", text)
        self.assertIn("1 of 3", text.splitlines()[1])  # zienkiewicz alone wins on a
        rows[0]["difference_db"] = 0.2
        self.assertIn("on 1 of 3 pictures: the goal does not hold", mb.summary(rows))


@unittest.skipUnless(TOOLS, f"needs triencode and tripack in {BIN} (TRISTREAM_BIN)")
class EndToEndTest(unittest.TestCase):
    def test_small_picture(self):
        from PIL import Image
        with tempfile.TemporaryDirectory() as tmp:
            images = Path(tmp) / "images"
            images.mkdir()
            picture = Image.new("L", (60, 40))
            picture.putdata([(x * 3 + (x * y) % 29) % 256 for y in range(40) for x in range(60)])
            picture.save(images / "p.png")
            p = subprocess.run([sys.executable, str(REPO / "tools/experiments/methods_at_equal_bytes.py"), str(BIN),
                                str(Path(tmp) / "out"), "--images", str(images), "--densities", "5"],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            with open(Path(tmp) / "out/methods.csv", newline="") as f:
                rows = list(csv.DictReader(f))
            self.assertEqual([r["method"] for r in rows], ["bilinear", "zienkiewicz", "clough-tocher"])
            self.assertTrue(all(r["status"] == "ok" for r in rows))
            self.assertEqual(rows[0]["vertices"], "120")
            # zienkiewicz's blob fits bilinear's bytes; clough-tocher has zienkiewicz's vertices
            self.assertLessEqual(int(rows[1]["bytes"]), int(rows[0]["bytes"]))
            self.assertEqual(rows[2]["vertices"], rows[1]["vertices"])
            self.assertIn("5 %: the better of the two beats bilinear", p.stdout)
