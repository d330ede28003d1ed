/* SPDX-License-Identifier: MIT */
#pragma once
// Benchmark scenes, shared by the core's benchmarks (tests/core) and bench_mcu: 512 x 512 RGB
// triangulations whose vertex values are the Kodak demo photograph's (data/demo/kodim23.png) at
// the vertex, 100 pixels to the right. Deterministic for a seed.
#include <cstdint>

#include "model/triangulation.h"

namespace tristream::scenes {

// About `triangles` triangles: the four corners and random distinct vertices on the pixel
// lattice (triangles / 2 + 2 in all), Delaunay.
Triangulation bench_scene(int triangles, std::uint32_t seed = 1);

// A grid of n x n vertices (n = points_per_side), each moved by up to 0.3 of the grid step (border
// vertices along the border) and rounded to the core's 1/16-pixel lattice, Delaunay: 2 (n-1)^2
// triangles.
Triangulation jittered_grid(int points_per_side, unsigned seed);

// The demo photograph's central 512 x 512 in grey (BT.601 luma), encoded by the greedy encoder at
// 1 % of its pixels (2,621 vertices; encode() with its default options): what triencode --grey
// -n 2621 --width 512 --height 512 --fit fill makes of data/demo/kodim23.png. About a second.
Triangulation grey_photo_1pct();

// Meshes whose connectivity a compressed stream must code far from the triangles' first corners
// (issue 44 item 4: before the reach limit of compressed_blob.h they decoded in quadratic time),
// 2048 x 64, RGB from the demo photograph along y = 32, on the 1/16-pixel lattice:
// A two-row strip: `per_row` vertices along y = 0 and as many along y = 63, each pair of
// neighbours joined to the other row, 2 (per_row - 1) triangles.
Triangulation two_row_strip(int per_row);
// A fan of thin triangles: one apex at the top middle and `rim` vertices along y = 63, rim - 1
// triangles.
Triangulation thin_fan(int rim);

}  // namespace tristream::scenes
