/* SPDX-License-Identifier: MIT */
#pragma once
// Which triangle lies across each edge of a mesh's triangles.
#include <array>
#include <cstdint>
#include <vector>

#include "model/triangulation.h"

namespace tristream::encoder {

inline constexpr std::uint32_t no_neighbour = 0xFFFFFFFFu;

// For each triangle t, the triangle across its edge e (v[e], v[(e + 1) % 3]), or no_neighbour on
// the boundary. The mesh must be a valid triangulation (each edge in at most two triangles).
std::vector<std::array<std::uint32_t, 3>> triangle_neighbours(const Mesh& mesh);

}  // namespace tristream::encoder
