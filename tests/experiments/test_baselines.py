#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Tests of the baseline comparison (tools/experiments/baselines.py): the vertex counts, the table's
means, worst image and target verdict, and a run end to end on a small picture (skipped when the
tools are not in $TRISTREAM_BIN, default build/bin)."""
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

import baselines as bl  # noqa: E402

BIN = Path(os.environ.get("TRISTREAM_BIN", REPO / "build/bin"))
TOOLS = all((BIN / t).is_file() for t in ("triencode", "tribaseline"))


def row(image, density, encoder, psnr, seconds=1.0):
    return dict(image=image, width=10, height=10, density_pct=density, vertices=4, encoder=encoder, psnr=psnr,
                seconds=seconds, status="ok", error="")


class TableTest(unittest.TestCase):
    def test_vertex_counts(self):
        self.assertEqual(bl.vertex_count(512, 512, 0.5), 1311)  # 1310.72
        self.assertEqual(bl.vertex_count(768, 512, 1), 3932)  # 3932.16
        self.assertEqual(bl.vertex_count(10, 10, 0.5), 4)  # at least the corners
        self.assertEqual(bl.vertex_count(100, 10, 0.25), 4)  # 2.5 rounds to 3, below the corners
        self.assertEqual(bl.vertex_count(200, 100, 0.25), 50)

    def test_means_worst_image_and_verdict(self):
        rows = []
        for image, tri, lsq, gpr in (("a", 31.0, 29.0, 28.0), ("b", 30.0, 30.1, 29.0)):
            rows += [row(image, 1.0, "triencode", tri), row(image, 1.0, "gpr_lsq", lsq), row(image, 1.0, "gpr", gpr)]
        text, met = bl.table(rows)
        line = text.splitlines()[2]
        self.assertIn("+0.95", line)  # mean of +2.0 and -0.1
        self.assertIn("+2.00", line)  # mean of +3.0 and +1.0
        self.assertIn("-0.10 b", line)
        self.assertFalse(met)  # the mean is below 1 dB
        rows[3]["psnr"] = 31.0  # b: +0.9; mean +1.45, worst +0.9
        text, met = bl.table(rows)
        self.assertTrue(met)
        self.assertIn(": met", text)

    def test_a_case_missing_an_encoder_is_left_out(self):
        rows = [row("a", 2.0, "triencode", 30.0), row("a", 2.0, "gpr_lsq", 25.0), row("a", 2.0, "gpr", 24.0),
                row("b", 2.0, "triencode", 20.0), row("b", 2.0, "gpr_lsq", 25.0)]
        rows.append(dict(row("b", 2.0, "gpr", 0.0), status="failed", psnr="", error="exit 70"))
        text, met = bl.table(rows)
        self.assertIn("  1  ", text.splitlines()[2])  # one complete image
        self.assertTrue(met)


@unittest.skipUnless(TOOLS, f"needs triencode and tribaseline in {BIN} (TRISTREAM_BIN)")
class EndToEndTest(unittest.TestCase):
    def test_small_picture(self):
        from PIL import Image
        with tempfile.TemporaryDirectory() as tmp:
            images = Path(tmp) / "images"
            images.mkdir()
            picture = Image.new("L", (40, 30))
            picture.putdata([(x * 7 + (x * y) % 23) % 256 for y in range(30) for x in range(40)])
            picture.save(images / "p.png")
            p = subprocess.run([sys.executable, str(REPO / "tools/experiments/baselines.py"), str(BIN),
                                str(Path(tmp) / "out"), "--images", str(images), "--densities", "2,10"],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            with open(Path(tmp) / "out/baselines.csv", newline="") as f:
                rows = list(csv.DictReader(f))
            self.assertEqual(len(rows), 6)
            self.assertEqual({r["vertices"] for r in rows}, {"24", "120"})
            self.assertTrue(all(r["status"] == "ok" for r in rows))
            self.assertEqual(len([line for line in p.stdout.splitlines() if line.lstrip().endswith(("yes", "no"))]), 2)
            again = subprocess.run([sys.executable, str(REPO / "tools/experiments/baselines.py"), str(BIN),
                                    str(Path(tmp) / "out"), "--report-only"], capture_output=True, text=True)
            self.assertEqual(again.returncode, 0, again.stderr)
            self.assertEqual(again.stdout, p.stdout)
            # Every result is cached; a second run takes them from the cache (times included).
            self.assertEqual(len(list((Path(tmp) / "out/cache").glob("*.json"))), 6)
            cached = subprocess.run([sys.executable, str(REPO / "tools/experiments/baselines.py"), str(BIN),
                                     str(Path(tmp) / "out"), "--images", str(images), "--densities", "2,10"],
                                    capture_output=True, text=True)
            self.assertEqual(cached.returncode, 0, cached.stderr)
            self.assertEqual(cached.stdout, p.stdout)

    def test_bad_arguments(self):
        p = subprocess.run([sys.executable, str(REPO / "tools/experiments/baselines.py"), str(BIN), "/tmp/x",
                            "--densities", "0"], capture_output=True, text=True)
        self.assertEqual(p.returncode, bl.EXIT_USAGE)
        self.assertIn("--densities", p.stderr)


if __name__ == "__main__":
    unittest.main()
