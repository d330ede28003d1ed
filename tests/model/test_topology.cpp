// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>

#include <vector>

#include "model/topology.h"
#include "../support/random_mesh.h"

using namespace tristream;

TEST_CASE("topology of a split square") {
  Mesh m;
  m.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  m.values = {0, 0, 0, 0};
  m.triangles = {{{0, 2, 1}}, {{0, 3, 2}}};
  m.normalize_winding();
  for (std::size_t t = 0; t < m.triangles.size(); ++t) CHECK(m.doubled_area(t) > 0);
  Topology topo = build_topology(m);
  int shared = 0, boundary = 0;
  for (std::uint32_t t = 0; t < 2; ++t)
    for (int e = 0; e < 3; ++e) {
      if (topo.is_boundary_edge(t, e)) ++boundary;
      else {
        CHECK(topo.neighbour[3 * t + e] == 1 - t);
        ++shared;
      }
    }
  CHECK(shared == 2);
  CHECK(boundary == 4);
  CHECK(topo.vertex_start[1] - topo.vertex_start[0] == 2);  // vertex 0 is in both
  CHECK(topo.vertex_start[2] - topo.vertex_start[1] == 1);
}

// Neighbours by brute force: every pair of triangles sharing an undirected edge.
namespace {
std::vector<std::uint32_t> brute_force_neighbours(const Mesh& mesh) {
  std::vector<std::uint32_t> out(3 * mesh.triangles.size(), no_neighbour);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = mesh.triangles[t].v[e], b = mesh.triangles[t].v[(e + 1) % 3];
      for (std::uint32_t u = 0; u < mesh.triangles.size() && out[3 * t + e] == no_neighbour; ++u) {
        if (u == t) continue;
        for (int f = 0; f < 3; ++f) {
          const std::uint32_t c = mesh.triangles[u].v[f], d = mesh.triangles[u].v[(f + 1) % 3];
          if ((c == a && d == b) || (c == b && d == a)) out[3 * t + e] = u;
        }
      }
    }
  return out;
}
}  // namespace

TEST_CASE("build_topology: neighbours as a brute-force search finds them, fans in triangle order") {
  auto check = [](const Mesh& mesh) {
    const Topology topo = build_topology(mesh);
    CHECK(topo.neighbour == brute_force_neighbours(mesh));
    REQUIRE(topo.vertex_start.size() == mesh.points.size() + 1);
    for (std::uint32_t v = 0; v < mesh.points.size(); ++v) {
      std::vector<std::uint32_t> fan;
      for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t w : mesh.triangles[t].v)
          if (w == v) fan.push_back(t);
      CHECK(std::vector<std::uint32_t>(topo.vertex_triangles.begin() + topo.vertex_start[v],
                                       topo.vertex_triangles.begin() + topo.vertex_start[v + 1]) == fan);
    }
  };
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    check(testing::random_lattice_mesh(60, 45, 300, seed, 0, 1));
    check(testing::random_lattice_mesh(60, 45, 300, seed, 200, 1));  // not Delaunay
  }
  // Holes and boundary edges: every third triangle removed; one triangle with the other winding
  // (edges match in either direction); an unused vertex; the empty mesh.
  Mesh mesh = testing::random_lattice_mesh(40, 30, 150, 9, 0, 1);
  std::vector<Triangle> kept;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (t % 3 != 1) kept.push_back(mesh.triangles[t]);
  mesh.triangles = kept;
  std::swap(mesh.triangles[5].v[0], mesh.triangles[5].v[1]);
  mesh.points.push_back({100, 100});
  mesh.values.push_back(0);
  check(mesh);
  check(Mesh{});
}
