#include <catch2/catch.hpp>

#include "model/topology.h"

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
