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

VertexRows vertex_rows(const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  std::vector<std::vector<std::uint32_t>> adjacent(n);
  for (const Triangle& t : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      adjacent[t.v[e]].push_back(t.v[(e + 1) % 3]), adjacent[t.v[e]].push_back(t.v[(e + 2) % 3]);
  VertexRows r;
  r.row.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    auto& a = adjacent[v];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    r.col.push_back(std::uint32_t(v));
    r.col.insert(r.col.end(), a.begin(), a.end());
    r.row[v + 1] = r.col.size();
  }
  return r;
}

std::size_t VertexRows::entry(std::uint32_t i, std::uint32_t j) const {
  if (i == j) return row[i];
  const auto begin = col.begin() + std::ptrdiff_t(row[i]) + 1, end = col.begin() + std::ptrdiff_t(row[i + 1]);
  return std::size_t(std::lower_bound(begin, end, j) - col.begin());
}

}  // namespace tristream::encoder
