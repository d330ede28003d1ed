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

}  // namespace tristream::scenes
