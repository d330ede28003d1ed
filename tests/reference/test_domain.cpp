// SPDX-License-Identifier: MIT
// The domain seen from the pixels (reference/domain.h): the owner of each pixel equals the
// coverage rule's, and the tests that let natural and voronoi skip work are right.
#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/domain.h"

#include "../support/random_mesh.h"

using namespace tristream;

TEST_CASE("owning_triangles follows the coverage rule of for_each_owned_pixel") {
  for (std::uint32_t seed : {11u, 12u, 13u, 14u}) {
    const Mesh mesh = tristream::testing::random_lattice_mesh(40, 30, 60, seed, 40);
    const Topology topo = build_topology(mesh);
    for (auto [w, h] : {std::pair{40, 30}, std::pair{97, 61}, std::pair{13, 11}}) {
      INFO("seed " << seed << ", output " << w << "x" << h);
      const PixelMapping map(40, 30, w, h);
      std::vector<std::uint32_t> expected(std::size_t(w) * h, no_neighbour);
      std::vector<int> visits(std::size_t(w) * h, 0);
      for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for_each_owned_pixel(mesh, topo, t, map, [&](int i, int j, double, double, double) {
          expected[std::size_t(j) * w + i] = t;
          ++visits[std::size_t(j) * w + i];
        });
      CHECK(std::count(visits.begin(), visits.end(), 1) == w * h);
      CHECK(owning_triangles(mesh, topo, map) == expected);
    }
  }
}

TEST_CASE("is_locally_delaunay and covers_rectangle tell a Delaunay mesh of the rectangle") {
  const Mesh delaunay = tristream::testing::random_lattice_mesh(50, 40, 120, 31, 0, 1);
  const Mesh flipped = tristream::testing::random_lattice_mesh(50, 40, 120, 31, 60, 1);
  CHECK(is_locally_delaunay(delaunay, build_topology(delaunay)));
  CHECK_FALSE(is_locally_delaunay(flipped, build_topology(flipped)));
  CHECK(covers_rectangle(delaunay, 49, 39));
  CHECK(covers_rectangle(flipped, 49, 39));
  CHECK_FALSE(covers_rectangle(delaunay, 50, 39));
  Mesh partial = delaunay;
  partial.triangles.pop_back();
  CHECK_FALSE(covers_rectangle(partial, 49, 39));
}
