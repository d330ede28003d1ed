// SPDX-License-Identifier: MIT
#include "scenes/bench_scenes.h"

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "encoder/encoder.h"
#include "encoder/panel.h"
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

// `n` vertices along y at equal steps from x = 0 to 2047, on the 1/16-pixel lattice, appended to
// `mesh`; their values the photograph's along its row 32.
void add_row(Mesh& mesh, int n, double y) {
  const Image& photo = demo_photo();
  for (int i = 0; i < n; ++i) {
    const double x = std::round(2047.0 * 16 * i / (n - 1)) / 16;
    mesh.points.push_back({x, y});
    for (int c = 0; c < 3; ++c) mesh.values.push_back(photo.at(int(x) % photo.width, 32, c % photo.channels));
  }
}

}  // namespace

Triangulation two_row_strip(int per_row) {
  Mesh mesh;
  mesh.value_count = 3;
  add_row(mesh, per_row, 0);
  add_row(mesh, per_row, 63);
  const auto n = std::uint32_t(per_row);
  for (std::uint32_t i = 0; i + 1 < n; ++i) {
    mesh.triangles.push_back({i, i + 1, n + i});
    mesh.triangles.push_back({i + 1, n + i + 1, n + i});
  }
  return rgb_scene(std::move(mesh), 2048, 64);
}

Triangulation thin_fan(int rim) {
  Mesh mesh;
  mesh.value_count = 3;
  mesh.points.push_back({1023.5, 0});
  for (int c = 0; c < 3; ++c) mesh.values.push_back(128);
  add_row(mesh, rim, 63);
  for (std::uint32_t i = 1; i < std::uint32_t(rim); ++i) mesh.triangles.push_back({0, i, i + 1});
  return rgb_scene(std::move(mesh), 2048, 64);
}

Triangulation grey_photo_1pct() {
  const PanelPicture p = fit_to_panel(demo_photo(), 512, 512, Fit::fill);
  EncodeOptions o;
  o.vertices = 512 * 512 / 100;
  o.grey = true;
  return encode(p.picture, o).triangulation;
}

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
