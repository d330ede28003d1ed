// SPDX-License-Identifier: MIT
#include "scenes/bench_scenes.h"

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "geometry/delaunay.h"
#include "io/image_io.h"

namespace tristream::scenes {
namespace {

const Image& demo_photo() {
  static const Image photo = read_image(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.png");
  return photo;
}

Triangulation rgb_scene(Mesh mesh, int w, int h) {
  Triangulation tri;
  tri.width = w;
  tri.height = h;
  tri.space = ColorSpace::rgb;
  tri.layers = {std::move(mesh)};
  return tri;
}

}  // namespace

Triangulation bench_scene(int triangles, std::uint32_t seed) {
  const Image& photo = demo_photo();
  const int w = 512, h = 512;
  std::mt19937 rng(seed);
  Mesh mesh;
  mesh.value_count = 3;
  std::set<std::pair<int, int>> taken;
  auto add = [&](int x, int y) {
    if (!taken.insert({x, y}).second) return;
    mesh.points.push_back({double(x), double(y)});
    for (int c = 0; c < 3; ++c) mesh.values.push_back(photo.at(x + 100, y, c % photo.channels));
  };
  for (auto [x, y] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}}) add(x, y);
  // A Delaunay triangulation of n points has about 2n triangles.
  const std::size_t vertices = std::size_t(triangles / 2 + 2);
  while (mesh.points.size() < vertices) add(int(rng() % w), int(rng() % h));
  mesh.triangles = delaunay_triangulation(mesh.points);
  return rgb_scene(std::move(mesh), w, h);
}

Triangulation jittered_grid(int n, unsigned seed) {
  const Image& photo = demo_photo();
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
  return rgb_scene(std::move(mesh), w, h);
}

}  // namespace tristream::scenes
