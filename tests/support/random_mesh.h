/* SPDX-License-Identifier: MIT */
#pragma once
// Random triangulations for property tests: vertices on lattice points of a W x H image
// (the four corners always included), Delaunay-triangulated, then optionally made
// non-Delaunay by random flips of convex quadrilaterals.
#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "geometry/delaunay.h"
#include "geometry/predicates.h"
#include "model/topology.h"
#include "model/triangulation.h"

namespace tristream::testing {

inline Mesh random_lattice_mesh(int width, int height, int interior_points, std::uint32_t seed, int flips = 0,
                                int value_count = 1) {
  std::mt19937 rng(seed);
  std::set<std::pair<int, int>> taken = {{0, 0}, {width - 1, 0}, {0, height - 1}, {width - 1, height - 1}};
  Mesh mesh;
  mesh.value_count = value_count;
  for (auto [x, y] : taken) mesh.points.push_back({double(x), double(y)});
  std::uniform_int_distribution<int> rx(0, width - 1), ry(0, height - 1);
  for (int k = 0; k < interior_points * 20 && int(mesh.points.size()) < interior_points + 4; ++k) {
    std::pair<int, int> p{rx(rng), ry(rng)};
    if (taken.insert(p).second) mesh.points.push_back({double(p.first), double(p.second)});
  }
  std::uniform_real_distribution<double> rv(0, 255);
  for (std::size_t i = 0; i < mesh.points.size() * value_count; ++i) mesh.values.push_back(rv(rng));
  mesh.triangles = delaunay_triangulation(mesh.points);

  for (int f = 0; f < flips; ++f) {
    const Topology topo = build_topology(mesh);
    std::uniform_int_distribution<std::uint32_t> rt(0, std::uint32_t(mesh.triangles.size() - 1));
    const std::uint32_t t = rt(rng);
    const int e = int(rng() % 3);
    const std::uint32_t u = topo.neighbour[3 * t + e];
    if (u == no_neighbour) continue;
    const auto tv = mesh.triangles[t].v;
    const std::uint32_t a = tv[e], b = tv[(e + 1) % 3], c = tv[(e + 2) % 3];
    std::uint32_t d = 0;
    for (std::uint32_t w : mesh.triangles[u].v)
      if (w != a && w != b) d = w;
    // Flip edge ab of triangles (a, b, c) and (b, a, d) to cd, when the quad is convex.
    const Point &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c], &pd = mesh.points[d];
    if (orient2d(pc, pd, pb) <= 0 || orient2d(pd, pc, pa) <= 0) continue;
    mesh.triangles[t].v = {c, d, b};
    mesh.triangles[u].v = {d, c, a};
    mesh.normalize_winding();
    (void)pa;
    (void)pb;
  }
  return mesh;
}

}  // namespace tristream::testing
