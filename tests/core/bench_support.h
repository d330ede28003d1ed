/* SPDX-License-Identifier: MIT */
#pragma once
// Benchmark scenes: 512 x 512 RGB triangulations of about N triangles, vertex values sampled from
// the Kodak demo photograph (data/demo/kodim23.png), vertices random on the pixel lattice.
#include <random>
#include <set>
#include <string>

#include "geometry/delaunay.h"
#include "io/image_io.h"
#include "model/triangulation.h"

namespace tristream::testing {

inline Triangulation bench_scene(int triangles, std::uint32_t seed = 1) {
  static const Image photo = read_image(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.png");
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
  Triangulation tri;
  tri.width = w;
  tri.height = h;
  tri.space = ColorSpace::rgb;
  tri.layers = {mesh};
  return tri;
}

}  // namespace tristream::testing
