// SPDX-License-Identifier: MIT
#include "model/topology.h"

#include <vector>

namespace tristream {

Topology build_topology(const Mesh& mesh) {
  Topology topo;
  const std::size_t nt = mesh.triangles.size();
  const std::size_t nv = mesh.points.size();

  // Vertex fans by counting sort; beside each fan entry, what matching needs of it: the
  // triangle's vertices after and before the fan's vertex, and the edge's index. Matching an
  // edge then reads only the fan's own packed entries, not each fan triangle's vertices.
  topo.vertex_start.assign(nv + 1, 0);
  for (const Triangle& tri : mesh.triangles)
    for (const std::uint32_t v : tri.v) ++topo.vertex_start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) topo.vertex_start[v + 1] += topo.vertex_start[v];
  topo.vertex_triangles.resize(topo.vertex_start[nv]);
  struct FanEntry {
    std::uint32_t next, prev, edge;
  };
  std::vector<FanEntry> fan(topo.vertex_start[nv]);
  {
    std::vector<std::uint32_t> fill(topo.vertex_start.begin(), topo.vertex_start.end() - 1);
    for (std::uint32_t t = 0; t < nt; ++t) {
      const auto& v = mesh.triangles[t].v;
      for (std::uint32_t e = 0; e < 3; ++e) {
        const std::uint32_t k = fill[v[e]]++;
        topo.vertex_triangles[k] = t;
        fan[k] = {v[e == 2 ? 0 : e + 1], v[e == 0 ? 2 : e - 1], e};
      }
    }
  }

  // Edge e = (a, b) of t is found in a's fan: the other entry whose triangle has the edge
  // {a, b}, that is, whose vertex after or before a is b.
  topo.neighbour.assign(3 * nt, no_neighbour);
  for (std::size_t a = 0; a < nv; ++a) {
    const std::uint32_t b0 = topo.vertex_start[a], b1 = topo.vertex_start[a + 1];
    for (std::uint32_t k = b0; k < b1; ++k) {
      const std::uint32_t b = fan[k].next;
      for (std::uint32_t m = b0; m < b1; ++m)
        if (m != k && (fan[m].prev == b || fan[m].next == b)) {
          topo.neighbour[3 * std::size_t(topo.vertex_triangles[k]) + fan[k].edge] = topo.vertex_triangles[m];
          break;
        }
    }
  }
  return topo;
}

}  // namespace tristream
