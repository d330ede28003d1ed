/* SPDX-License-Identifier: MIT */
#pragma once
// Whether triangles form a mesh the renderers can draw: interiors that do not overlap, and edge to
// edge (no vertex inside another triangle's edge). O(n log n) for n triangles of any shape.
#include <cstdint>
#include <optional>
#include <span>

#include "model/triangulation.h"

namespace tristream {

struct MeshDefect {
  enum class Kind {
    overlap,      // triangles `a` and `b` have overlapping interiors
    t_junction,   // `vertex` lies inside an edge of triangle `a` (and is a vertex of triangle `b`)
  };
  Kind kind;
  std::uint32_t a = 0, b = 0;  // triangle indices
  std::uint32_t vertex = 0;    // for t_junction
};

// The first defect found, or nothing for a valid mesh. `triangles` are non-degenerate with
// orient2d > 0 (the Mesh winding); `points` are distinct. Vertices no triangle uses are ignored.
//
// A plane sweep (Shamos and Hoey) in lexicographic (x, y) order over the triangles' edges, with
// exact orientation predicates. With every triangle positive, interiors overlap or a vertex lies
// inside an edge iff one of these holds, each of which the sweep detects:
// - two triangles lie on the same side of one edge (the directed edge occurs twice);
// - two edges cross, or a vertex lies inside an edge (found between neighbours in the sweep);
// - a vertex lies inside a triangle it does not belong to: then, with no crossings, the edge
//   just below the vertex in the sweep has that triangle above it.
std::optional<MeshDefect> find_mesh_defect(std::span<const Point> points, std::span<const Triangle> triangles);

}  // namespace tristream
