/* SPDX-License-Identifier: MIT */
#pragma once
// The meshes of the bench-mcu matrix, by name:
//   kodim23  data/demo/kodim23.rgb.tri (768 x 512, 7,964 triangles)
//   scene4k  scenes::bench_scene(4000), 512 x 512 (host_sim/scenes/bench_scenes.h)
//   grid40k  scenes::jittered_grid(142, 1): a 512 x 512 grid of 142 x 142 vertices (39,762
//            triangles), each vertex moved by up to 0.3 of the grid step
#include <string>
#include <vector>

#include "model/triangulation.h"

namespace tristream::bench_mcu {

const std::vector<std::string>& mesh_names();
// Throws UsageError for an unknown name.
Triangulation make_mesh(const std::string& name);

}  // namespace tristream::bench_mcu
