#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Tests of the rate-distortion driver (tools/experiments/rate_distortion.py): the search for the
smallest file at a PSNR, the PSNR itself, and its quick mode end to end (one image, two densities;
skipped when the tools are not in $TRISTREAM_BIN, default build/bin)."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True
REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "tools/experiments"))

import numpy as np  # noqa: E402

import rate_distortion as rd  # noqa: E402

BIN = Path(os.environ.get("TRISTREAM_BIN", REPO / "build/bin"))
TOOLS = all((BIN / t).is_file() for t in ("triencode", "tripack", "trisim"))


class SearchTest(unittest.TestCase):
    def test_finds_the_smallest_passing_quality(self):
        calls = []

        def evaluate(q):  # bytes grow and PSNR grows with q; q >= 37 reaches 30 dB
            calls.append(q)
            return 100 * q, 20 + 10 * q / 37

        self.assertEqual(rd.smallest_at_psnr(evaluate, 1, 100, 30.0, integer=True), (37, 3700, 30.0))
        self.assertLess(len(calls), 12)  # a binary search, not a scan

    def test_unreachable_target(self):
        self.assertIsNone(rd.smallest_at_psnr(lambda q: (q, q / 10), 1, 100, 50.0, integer=True))

    def test_lowest_parameter_already_passes(self):
        self.assertEqual(rd.smallest_at_psnr(lambda q: (q, 40.0), 1, 100, 30.0, integer=True), (1, 1, 40.0))

    def test_keeps_the_smallest_file_where_psnr_is_not_monotone(self):
        # PSNR dips at 50 (passes at 26 and up except 50); bytes are smaller at 30 than at 26.
        table = {q: (1000 - abs(q - 30) if q < 40 else 2000 + q, 31.0 if q >= 26 and q != 50 else 29.0)
                 for q in range(1, 101)}
        param, size, _ = rd.smallest_at_psnr(lambda q: table[q], 1, 100, 30.0, integer=True)
        passing = [table[q][0] for q in range(1, 101) if table[q][1] >= 30.0]
        self.assertGreaterEqual(size, min(passing))
        self.assertGreaterEqual(table[param][1], 30.0)
        self.assertEqual(size, table[param][0])

    def test_continuous_parameter(self):
        param, _, q = rd.smallest_at_psnr(lambda p: (p, p), -5.0, 5.0, 1.25, integer=False, steps=30)
        self.assertGreaterEqual(q, 1.25)
        self.assertAlmostEqual(param, 1.25, places=2)


class PsnrTest(unittest.TestCase):
    def test_definition(self):
        a = np.zeros((4, 4, 3), np.uint8)
        b = a.copy()
        b[0, 0, 0] = 16  # MSE 256 / 48
        self.assertAlmostEqual(rd.psnr(a, b), 10 * math.log10(255 ** 2 * 48 / 256))
        self.assertEqual(rd.psnr(a, a), math.inf)

    def test_codecs_round_trip(self):
        from PIL import Image
        rng = np.random.default_rng(1)
        pixels = (rng.random((32, 48, 3)) * 255).astype(np.uint8)
        for mode in ("RGB", "L"):
            image = Image.fromarray(pixels).convert(mode)
            original = rd.as_array(image, mode == "L")
            for codec, good, poor in (("jpeg", 95, 5), ("webp", 95, 5), ("jp2", 2.0, 200.0)):
                hi = rd.psnr(rd.as_array(rd.decode(rd.encode(codec, image, mode == "L", good)), mode == "L"), original)
                lo = rd.psnr(rd.as_array(rd.decode(rd.encode(codec, image, mode == "L", poor)), mode == "L"), original)
                self.assertGreater(hi, lo, f"{codec} {mode}")


class MediansTest(unittest.TestCase):
    def row(self, group, density, v1, jpeg, param=40):
        r = dict.fromkeys(rd.COLUMNS, "")
        r.update(group=group, density_pct=density, v1_bytes=v1, status="ok", jpeg_param=param)
        if jpeg:
            r.update(jpeg_bytes=jpeg, v1_over_jpeg=v1 / jpeg)
        return r

    def test_medians_per_group_and_density(self):
        rows = [self.row("grey", 1.0, 100, 10), self.row("grey", 1.0, 300, 10), self.row("grey", 2.0, 50, 10),
                self.row("colour", 1.0, 80, 10), self.row("colour", 1.0, 80, None, "unreached")]
        t = rd.medians(rows)
        self.assertEqual(t[("grey", 1.0, "v1", "jpeg")], (20.0, 10.0, 30.0, 2, 0))
        self.assertEqual(t[("grey", "all", "v1", "jpeg")], (10.0, 5.0, 30.0, 3, 0))
        self.assertEqual(t[("colour", 1.0, "v1", "jpeg")], (8.0, 8.0, 8.0, 1, 1))  # unreached: counted, not ranked
        self.assertNotIn(("grey", 1.0, "compressed", "jpeg"), t)
        self.assertIn("1 unreached", rd.summary(t, 0))

    def test_report_only_reads_an_earlier_run(self):
        rows = [self.row("grey", 0.5, 120, 10), self.row("colour", 0.5, 60, 20)]
        with tempfile.TemporaryDirectory() as out:
            rd.write_csv(Path(out) / "rd.csv", rows)
            p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/rate_distortion.py"), "unused", out,
                                "--report-only"], capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            self.assertRegex(p.stdout, r"grey\s+0\.5 %\s+v1\s+/ jpeg\s+12\.00x")
            self.assertRegex(p.stdout, r"colour\s+0\.5 %\s+v1\s+/ jpeg\s+3\.00x")
            self.assertTrue((Path(out) / "rd.png").is_file())
            (Path(out) / "rd.csv").write_text("image,group\nx,grey\n")
            p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/rate_distortion.py"), "unused", out,
                                "--report-only"], capture_output=True, text=True)
            self.assertEqual(p.returncode, 65)
            self.assertIn("rd.csv: expected the columns", p.stderr)


@unittest.skipUnless(TOOLS, f"triencode, tripack and trisim not found in {BIN} (set TRISTREAM_BIN)")
class QuickRunTest(unittest.TestCase):
    def test_quick_mode(self):
        with tempfile.TemporaryDirectory() as out:
            p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/rate_distortion.py"), str(BIN), out,
                                "--quick"], capture_output=True, text=True, timeout=600)
            self.assertEqual(p.returncode, 0, p.stderr)
            self.assertIn("median blob bytes / codec bytes", p.stdout)
            self.assertRegex(p.stdout, r"colour\s+all\s+compressed\s+/ jpeg\s+[0-9.]+x")
            self.assertRegex(p.stdout, r"colour\s+all\s+v1\s+/ jpeg\s+[0-9.]+x")
            with open(Path(out) / "rd.csv", newline="") as f:
                rows = list(csv.DictReader(f))
            self.assertEqual(Path(out, "rd.png").read_bytes()[:8], b"\x89PNG\r\n\x1a\n")
        self.assertEqual([float(r["density_pct"]) for r in rows], [0.5, 1.0])
        for r in rows:
            self.assertEqual(r["status"], "ok", r["error"])
            self.assertEqual(r["group"], "colour")
            self.assertEqual(int(r["vertices"]), round(float(r["density_pct"]) / 100 * 768 * 512))
            target = float(r["psnr_blob"])
            self.assertGreater(target, 20)
            for codec in rd.CODECS:
                self.assertGreaterEqual(float(r[f"{codec}_psnr"]), target, codec)
                self.assertLess(float(r[f"{codec}_psnr"]), target + 1.0, codec)  # equal PSNR, not far above
                self.assertAlmostEqual(float(r[f"v1_over_{codec}"]), int(r["v1_bytes"]) / int(r[f"{codec}_bytes"]),
                                       places=3)
                self.assertAlmostEqual(float(r[f"compressed_over_{codec}"]),
                                       int(r["compressed_bytes"]) / int(r[f"{codec}_bytes"]), places=3)
            self.assertEqual(r["compressed_render"], "identical")
            self.assertLess(int(r["compressed_bytes"]), int(r["v1_bytes"]))
        # The blob's PSNR is the core's render as trisim measures it.
        with tempfile.TemporaryDirectory() as tmp:
            image = REPO / "data/demo/kodim23.png"
            subprocess.run([str(BIN / "triencode"), str(image), "-n", rows[0]["vertices"], "-o", f"{tmp}/x.tri"],
                           check=True, capture_output=True)
            subprocess.run([str(BIN / "tripack"), f"{tmp}/x.tri", "-o", f"{tmp}/x.bin"], check=True,
                           capture_output=True)
            self.assertEqual(os.path.getsize(f"{tmp}/x.bin"), int(rows[0]["v1_bytes"]))
            p = subprocess.run([str(BIN / "trisim"), "compare", f"{tmp}/x.bin", "--original", str(image), "--json"],
                               check=True, capture_output=True, text=True)
            self.assertAlmostEqual(json.loads(p.stdout)["psnr"], float(rows[0]["psnr_blob"]), places=3)


@unittest.skipUnless(TOOLS, f"triencode, tripack and trisim not found in {BIN} (set TRISTREAM_BIN)")
class CompressedRenderTest(unittest.TestCase):
    """A compressed blob whose render differs from the v1 blob's, or that trisim cannot open, fails
    its case (here through a trisim wrapper that draws TSTC blobs differently or refuses them)."""

    def case_with(self, tstc_render):
        with tempfile.TemporaryDirectory() as tmp:
            for tool in ("triencode", "tripack"):
                os.symlink(BIN / tool, Path(tmp) / tool)
            wrapper = Path(tmp) / "trisim"
            wrapper.write_text("#!/bin/bash\n"
                               f'if [ "$1" = render ] && [ "$(head -c 4 "$2")" = TSTC ]; then {tstc_render}; fi\n'
                               f'exec {BIN / "trisim"} "$@"\n')
            wrapper.chmod(0o755)
            return rd.measure((str(REPO / "data/demo/kodim23.png"), "kodim23", 0.5, tmp, True))

    def test_a_different_render_fails(self):
        row = self.case_with(f'exec {BIN / "trisim"} render "$2" --engine reference -m natural "${{@:3}}"')
        self.assertEqual(row["status"], "failed")
        self.assertIn("the compressed blob renders differently from the v1 blob", row["error"])

    def test_a_blob_trisim_refuses_fails(self):
        row = self.case_with('echo "trisim: $2: byte 0: bad magic" >&2; exit 65')
        self.assertEqual(row["status"], "failed")
        self.assertIn("trisim render of the compressed blob: exit 65", row["error"])


if __name__ == "__main__":
    unittest.main()
