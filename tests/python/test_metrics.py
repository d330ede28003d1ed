# SPDX-License-Identifier: MIT
"""psnr, ssim and mse equal trisim metrics' figures to 1e-9 (item: metrics)."""
import unittest

import numpy as np
import tristream

from support import DEMO, ScratchTest, tool, tool_json


class MetricsEqualTrisim(ScratchTest):
    def pair(self, tri):
        """The demo image and a render of it as PNGs (the files trisim measures) and as arrays."""
        render = self.dir / "render.png"
        tool("trisim", "render", tri, "--method", "bilinear", "-o", render)
        original = DEMO / "kodim23.png"
        return original, render, tristream.read_image(original), tristream.read_image(render)

    def check(self, a_path, b_path, a, b):
        for window in ("gaussian", "8x8"):
            expected = tool_json("trisim", "metrics", a_path, b_path, "--ssim-window", window)
            self.assertClose(tristream.mse(a, b), expected["mse"], "mse")
            self.assertClose(tristream.psnr(a, b), expected["psnr"], "psnr")
            self.assertClose(tristream.ssim(a, b, window=window), expected["ssim"], f"ssim {window}")
            together = tristream.metrics(a, b, window=window)
            for key in ("mse", "psnr", "ssim"):
                self.assertClose(together[key], expected[key], f"metrics()['{key}'] {window}")

    def test_colour(self):
        self.check(*self.pair(DEMO / "kodim23.rgb.tri"))

    def test_grey(self):
        # Both files grey: the grey render and the original written as grey.
        _, render, original, rendered = self.pair(DEMO / "kodim23.grey.tri")
        grey = tristream.render(tristream.read_tri(DEMO / "kodim23.grey.tri"))
        self.assertTrue(np.array_equal(grey, rendered))
        luma = self.dir / "luma.png"
        tristream.write_png(luma, (original.astype(float) @ [0.299, 0.587, 0.114]).round().astype(np.uint8))
        self.check(luma, render, tristream.read_image(luma), rendered)

    def test_identical_images_have_infinite_psnr(self):
        image = tristream.read_image(DEMO / "kodim23.png")
        path = DEMO / "kodim23.png"
        self.assertEqual(tristream.psnr(image, image), float("inf"))
        self.assertIsNone(tool_json("trisim", "metrics", path, path)["psnr"])
        self.assertEqual(tristream.mse(image, image), 0.0)

    def test_float_arrays_of_integers_measure_alike(self):
        a = tristream.read_image(DEMO / "kodim23.png")
        b = tristream.render(tristream.read_tri(DEMO / "kodim23.rgb.tri"))
        self.assertEqual(tristream.mse(a.astype(np.float64), b.astype(np.float32)), tristream.mse(a, b))

    def test_bad_input_names_the_problem(self):
        a = tristream.read_image(DEMO / "kodim23.png")
        with self.assertRaisesRegex(ValueError, r"image sizes differ"):
            tristream.mse(a, a[:-1])
        with self.assertRaisesRegex(ValueError, r"b: pixel \(x 0, y 0\) channel 0 is 0\.5; expected integers 0 to 255"):
            tristream.psnr(a, np.full(a.shape, 0.5))
        with self.assertRaisesRegex(ValueError, r"a: expected an array of shape \(H, W\), \(H, W, 1\) or \(H, W, 3\), found \(4,\)"):
            tristream.mse(np.zeros(4), a)
        with self.assertRaisesRegex(ValueError, r"window: expected gaussian\|8x8, found 'box'"):
            tristream.ssim(a, a, window="box")


if __name__ == "__main__":
    unittest.main()
