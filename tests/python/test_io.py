# SPDX-License-Identifier: MIT
"""read_tri, write_tri, read_image, write_png, pack and unpack: round trips, pack equals tripack's
bytes, and bad files raise with a message naming the file and the problem (items: io, pack); a
mesh the core's grid would merge raises when packed."""
import unittest

import numpy as np
import tristream

from support import DEMO, GOLDEN, ScratchTest, tool


class TriFiles(ScratchTest):
    def test_round_trip(self):
        for name in ("rgb.tri", "grey.tri", "ycbcr-layers.tri"):
            with self.subTest(tri=name):
                tri = tristream.read_tri(GOLDEN / name)
                path = self.dir / name
                tristream.write_tri(path, tri)
                again = tristream.read_tri(path)
                self.assertEqual(again, tri)
                self.assertEqual(path.read_text(), tri.to_text())
                self.assertEqual(tristream.Triangulation.from_text(tri.to_text()), tri)
                self.assertEqual(tri.layered, name.startswith("ycbcr-layers"))

    def test_missing_file_is_an_oserror(self):
        missing = self.dir / "missing.tri"
        with self.assertRaisesRegex(OSError, "missing.tri"):
            tristream.read_tri(missing)
        with self.assertRaises(tristream.InputError):
            tristream.read_tri(missing)

    def test_malformed_file_names_the_line(self):
        bad = self.dir / "bad.tri"
        bad.write_text((GOLDEN / "grey.tri").read_text().replace("tri 1", "tri 7", 1))
        with self.assertRaisesRegex(ValueError, r"bad\.tri:1: expected"):
            tristream.read_tri(bad)
        with self.assertRaises(tristream.DataError):
            tristream.read_tri(bad)

    def test_unwritable_output_is_an_oserror(self):
        with self.assertRaisesRegex(OSError, "no-such-dir"):
            tristream.write_tri(self.dir / "no-such-dir" / "x.tri", tristream.read_tri(GOLDEN / "grey.tri"))


class Images(ScratchTest):
    def test_png_round_trip(self):
        image = tristream.read_image(DEMO / "kodim23.png")
        self.assertEqual((image.dtype, image.shape), (np.uint8, (512, 768, 3)))
        path = self.dir / "copy.png"
        tristream.write_png(path, image[::2, ::3])
        self.assertTrue(np.array_equal(tristream.read_image(path), image[::2, ::3]))
        grey = image[:, :, 1]
        tristream.write_png(path, grey)
        self.assertTrue(np.array_equal(tristream.read_image(path), grey))

    def test_not_an_image(self):
        with self.assertRaisesRegex(ValueError, "grey.tri"):
            tristream.read_image(GOLDEN / "grey.tri")


class PackEqualsTripack(ScratchTest):
    def test_pack_bytes(self):
        for name in ("rgb.tri", "grey.tri", "ycbcr-layers.tri"):
            tri = tristream.read_tri(GOLDEN / name)
            for method in ("bilinear", "zienkiewicz"):
                for compress in (False, True):
                    with self.subTest(tri=name, method=method, compress=compress):
                        out = self.dir / "blob.bin"
                        tool("tripack", GOLDEN / name, "-o", out, "-m", method, *(["--compress"] if compress else []))
                        blob = tristream.pack(tri, method, compress=compress)
                        self.assertIsInstance(blob, bytes)
                        self.assertEqual(blob, out.read_bytes())

    def test_unpack_packs_to_the_same_bytes(self):
        for name in ("rgb-bilinear.bin", "grey-bilinear.bin", "ycbcr-layers-bilinear.bin"):
            with self.subTest(blob=name):
                blob = (GOLDEN / name).read_bytes()
                tri = tristream.unpack(blob)
                self.assertEqual(tristream.pack(tri, "bilinear"), blob)
        compressed = tristream.pack(tristream.read_tri(GOLDEN / "rgb.tri"), "bilinear", compress=True)
        self.assertEqual(tristream.unpack(compressed).vertices.shape, tristream.unpack(
            tristream.pack(tristream.read_tri(GOLDEN / "rgb.tri"), "bilinear")).vertices.shape)

    def test_bad_blobs_and_methods(self):
        tri = tristream.read_tri(GOLDEN / "rgb.tri")
        with self.assertRaisesRegex(ValueError, r"bezier.*bilinear|bilinear.*bezier"):
            tristream.pack(tri, "bezier")
        with self.assertRaisesRegex(ValueError, r"mine\.bin: byte 4: unsupported blob version"):
            tristream.unpack(b"TSTB" + bytes(60), name="mine.bin")

    def test_vertices_that_round_together_are_refused(self):
        # Two triangles whose tips are 0.01 pixel apart: one point on the core's 1/16-pixel grid.
        text = ("tri 1\nsize 3 3\nchannels grey\nvertices 6\n0 0 10\n2 0 20\n1 1 30\n1 1.01 200\n2 2 40\n"
                "0 2 50\ntriangles 2\n0 1 2\n3 4 5\n")
        tri = tristream.Triangulation.from_text(text)
        message = r"vertices on lines 7 \(1, 1\) and 8 \(1, 1\.01\) both round to \(1, 1\)"
        with self.assertRaisesRegex(tristream.DataError, message):
            tristream.pack(tri)
        with self.assertRaisesRegex(tristream.DataError, message):
            tristream.render(tri, engine="core")
        tristream.render(tri)  # the reference draws the geometry as given


if __name__ == "__main__":
    unittest.main()
