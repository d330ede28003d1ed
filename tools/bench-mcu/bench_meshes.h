/* SPDX-License-Identifier: MIT */
#pragma once
// The meshes of the bench-mcu matrix, by name:
//   kodim23  data/demo/kodim23.rgb.tri (768 x 512, 7,964 triangles)
//   scene4k  tests/core/bench_support.h's 512 x 512 benchmark scene of about 4,000 triangles
//   grid40k  a 512 x 512 grid of 142 x 142 vertices (39,762 triangles), each vertex moved by up
//            to 0.3 of the grid step (border vertices along the border), values from the demo
//            photograph: deterministic
#include <string>
#include <vector>

#include "model/triangulation.h"

namespace tristream::bench_mcu {

const std::vector<std::string>& mesh_names();
// Throws UsageError for an unknown name.
Triangulation make_mesh(const std::string& name);
Triangulation jittered_grid(int points_per_side, unsigned seed);

}  // namespace tristream::bench_mcu
