#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Unit tests of the experiment driver's helpers (tools/experiments). Run with
/usr/bin/python3 -m unittest discover -s tests/experiments  (or directly). Tests that need the
built tools look for them in $TRISTREAM_BIN (default build/bin) and skip when they are absent."""
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

import findings  # noqa: E402
import trifile  # noqa: E402
from execute import luma  # noqa: E402
from pictures import neighbour_contrast  # noqa: E402
from plan import make_plan, scaled  # noqa: E402
from runner import Cache, key_of  # noqa: E402

BIN = Path(os.environ.get("TRISTREAM_BIN", REPO / "build/bin"))


class TriFileTest(unittest.TestCase):
    def test_reads_single_layer_with_comments(self):
        with tempfile.TemporaryDirectory() as d:
            p = Path(d) / "a.tri"
            p.write_text("tri 1\nsize 4 3\nchannels grey  # c\nvertices 4\n0 0 1\n3 0 2\n0 2 3\n3 2 4.5\n"
                         "triangles 2\n0 1 2\n1 3 2\n")
            t = trifile.read_tri(p)
            self.assertEqual((t.width, t.height, t.channels), (4, 3, "grey"))
            self.assertEqual(t.layers[0].points.shape, (4, 2))
            self.assertEqual(t.layers[0].values[3, 0], 4.5)
            self.assertEqual(t.layers[0].triangles.tolist(), [[0, 1, 2], [1, 3, 2]])

    def test_layered_round_trip(self):
        pts = np.array([[0, 0], [9, 0], [0, 9], [9, 9.5]])
        layers = [trifile.Layer(n, pts, np.array([[1.0], [2.0], [3.0], [4.0]]) * (i + 1),
                                np.array([[0, 1, 2], [1, 3, 2]])) for i, n in enumerate(("y", "cb", "cr"))]
        with tempfile.TemporaryDirectory() as d:
            p = Path(d) / "l.tri"
            p.write_text(trifile.write_layered(10, 10, "ycbcr", layers))
            t = trifile.read_tri(p)
            self.assertEqual([l.name for l in t.layers], ["y", "cb", "cr"])
            self.assertEqual(t.vertex_count(), 12)
            self.assertTrue(np.array_equal(t.layers[2].values[:, 0], [3, 6, 9, 12]))
            self.assertTrue(np.array_equal(t.layers[0].points, pts))

    def test_rejects_truncated_file(self):
        with tempfile.TemporaryDirectory() as d:
            p = Path(d) / "bad.tri"
            p.write_text("tri 1\nsize 4 3\nchannels grey\nvertices 4\n0 0 1\n")
            with self.assertRaisesRegex(ValueError, "bad.tri"):
                trifile.read_tri(p)


class HelpersTest(unittest.TestCase):
    def test_scaled_by_area(self):
        self.assertEqual(scaled(1000, 512, 512), 1000)
        self.assertEqual(scaled(1000, 768, 512), 1500)
        self.assertEqual(scaled(15000, 512, 480), 14062)  # 14062.5 rounds to even

    def test_keys_depend_on_every_input(self):
        a = {"tool": "x", "image": "y", "n": 1}
        self.assertEqual(key_of(a), key_of(dict(reversed(list(a.items())))))
        self.assertNotEqual(key_of(a), key_of({**a, "n": 2}))

    def test_cache_force_recomputes_once(self):
        with tempfile.TemporaryDirectory() as d:
            Cache(Path(d), force=False).store("runs", "ab" * 32, {"v": 1})
            forced = Cache(Path(d), force=True)
            self.assertIsNone(forced.load("runs", "ab" * 32))
            forced.store("runs", "ab" * 32, {"v": 2})
            self.assertEqual(forced.load("runs", "ab" * 32), {"v": 2})

    def test_neighbour_contrast(self):
        # Two triangles of areas 1 and 4 sharing an edge, and one with no neighbour.
        tris = np.array([[0, 1, 2], [1, 3, 2], [4, 5, 6]])
        area = np.array([1.0, 4.0, 2.0])
        self.assertTrue(np.allclose(neighbour_contrast(tris, area), [4.0, 4.0, 1.0]))

    def test_excess_error_window_finds_the_patch_artifact(self):
        from pictures import excess_error_window
        original = np.full((100, 120), 100, np.uint8)
        bilinear = original.copy()
        coons = original.copy()
        coons[60:70, 80:90] = 200  # an artifact of the patch method only
        x, y, w, h = excess_error_window(original, {"bilinear": (bilinear, ""), "coons": (coons, "")}, 20)
        self.assertEqual((w, h), (20, 20))
        self.assertTrue(x <= 80 and x + w >= 90 and y <= 60 and y + h >= 70, (x, y))
        self.assertIsNone(excess_error_window(original, {"bilinear": (bilinear, "")}, 20))

    def test_luma_rounds_half_away_from_zero(self):
        rgb = np.array([[[255, 255, 255], [0, 0, 0], [1, 2, 0]]], dtype=np.uint8)
        # 0.299 + 1.174 = 1.473 -> 1
        self.assertEqual(luma(rgb).tolist(), [[255, 0, 1]])


def row(image, n, method, psnr, ssim, variant="", study="grey", colour="grey", mode="grey", space="grey",
        cotri=""):
    return {"image": image, "nominal_vertices": n, "method": method, "variant": variant, "engine": "reference",
            "status": "ok", "psnr": psnr, "ssim": ssim, "mse": 255 ** 2 / 10 ** (psnr / 10), "study": study,
            "colour": colour, "mode": mode, "space": space, "cotri": cotri, "ssim_8x8": ssim}


class FindingsTest(unittest.TestCase):
    def test_zienkiewicz_against_bilinear_counts_cases(self):
        rows = [row("a", 1000, "bilinear", 30, 0.8), row("a", 1000, "zienkiewicz", 31, 0.81),
                row("b", 1000, "bilinear", 30, 0.8), row("b", 1000, "zienkiewicz", 29, 0.79)]
        f = {x["topic"]: x for x in findings.grey_findings(rows)}
        psnr = f["Zienkiewicz against bilinear (PSNR)"]
        self.assertIn("1 of 2", psnr["here"])
        self.assertEqual(psnr["cases"], 2)
        self.assertEqual(psnr["verdict"], "not enough data")  # below findings.MIN_CASES

    def test_verdict_from_enough_cases(self):
        rows = []
        for k, better in enumerate([True, False, True, False, True, False]):
            rows += [row(f"i{k}", 1000, "bilinear", 30, 0.8), row(f"i{k}", 1000, "zienkiewicz", 31 if better else 29,
                                                                   0.81 if better else 0.79)]
        psnr = {x["topic"]: x for x in findings.grey_findings(rows)}["Zienkiewicz against bilinear (PSNR)"]
        self.assertEqual((psnr["cases"], psnr["verdict"]), (6, "mixed"))

    def test_claim_about_an_absent_image_is_not_compared(self):
        rows = [row(f"i{k}", 5000, m, 31, 0.8) for k in range(6) for m in ("bilinear", "zienkiewicz")]
        f = {x["topic"]: x for x in findings.grey_findings(rows)}
        self.assertIn("Fruits", f["30 dB at 5,000 vertices"]["verdict"])
        rows += [row("fruits", 5000, m, 31, 0.8) for m in ("bilinear", "zienkiewicz")]
        f = {x["topic"]: x for x in findings.grey_findings(rows)}
        self.assertEqual(f["30 dB at 5,000 vertices"]["verdict"], "agrees")

    def test_ranking_reports_reversed_pairs(self):
        rows = [row("a", 1000, m, p, 0.8) for m, p in (("zienkiewicz", 28), ("bilinear", 30), ("natural", 29))]
        f = {x["topic"]: x for x in findings.grey_findings(rows)}
        text = f["Ranking of the methods (PSNR)"]["here"]
        self.assertIn("bilinear ahead of zienkiewicz", text)
        self.assertIn("natural ahead of zienkiewicz", text)

    def test_separate_against_co(self):
        rows = []
        for image in ("a", "b", "c"):
            for m in ("bilinear", "zienkiewicz"):
                rows.append(row(image, 3000, m, 30, 0.80, study="colour", colour="separate-rgb", mode="separate",
                                space="rgb"))
                rows.append(row(image, 3000, m, 31, 0.85, study="colour", colour="co-rgb", mode="co", space="rgb",
                                cotri="greedy"))
        f = {x["topic"]: x for x in findings.colour_findings(rows)}
        self.assertIn("0 of 6", f["Separate against co-triangulation, equal totals (PSNR)"]["here"])
        self.assertEqual(f["Compression: co-triangulation against separate"]["verdict"], "agrees")

    def test_verdict_thresholds(self):
        n = findings.MIN_CASES
        self.assertEqual(findings.verdict(None, 0), "no data")
        self.assertEqual(findings.verdict(1.0, n - 1), "not enough data")
        self.assertEqual(findings.verdict(0.8, n), "agrees")
        self.assertEqual(findings.verdict(0.6, n), "mostly agrees")
        self.assertEqual(findings.verdict(0.3, n), "mixed")
        self.assertEqual(findings.verdict(0.1, n), "disagrees")


@unittest.skipUnless((BIN / "trisim").exists(), f"trisim not built in {BIN}")
class ToolsTest(unittest.TestCase):
    def test_luma_matches_trisim(self):
        """The driver's luma image equals what trisim compares a grey render with."""
        from PIL import Image
        demo = REPO / "data/demo/kodim23.png"
        with tempfile.TemporaryDirectory() as d:
            p = Path(d) / "luma.png"
            Image.fromarray(luma(np.asarray(Image.open(demo).convert("RGB")))).save(p)
            out = subprocess.run([str(BIN / "trisim"), "metrics", str(p), str(demo), "--json"],
                                 capture_output=True, text=True, check=True).stdout
            self.assertIn('"mse":0.0', out.replace(" ", ""))

    def test_driver_usage_error_exits_64(self):
        p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/run_experiments.py"), str(BIN),
                            tempfile.gettempdir() + "/exp-never", "--set", "huge"], capture_output=True, text=True)
        self.assertEqual(p.returncode, 64)
        self.assertIn("--set", p.stderr)

    def test_driver_rejects_a_missing_bin_dir(self):
        p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/run_experiments.py"),
                            "/nonexistent-bin", tempfile.gettempdir() + "/exp-never"], capture_output=True,
                           text=True)
        self.assertEqual(p.returncode, 66)
        self.assertIn("/nonexistent-bin/trisim", p.stderr)


class PlanTest(unittest.TestCase):
    """The full set takes every image of --images DIR, says which, and refuses an empty one."""

    @staticmethod
    def write(path, mode, size=(40, 30)):
        from PIL import Image
        path.parent.mkdir(parents=True, exist_ok=True)
        rng = np.random.default_rng(1)
        shape = (size[1], size[0]) + ({"RGB": (3,), "RGBA": (4,)}.get(mode, ()))
        Image.fromarray(rng.integers(0, 256, shape, dtype=np.uint8), mode).save(path)

    def test_every_image_of_the_folder_is_used(self):
        with tempfile.TemporaryDirectory() as d:
            root = Path(d)
            self.write(root / "kodak/kodim05.png", "RGB")
            self.write(root / "grey/boat.png", "L")
            self.write(root / "mine.jpg", "RGB")
            self.write(root / "colour/mine.png", "RGB")  # the same name as mine.jpg: named by path
            plan = make_plan("full", REPO, root)
            self.assertEqual(sorted(s.name for s in plan.grey_sources),
                             ["boat", "colour/mine", "kodim05", "mine"])
            self.assertEqual(sorted(s.name for s in plan.colour_sources), ["colour/mine", "kodim05", "mine"])
            self.assertEqual([s.name for s in plan.time_sources], ["boat"])
            self.assertNotIn("kodim23", {s.name for s in plan.grey_sources})
            page = " ".join(plan.notes)
            for name in ("boat", "kodim05", "colour/mine"):
                self.assertIn(name, page)
            self.assertNotIn("sailboat", page)

    def test_an_unusable_image_is_named_and_the_rest_used(self):
        with tempfile.TemporaryDirectory() as d:
            root = Path(d)
            self.write(root / "a.png", "RGB")
            self.write(root / "b.png", "RGBA")
            plan = make_plan("full", REPO, root)
            self.assertEqual([s.name for s in plan.grey_sources], ["a"])
            self.assertTrue(any("b.png" in n and "RGBA" in n for n in plan.notes), plan.notes)

    def test_an_empty_selection_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            (Path(d) / "notes.txt").write_text("no pictures here")
            with self.assertRaisesRegex(ValueError, "no usable image"):
                make_plan("full", REPO, Path(d))
            with self.assertRaisesRegex(ValueError, "no such folder"):
                make_plan("full", REPO, Path(d) / "absent")

    def test_the_driver_exits_65_on_an_empty_folder(self):
        if not (BIN / "trisim").exists():
            self.skipTest(f"{BIN}/trisim not built")
        with tempfile.TemporaryDirectory() as d:
            p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/run_experiments.py"), str(BIN),
                                str(Path(d) / "out"), "--set", "full", "--images", d], capture_output=True, text=True)
            self.assertEqual(p.returncode, 65, p.stderr)
            self.assertIn(f"{d}: no usable image", p.stderr)

    def test_a_run_off_a_terminal_prints_a_line_per_case_and_names_its_images(self):
        if not (BIN / "trisim").exists():
            self.skipTest(f"{BIN}/trisim not built")
        with tempfile.TemporaryDirectory() as d:
            from PIL import Image
            ramp = (np.add.outer(np.arange(24), np.arange(32)) * 4).astype(np.uint8)
            (Path(d) / "img").mkdir()
            Image.fromarray(ramp, "L").save(Path(d) / "img/ramp.png")
            p = subprocess.run(["/usr/bin/python3", str(REPO / "tools/experiments/run_experiments.py"), str(BIN),
                                str(Path(d) / "out"), "--set", "full", "--images", str(Path(d) / "img"), "--jobs", "2"],
                               capture_output=True, text=True)
            self.assertEqual(p.returncode, 0, p.stderr)
            lines = [line for line in p.stderr.splitlines() if line.startswith("experiments (full): case ")]
            total = int(lines[-1].split("/")[1].split()[0]) if lines else -1
            self.assertEqual(len(lines), total, p.stderr[-2000:])
            self.assertIn("grey ramp grey, 1,000 vertices", p.stderr)
            page = (Path(d) / "out/index.html").read_text(encoding="utf-8")
            self.assertIn("Greyscale: 1 image (ramp as they are)", page)
            self.assertNotIn("kodim23", "".join(line for line in lines))


if __name__ == "__main__":
    unittest.main()
