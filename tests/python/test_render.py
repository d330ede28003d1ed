# SPDX-License-Identifier: MIT
"""render equals trisim render: the reference's pixels for every method, the core's frames (decoded
and raw) for .tri files and blobs; the float render is the 8-bit one before rounding (item: render)."""
import unittest

import numpy as np
import tristream

from support import GOLDEN, ScratchTest, tool

METHODS = ["bilinear", "zienkiewicz", "bezier", "coons", "voronoi", "natural", "clough-tocher"]


class RenderEqualsTrisim(ScratchTest):
    def trisim_png(self, source, *args):
        out = self.dir / "trisim.png"
        tool("trisim", "render", source, *args, "-o", out)
        return tristream.read_image(out)

    def test_reference_every_method(self):
        for name in ("rgb.tri", "grey.tri", "ycbcr-layers.tri"):
            tri = tristream.read_tri(GOLDEN / name)
            for method in METHODS:
                with self.subTest(tri=name, method=method):
                    ours = tristream.render(tri, method)
                    self.assertTrue(np.array_equal(ours, self.trisim_png(GOLDEN / name, "--method", method)))

    def test_reference_size_fit_background(self):
        tri = tristream.read_tri(GOLDEN / "rgb.tri")
        ours = tristream.render(tri, "zienkiewicz", width=200, height=90, fit="inside", background=(10, 20, 30))
        theirs = self.trisim_png(GOLDEN / "rgb.tri", "--method", "zienkiewicz", "--width", 200, "--height", 90,
                                 "--fit", "inside", "--background", "10,20,30")
        self.assertEqual(ours.shape, (90, 200, 3))
        self.assertTrue(np.array_equal(ours, theirs))

    def test_core_frames(self):
        for name, method, fmt in (("rgb.tri", "bilinear", "rgb565be"), ("rgb.tri", "zienkiewicz", "xrgb8888"),
                                  ("grey.tri", "bilinear", "l8"), ("ycbcr-layers.tri", "zienkiewicz", "rgb888")):
            with self.subTest(tri=name, method=method, format=fmt):
                tri = tristream.read_tri(GOLDEN / name)
                args = ["--engine", "core", "--method", method, "--format", fmt, "--tile-width", 24, "--tile-height", 16]
                ours = tristream.render(tri, method, engine="core", format=fmt, tile_width=24, tile_height=16)
                self.assertTrue(np.array_equal(ours, self.trisim_png(GOLDEN / name, *args)))
                raw = self.dir / "frame.raw"
                tool("trisim", "render", GOLDEN / name, *args, "--raw", "-o", raw)
                frame = tristream.render(tri, method, engine="core", format=fmt, tile_width=24, tile_height=16, raw=True)
                self.assertEqual(frame.tobytes(), raw.read_bytes())

    def test_core_dither_viewport(self):
        tri = tristream.read_tri(GOLDEN / "rgb.tri")
        ours = tristream.render(tri, "bilinear", engine="core", format="rgb565le", dither=True, width=300, height=200,
                                viewport=(10, 20, 250, 180), tile=0)
        theirs = self.trisim_png(GOLDEN / "rgb.tri", "--engine", "core", "--format", "rgb565le", "--dither",
                                 "--width", 300, "--height", 200, "--viewport", "10,20,250,180", "--tile", 0)
        self.assertEqual(ours.shape, (160, 240, 3))
        self.assertTrue(np.array_equal(ours, theirs))

    def test_blobs(self):
        # A blob's bytes are drawn by the core with its own method, as trisim draws the file.
        for name, compress in (("rgb-zienkiewicz.bin", False), ("grey-bilinear.bin", False)):
            blob = (GOLDEN / name).read_bytes()
            with self.subTest(blob=name):
                self.assertTrue(np.array_equal(tristream.render(blob), self.trisim_png(GOLDEN / name)))
                reference = tristream.render(blob, engine="reference", method="natural")
                theirs = self.trisim_png(GOLDEN / name, "--engine", "reference", "--method", "natural")
                self.assertTrue(np.array_equal(reference, theirs))
        compressed = tristream.pack(tristream.read_tri(GOLDEN / "rgb.tri"), "bilinear", compress=True)
        path = self.dir / "c.bin"
        path.write_bytes(compressed)
        self.assertTrue(np.array_equal(tristream.render(compressed, format="rgb565be"),
                                       self.trisim_png(path, "--format", "rgb565be")))

    def test_float_render_rounds_to_the_8_bit_one(self):
        for name in ("rgb.tri", "ycbcr-layers.tri", "grey.tri"):
            tri = tristream.read_tri(GOLDEN / name)
            with self.subTest(tri=name):
                field = tristream.render(tri, "coons", dtype="float64", width=150, height=150, fit="inside")
                image = tristream.render(tri, "coons", width=150, height=150, fit="inside")
                self.assertEqual(field.dtype, np.float64)
                self.assertEqual(field.shape, image.shape)
                inside = ~np.isnan(field)
                self.assertTrue(inside.any() and not inside.all())  # the border of fit='inside'
                rounded = np.floor(np.clip(field[inside], 0, 255) + 0.5)
                self.assertTrue(np.array_equal(rounded.astype(np.uint8), image[inside]))
                self.assertTrue((image[~inside] == 0).all())
                self.assertTrue(((field[inside] < 0) | (field[inside] > 255) | (field[inside] % 1 != 0)).any())

    def test_bad_options_name_the_problem(self):
        tri = tristream.read_tri(GOLDEN / "rgb.tri")
        cases = [
            (dict(method="cubic"), r"method: expected bilinear\|.*clough-tocher, found 'cubic'"),
            (dict(method="natural", engine="core"), r"the core renders|bilinear or zienkiewicz"),
            (dict(tile=16), r"tile, .*: apply to engine='core' only"),
            (dict(engine="core", dtype="float64"), r"dtype: the core renders 8-bit pixels"),
            (dict(engine="core", dither=True), r"dither: applies to format rgb565le and rgb565be only"),
            (dict(engine="core", format="rgb444"), r"rgb444"),
            (dict(background=(1, 2)), r"background: expected one value or \(R, G, B\)"),
            (dict(background=300), r"background: expected integers 0 to 255, found 300"),
            (dict(width=100000, height=100000), r"at most 33554432 pixels"),
            (dict(engine="core", viewport=(5, 5, 2, 9)), r"viewport: expected \(x0, y0, x1, y1\)"),
        ]
        for kwargs, message in cases:
            with self.subTest(**{k: str(v) for k, v in kwargs.items()}):
                with self.assertRaisesRegex(ValueError, message):
                    tristream.render(tri, **kwargs)
        blob = (GOLDEN / "rgb-bilinear.bin").read_bytes()
        with self.assertRaisesRegex(ValueError, r"the blob is packed for bilinear"):
            tristream.render(blob, "zienkiewicz")
        damaged = bytearray(blob)
        damaged[100] ^= 0xFF
        with self.assertRaisesRegex(ValueError, r"blob: byte 36: checksum mismatch"):
            tristream.render(bytes(damaged))


if __name__ == "__main__":
    unittest.main()
