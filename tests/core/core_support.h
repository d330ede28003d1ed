/* SPDX-License-Identifier: MIT */
#pragma once
// Helpers of the core tests: meshes with sub-pixel vertices, core renders at any tiling.
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "../support/random_mesh.h"
#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"
#include "core_bridge/unpack.h"
#include "geometry/delaunay.h"

namespace tristream::testing {

inline Triangulation single_mesh(const Mesh& mesh, int w, int h, ColorSpace space = ColorSpace::grey) {
  Triangulation t;
  t.width = w;
  t.height = h;
  t.space = space;
  t.layers = {mesh};
  return t;
}

// Delaunay mesh of `n` random points on the 1/16-pixel grid of [0, W-1] x [0, H-1]; with
// `corners` the four image corners are added, otherwise the domain is the points' convex hull.
inline Mesh random_subpixel_mesh(int w, int h, int n, std::uint32_t seed, bool corners, int value_count = 1) {
  std::mt19937 rng(seed);
  std::set<std::pair<int, int>> taken;
  Mesh mesh;
  mesh.value_count = value_count;
  if (corners)
    for (auto [x, y] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}}) {
      taken.insert({16 * x, 16 * y});
      mesh.points.push_back({double(x), double(y)});
    }
  std::uniform_int_distribution<int> rx(0, 16 * (w - 1)), ry(0, 16 * (h - 1));
  while (int(mesh.points.size()) < n) {
    std::pair<int, int> p{rx(rng), ry(rng)};
    if (rng() % 3 == 0) p = {p.first & ~15, p.second & ~15};  // many on the pixel lattice
    if (taken.insert(p).second) mesh.points.push_back({p.first / 16.0, p.second / 16.0});
  }
  std::uniform_real_distribution<double> rv(0, 255);
  for (std::size_t i = 0; i < mesh.points.size() * value_count; ++i) mesh.values.push_back(rv(rng));
  mesh.triangles = delaunay_triangulation(mesh.points);
  return mesh;
}

// Tile shapes every output must be identical across (0 = whole viewport side).
struct Tiling {
  int w, h;
};
// The core's parameters of a host render's options with the tiling t.
// A zienkiewicz blob of `tri` whose gradients are the packer's estimate rounded to multiples of
// 2^bits (as a fitted encoder's coarse step), given to pack_blob explicitly. `odd`: one component
// of each layer then moved by one toward 0, so that the compressor's step is 0.
inline std::vector<std::uint8_t> stepped_gradient_blob(const Triangulation& tri, int bits, bool odd = false) {
  UnpackedBlob u = unpack_blob(pack_blob(tri, core::Method::zienkiewicz), "stepped");
  const std::int32_t half = std::int32_t(1) << (bits - 1), mask = ~((std::int32_t(1) << bits) - 1);
  for (auto& layer : u.gradients)
    for (std::int32_t& g : layer) g = g >= 0 ? (g + half) & mask : -((-g + half) & mask);
  if (odd)
    for (auto& layer : u.gradients) {
      std::int32_t& g = layer[layer.size() / 2];
      g = g > 0 ? g - 1 : g + 1;
    }
  return pack_blob(u.tri, core::Method::zienkiewicz, "stepped", &u.gradients);
}

inline core::RenderParams params_of(const CoreOptions& o, Tiling t) {
  core::RenderParams p;
  p.output_width = std::uint16_t(o.width);
  p.output_height = std::uint16_t(o.height);
  p.fit = o.fit;
  p.viewport = o.viewport;
  p.tile_width = std::uint16_t(t.w);
  p.tile_height = std::uint16_t(t.h);
  p.format = o.format;
  p.dither = o.dither;
  for (int c = 0; c < 3; ++c) p.background[c] = o.background.rgb[c];
  return p;
}

inline const std::vector<Tiling>& all_tilings() {
  static const std::vector<Tiling> t = {{0, 0}, {1, 0}, {0, 1}, {8, 8}, {13, 7}, {32, 32}, {64, 64}, {0, 16}, {5, 1}};
  return t;
}

inline CoreFrame core_frame(const std::vector<std::uint8_t>& blob, CoreOptions o, Tiling t) {
  o.tile_width = t.w;
  o.tile_height = t.h;
  CoreRenderer r(blob, o);
  CoreFrame f;
  r.render(f);
  return f;
}

// Number of bytes that differ (and the size difference), for compact test messages.
inline std::size_t bytes_differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  std::size_t n = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != b[i];
  return n;
}

}  // namespace tristream::testing
