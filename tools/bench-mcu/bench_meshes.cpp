// SPDX-License-Identifier: MIT
#include "bench_meshes.h"

#include <cmath>
#include <random>

#include "bench_support.h"
#include "core_support.h"
#include "common/errors.h"
#include "geometry/delaunay.h"
#include "io/image_io.h"
#include "io/tri_file.h"

namespace tristream::bench_mcu {

const std::vector<std::string>& mesh_names() {
  static const std::vector<std::string> names = {"kodim23", "scene4k", "grid40k"};
  return names;
}

Triangulation jittered_grid(int n, unsigned seed) {
  const Image photo = read_image(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.png");
  const int w = 512, h = 512;
  const double step = double(w - 1) / (n - 1);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3 * step, 0.3 * step);
  Mesh mesh;
  mesh.value_count = 3;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double x = i * step, y = j * step;
      const double dx = jitter(rng), dy = jitter(rng);
      if (i > 0 && i < n - 1) x += dx;
      if (j > 0 && j < n - 1) y += dy;
      // On the core's 1/16-pixel lattice, so packing moves no vertex.
      x = std::round(x * 16) / 16;
      y = std::round(y * 16) / 16;
      mesh.points.push_back({x, y});
      for (int c = 0; c < 3; ++c)
        mesh.values.push_back(photo.at(int(std::lround(x)) + 100, int(std::lround(y)), c % photo.channels));
    }
  mesh.triangles = delaunay_triangulation(mesh.points);
  return testing::single_mesh(mesh, w, h, ColorSpace::rgb);
}

Triangulation make_mesh(const std::string& name) {
  if (name == "kodim23") return read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.rgb.tri");
  if (name == "scene4k") return testing::bench_scene(4000);
  if (name == "grid40k") return jittered_grid(142, 1);
  throw UsageError("unknown mesh '" + name + "' (expected kodim23, scene4k or grid40k)");
}

}  // namespace tristream::bench_mcu
