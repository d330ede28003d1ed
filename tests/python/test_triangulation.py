# SPDX-License-Identifier: MIT
"""Triangulation and Mesh: vertices, values and triangles as arrays, and a triangulation made from
arrays checked as the .tri reader checks a file (item: vertices and triangles as arrays)."""
import unittest

import numpy as np
import tristream

from support import GOLDEN


class Arrays(unittest.TestCase):
    def test_arrays_of_a_file(self):
        tri = tristream.read_tri(GOLDEN / "rgb.tri")
        self.assertEqual((tri.width, tri.height, tri.space, tri.channels), (192, 128, "rgb", 3))
        v, c, t = tri.vertices, tri.values, tri.triangles
        self.assertEqual((v.dtype, c.dtype, t.dtype), (np.float64, np.float64, np.uint32))
        self.assertEqual(v.shape[1], 2)
        self.assertEqual(c.shape, (len(v), 3))
        self.assertTrue((t < len(v)).all())
        self.assertEqual(set(map(tuple, v[[0]])), {(0.0, 0.0)})
        # The arrays make the same triangulation back.
        self.assertEqual(tristream.Triangulation(tri.width, tri.height, tri.space, v, c, t), tri)

    def test_layers(self):
        tri = tristream.read_tri(GOLDEN / "ycbcr-layers.tri")
        self.assertEqual([m.name for m in tri.layers], ["y", "cb", "cr"])
        with self.assertRaisesRegex(ValueError, r"layered triangulation has one mesh per channel"):
            tri.vertices
        again = tristream.Triangulation.from_layers(
            tri.width, tri.height, "ycbcr", [(m.vertices, m.values, m.triangles) for m in tri.layers])
        self.assertEqual(again, tri)

    def test_gradients(self):
        square = np.array([[0, 0], [9, 0], [0, 9], [9, 9]], float)
        values = np.array([0.0, 90.0, 45.0, 135.0])  # 10 x + 5 y
        gradients = np.tile([10.0, 5.0], (4, 1))
        tri = tristream.Triangulation(10, 10, "grey", square, values, gradients=gradients)
        self.assertTrue(np.array_equal(tri.layers[0].gradients, gradients))
        self.assertIn("gradients 4\n10 5\n", tri.to_text())
        self.assertEqual(tristream.Triangulation.from_text(tri.to_text()), tri)
        # Exact gradients of linear data: zienkiewicz draws the plane.
        image = tristream.render(tri, "zienkiewicz")
        self.assertEqual((image[0, 9], image[9, 0], image[5, 4]), (90, 45, 65))  # rows are y
        # Others than the estimate change the render.
        steep = tristream.Triangulation(10, 10, "grey", square, values, gradients=gradients * 3)
        self.assertFalse(np.array_equal(tristream.render(steep, "zienkiewicz"), image))
        with self.assertRaisesRegex(ValueError, r"expected gradients as an array of shape \(4, 2\)"):
            tristream.Triangulation(10, 10, "grey", square, values, gradients=np.zeros((4, 6)))
        with self.assertRaisesRegex(ValueError, r"Triangulation:\d+: expected a gradient"):
            tristream.Triangulation(10, 10, "grey", square, values, gradients=gradients * 1e5)

    def test_delaunay_when_no_triangles(self):
        vertices = np.array([[0, 0], [9, 0], [0, 9], [9, 9], [4, 5]], float)
        tri = tristream.Triangulation(10, 10, "grey", vertices, np.arange(5) * 10.0)
        self.assertEqual(tri.triangles.shape, (4, 3))
        self.assertEqual(tri.values.shape, (5, 1))
        image = tristream.render(tri)
        self.assertEqual(image.shape, (10, 10))
        self.assertEqual((image[0, 0], image[9, 9]), (0, 30))

    def test_bad_meshes_name_the_problem(self):
        square = np.array([[0, 0], [9, 0], [0, 9], [9, 9]], float)
        values = np.zeros(4)
        with self.assertRaisesRegex(ValueError, r"overlap"):
            tristream.Triangulation(10, 10, "grey", square, values, [[0, 1, 2], [0, 1, 3]])
        with self.assertRaisesRegex(ValueError, r"triangle 0 names vertex 7; expected 0 to 4 - 1"):
            tristream.Triangulation(10, 10, "grey", square, values, [[0, 1, 7]])
        with self.assertRaisesRegex(ValueError, r"expected values as an array of shape \(4, 3\)"):
            tristream.Triangulation(10, 10, "rgb", square, values)
        with self.assertRaisesRegex(ValueError, r"space: expected grey\|rgb\|ycbcr, found 'cmyk'"):
            tristream.Triangulation(10, 10, "cmyk", square, values)
        with self.assertRaisesRegex(ValueError, r"Triangulation:\d+: expected"):
            tristream.Triangulation(10, 10, "grey", square, values + 300)


if __name__ == "__main__":
    unittest.main()
