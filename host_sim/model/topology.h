/* SPDX-License-Identifier: MIT */
#pragma once
// Adjacency of a mesh: the neighbour across each triangle edge and the triangles around
// each vertex. Edge e of triangle t joins t.v[e] and t.v[(e + 1) % 3].
#include <cstdint>
#include <vector>

#include "model/triangulation.h"

namespace tristream {

inline constexpr std::uint32_t no_neighbour = 0xFFFFFFFFu;

struct Topology {
  // neighbour[3 * t + e]: triangle across edge e of t, or no_neighbour on the domain boundary.
  std::vector<std::uint32_t> neighbour;
  // Triangles incident to vertex v: vertex_triangles[vertex_start[v] .. vertex_start[v + 1]).
  std::vector<std::uint32_t> vertex_start;
  std::vector<std::uint32_t> vertex_triangles;

  bool is_boundary_edge(std::uint32_t t, int e) const { return neighbour[3 * t + e] == no_neighbour; }
};

// Builds the adjacency in time linear in the mesh size (fans, then a search of one fan per
// edge). Each undirected edge must be shared by at most two triangles (the reader
// guarantees it); winding does not matter.
Topology build_topology(const Mesh& mesh);

}  // namespace tristream
