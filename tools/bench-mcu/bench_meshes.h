/* SPDX-License-Identifier: MIT */
#pragma once
// The meshes of the bench-mcu matrix, by name:
//   kodim23  data/demo/kodim23.rgb.tri (768 x 512, 7,964 triangles)
//   grey1pct scenes::grey_photo_1pct(): 512 x 512 grey, the demo photograph's centre at 1 % vertices
//   scene4k  scenes::bench_scene(4000), 512 x 512 (host_sim/scenes/bench_scenes.h)
//   grid40k  scenes::jittered_grid(142, 1): a 512 x 512 grid of 142 x 142 vertices (39,762
//            triangles), each vertex moved by up to 0.3 of the grid step
//   strip5k  scenes::two_row_strip(2500): 2048 x 64, two rows of 2,500 vertices (4,998 triangles)
//   fan4k    scenes::thin_fan(4000): 2048 x 64, an apex and 4,000 vertices in a row (3,999 triangles)
//            (both compress to streams that decoded in quadratic time before the reach limit)
#include <string>
#include <vector>

#include "model/triangulation.h"

namespace tristream::bench_mcu {

const std::vector<std::string>& mesh_names();
// Throws UsageError for an unknown name.
Triangulation make_mesh(const std::string& name);

}  // namespace tristream::bench_mcu
