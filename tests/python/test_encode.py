# SPDX-License-Identifier: MIT
"""encode equals triencode's output for the same parameters, and bad arguments raise with a
message naming them (item: encode)."""
import unittest

import numpy as np
import tristream

from support import ScratchTest, small_image, tool, tool_json


class EncodeEqualsTriencode(ScratchTest):
    def check(self, image, kwargs, args):
        path = self.dir / "in.png"
        tristream.write_png(path, image)
        out = self.dir / "out.tri"
        tool("triencode", path, "-o", out, "-q", *args)
        tri = tristream.encode(image, **kwargs)
        self.assertEqual(tri.to_text(), out.read_text())
        return tri, out

    def test_vertex_count(self):
        tri, _ = self.check(small_image(), dict(vertices=300), ["-n", 300])
        self.assertEqual(tri.vertices.shape, (300, 2))
        self.assertEqual(tri.values.shape, (300, 3))
        self.assertEqual(tri.triangles.shape[1], 3)

    def test_grey_and_options(self):
        self.check(small_image(grey=True), dict(error=6.0, values="pixel", rank="worst", sigma=0.0),
                   ["-e", 6, "--values", "pixel", "--rank", "worst", "--sigma", 0])
        self.check(small_image(), dict(vertices=120, grey=True, relocate=1), ["-n", 120, "--grey", "--relocate", 1])
        self.check(small_image(), dict(vertices=150, flips=0), ["-n", 150, "--flips", 0])
        self.check(small_image(), dict(vertices=150, flips=1, relocate=0), ["-n", 150, "--flips", 1, "--relocate", 0])

    def test_colour_modes(self):
        tri, _ = self.check(small_image(), dict(vertices=80, color="separate", space="ycbcr"),
                            ["-n", 80, "--color", "separate", "--space", "ycbcr"])
        self.assertTrue(tri.layered)
        self.assertEqual([m.name for m in tri.layers], ["y", "cb", "cr"])
        self.check(small_image(), dict(vertices=100, cotri="thesis"), ["-n", 100, "--cotri", "thesis"])

    def test_panel_and_budget(self):
        args = ["--max-bytes", 3000, "--blob", "v1", "-m", "zienkiewicz", "--width", 80, "--height", 80,
                "--fit", "inside"]
        kwargs = dict(max_bytes=3000, blob="v1", method="zienkiewicz", width=80, height=80, fit="inside")
        tri, out = self.check(small_image(), kwargs, args)
        self.assertEqual((tri.width, tri.height), (80, 80))
        self.assertLessEqual(len(tristream.pack(tri, "zienkiewicz")), 3000)
        summary = tool_json("triencode", self.dir / "in.png", "-o", self.dir / "again.tri", "-q", *args)
        self.assertEqual(summary["vertices"], len(tri.vertices))
        self.assertEqual(summary["blob_bytes"], len(tristream.pack(tri, "zienkiewicz")))
        tri, _ = self.check(small_image(), dict(max_bytes=1500), ["--max-bytes", 1500])
        self.assertLessEqual(len(tristream.pack(tri, "bilinear", compress=True)), 1500)

    def test_methods_fit_gradients(self):
        tri, _ = self.check(small_image(), dict(vertices=150), ["-n", 150])
        self.assertIsNone(tri.layers[0].gradients)
        for method in ("zienkiewicz", "clough-tocher"):
            fitted, _ = self.check(small_image(), dict(vertices=150, method=method), ["-n", 150, "-m", method])
            self.assertEqual(fitted.layers[0].gradients.shape, (150, 6))
            self.assertTrue(np.array_equal(fitted.vertices, tri.vertices))  # the same mesh
        stepped, _ = self.check(small_image(), dict(vertices=150, method="zienkiewicz", gradient_step=4),
                                ["-n", 150, "-m", "zienkiewicz", "--gradient-step", 4])
        g = stepped.layers[0].gradients * 256  # steps of 2^(4 - 12)
        self.assertTrue(np.array_equal(g, np.round(g)))

    def test_float_image_of_integers(self):
        image = small_image()
        self.assertEqual(tristream.encode(image.astype(np.float64), 50), tristream.encode(image, 50))

    def test_bad_arguments_name_the_problem(self):
        image = small_image()
        cases = [
            (dict(), r"give vertices=N, error=E or max_bytes=B"),
            (dict(vertices=3), r"vertices: expected at least 4 \(the corners\), found 3"),
            (dict(vertices=10, max_bytes=100), r"max_bytes: chooses the vertex count itself"),
            (dict(vertices=10, color="mixed"), r"color: expected co\|separate, found 'mixed'"),
            (dict(vertices=10, fit="crop", width=10, height=10), r"fit: expected stretch\|inside\|fill, found 'crop'"),
            (dict(vertices=10, width=10), r"width, height: give the panel's width and height together"),
            (dict(vertices=10, values="pixel", relocate=2), r"relocate: applies to values='lsq' only"),
            (dict(vertices=10, values="pixel", flips=1), r"flips: applies to values='lsq' only"),
            (dict(vertices=10, flips=-1), r"flips: expected 0 to 100"),
            (dict(max_bytes=10), r"max_bytes 10: expected at least \d+ bytes, the smallest compressed blob"),
            (dict(vertices=10, grey=True, space="ycbcr"), r"apply to colour encodings only"),
            (dict(vertices=10, method="coons"), r"method: expected bilinear\|zienkiewicz\|clough-tocher"),
            (dict(vertices=10, gradient_step=3), r"gradient_step: applies to method='zienkiewicz'"),
            (dict(vertices=10, method="zienkiewicz", gradient_step=13), r"gradient_step: expected 0 to 12"),
            (dict(vertices=10, method="zienkiewicz", values="pixel"), r"method: zienkiewicz fits"),
            (dict(max_bytes=5000, method="clough-tocher"), r"method: the core does not draw clough-tocher"),
        ]
        for kwargs, message in cases:
            with self.subTest(**{k: str(v) for k, v in kwargs.items()}):
                with self.assertRaisesRegex(ValueError, message):
                    tristream.encode(image, **kwargs)
        with self.assertRaisesRegex(ValueError, r"photo: pixel \(x 1, y 0\) channel 0 is 300"):
            tristream.encode(np.array([[0, 300], [0, 0]]), 4, name="photo")
        with self.assertRaisesRegex(ValueError, r"photo: expected an array of shape"):
            tristream.encode(np.zeros((4, 4, 4), np.uint8), 4, name="photo")


if __name__ == "__main__":
    unittest.main()
