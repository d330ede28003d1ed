// SPDX-License-Identifier: MIT
#include "encoder/mesh_adjacency.h"

#include <algorithm>

namespace tristream::encoder {

std::vector<std::array<std::uint32_t, 3>> triangle_neighbours(const Mesh& mesh) {
  struct HalfEdge {
    std::uint64_t key;
    std::uint32_t t;
    int e;
  };
  std::vector<HalfEdge> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint64_t a = mesh.triangles[t].v[e], b = mesh.triangles[t].v[(e + 1) % 3];
      edges.push_back({std::min(a, b) << 32 | std::max(a, b), std::uint32_t(t), e});
    }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.t < y.t;
  });
  std::vector<std::array<std::uint32_t, 3>> across(mesh.triangles.size(), {no_neighbour, no_neighbour, no_neighbour});
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i].key == edges[i + 1].key) {
      across[edges[i].t][edges[i].e] = edges[i + 1].t;
      across[edges[i + 1].t][edges[i + 1].e] = edges[i].t;
    }
  return across;
}

}  // namespace tristream::encoder
