#include "model/topology.h"

#include <algorithm>
#include <tuple>

namespace tristream {

Topology build_topology(const Mesh& mesh) {
  Topology topo;
  const std::size_t nt = mesh.triangles.size();
  const std::size_t nv = mesh.points.size();
  topo.neighbour.assign(3 * nt, no_neighbour);

  struct HalfEdge {
    std::uint32_t lo, hi, t;
    int e;
  };
  std::vector<HalfEdge> edges;
  edges.reserve(3 * nt);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = mesh.triangles[t].v[e], b = mesh.triangles[t].v[(e + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, e});
    }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& p, const HalfEdge& q) {
    return std::tie(p.lo, p.hi, p.t) < std::tie(q.lo, q.hi, q.t);
  });
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const HalfEdge& p = edges[i];
    const HalfEdge& q = edges[i + 1];
    if (p.lo == q.lo && p.hi == q.hi) {
      topo.neighbour[3 * p.t + p.e] = q.t;
      topo.neighbour[3 * q.t + q.e] = p.t;
      ++i;
    }
  }

  topo.vertex_start.assign(nv + 1, 0);
  for (const Triangle& tri : mesh.triangles)
    for (std::uint32_t v : tri.v) ++topo.vertex_start[v + 1];
  for (std::size_t v = 0; v < nv; ++v) topo.vertex_start[v + 1] += topo.vertex_start[v];
  topo.vertex_triangles.resize(topo.vertex_start[nv]);
  std::vector<std::uint32_t> fill(topo.vertex_start.begin(), topo.vertex_start.end() - 1);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t v : mesh.triangles[t].v) topo.vertex_triangles[fill[v]++] = t;
  return topo;
}

}  // namespace tristream
