/* SPDX-License-Identifier: MIT */
#pragma once
// The triangulated domain seen from the output pixels, for the methods that do not walk
// triangles themselves (natural, voronoi): which triangle owns each pixel under the coverage
// rule (coverage.h), whether the domain is the whole image rectangle, and whether the mesh is
// already a Delaunay triangulation of its vertices.
#include <cstdint>
#include <vector>

#include "model/topology.h"
#include "model/triangulation.h"
#include "reference/coverage.h"

namespace tristream {

// For every output pixel, the triangle of `mesh` that owns its sample point under the rule of
// reference/coverage.h (for_each_owned_pixel), or no_neighbour outside the domain; row-major.
// Per triangle and row it finds the span with a few exact orient2d tests at its ends instead
// of one test per pixel of the bounding box.
std::vector<std::uint32_t> owning_triangles(const Mesh& mesh, const Topology& topo, const PixelMapping& map);

// Whether every vertex is in a triangle and every interior edge is locally Delaunay (the
// apex across it is not strictly inside the triangle's circumcircle; exact). With a convex
// domain this makes the mesh a Delaunay triangulation of its vertices.
bool is_locally_delaunay(const Mesh& mesh, const Topology& topo);

// Whether the mesh's domain is the whole rectangle [0, xmax] x [0, ymax]: its four corners are
// vertices, no vertex lies outside it (so it is the hull), and the triangles, which do not
// overlap in a valid mesh, cover its area (the sum is exact for coordinates on a binary grid
// such as pixel positions; for other coordinates, an area short of the rectangle's by less than
// rounding would pass).
bool covers_rectangle(const Mesh& mesh, double xmax, double ymax);

}  // namespace tristream
