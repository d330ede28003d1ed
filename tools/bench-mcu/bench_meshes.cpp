// SPDX-License-Identifier: MIT
#include "bench_meshes.h"

#include "common/errors.h"
#include "io/tri_file.h"
#include "scenes/bench_scenes.h"

namespace tristream::bench_mcu {

const std::vector<std::string>& mesh_names() {
  static const std::vector<std::string> names = {"kodim23", "grey1pct", "scene4k", "grid40k", "strip5k", "fan4k"};
  return names;
}

Triangulation make_mesh(const std::string& name) {
  if (name == "kodim23") return read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.rgb.tri");
  if (name == "grey1pct") return scenes::grey_photo_1pct();
  if (name == "scene4k") return scenes::bench_scene(4000);
  if (name == "grid40k") return scenes::jittered_grid(142, 1);
  if (name == "strip5k") return scenes::two_row_strip(2500);
  if (name == "fan4k") return scenes::thin_fan(4000);
  throw UsageError("unknown mesh '" + name + "' (expected kodim23, grey1pct, scene4k, grid40k, strip5k or fan4k)");
}

}  // namespace tristream::bench_mcu
