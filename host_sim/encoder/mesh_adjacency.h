/* SPDX-License-Identifier: MIT */
#pragma once
// Which triangle lies across each edge of a mesh's triangles, and which vertices share an edge.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/triangulation.h"

namespace tristream::encoder {

inline constexpr std::uint32_t no_neighbour = 0xFFFFFFFFu;

// For each triangle t, the triangle across its edge e (v[e], v[(e + 1) % 3]), or no_neighbour on
// the boundary. The mesh must be a valid triangulation (each edge in at most two triangles).
std::vector<std::array<std::uint32_t, 3>> triangle_neighbours(const Mesh& mesh);

// The sparsity of the least-squares fits' normal equations (compressed sparse rows): row v lists v
// itself, then its edge neighbours in increasing order.
struct VertexRows {
  std::vector<std::size_t> row;  // vertex v's entries are [row[v], row[v + 1])
  std::vector<std::uint32_t> col;
  // The entry of (i, j), j being i or one of its neighbours.
  std::size_t entry(std::uint32_t i, std::uint32_t j) const;
};

VertexRows vertex_rows(const Mesh& mesh);

}  // namespace tristream::encoder
