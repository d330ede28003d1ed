#include "model/topology.h"

namespace tristream {

Topology build_topology(const Mesh& mesh) {
  Topology topo;
  const std::size_t nt = mesh.triangles.size();
  const std::size_t nv = mesh.points.size();

  // Vertex fans by counting sort.
  topo.vertex_start.assign(nv + 1, 0);
  for (const Triangle& tri : mesh.triangles)
    for (std::uint32_t v : tri.v) ++topo.vertex_start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) topo.vertex_start[v + 1] += topo.vertex_start[v];
  topo.vertex_triangles.resize(topo.vertex_start[nv]);
  std::vector<std::uint32_t> fill(topo.vertex_start.begin(), topo.vertex_start.end() - 1);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t v : mesh.triangles[t].v) topo.vertex_triangles[fill[v]++] = t;

  // The neighbour across edge (a, b) of t is the other triangle of a's fan that has edge (a, b).
  topo.neighbour.assign(3 * nt, no_neighbour);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      if (topo.neighbour[3 * t + e] != no_neighbour) continue;
      const std::uint32_t a = mesh.triangles[t].v[e], b = mesh.triangles[t].v[(e + 1) % 3];
      for (std::uint32_t k = topo.vertex_start[a]; k < topo.vertex_start[a + 1]; ++k) {
        const std::uint32_t u = topo.vertex_triangles[k];
        if (u == t) continue;
        const auto& uv = mesh.triangles[u].v;
        for (int f = 0; f < 3; ++f) {
          const std::uint32_t p = uv[f], q = uv[(f + 1) % 3];
          if ((p == b && q == a) || (p == a && q == b)) {
            topo.neighbour[3 * t + e] = u;
            topo.neighbour[3 * u + f] = t;
          }
        }
      }
    }
  return topo;
}

}  // namespace tristream
