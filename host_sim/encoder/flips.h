/* SPDX-License-Identifier: MIT */
#pragma once
// A post-pass of the encoder: data-dependent triangulation. Interior edges are flipped where
// the other diagonal of their quadrilateral lowers the squared error of the linear interpolant
// (Yu, Morse and Sederberg 2001, "Image reconstruction using data-dependent triangulation").
// The mesh is then no longer Delaunay: the vertices keep their positions, the triangles change.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "encoder/planes.h"
#include "model/triangulation.h"

namespace tristream::encoder {

struct FlipReport {
  std::size_t flips = 0;  // edges flipped
  std::vector<std::uint8_t> touched;  // per vertex: 1 if a triangle around it changed
  double sse_before = 0;  // squared error of the linear interpolant before and after (values unrounded)
  double sse_after = 0;
};

// `mesh`: triangles of positive orientation (orient as in model/triangulation.h) tiling
// [0, W-1] x [0, H-1] of `target`, vertices at distinct pixel positions, values fitted (e.g. by
// least squares). Visits the interior edges from a work list (first every edge in triangle
// order, then the four outer edges of each flip); an edge whose quadrilateral is strictly convex
// is flipped when the two new triangles' squared error over the quadrilateral's pixels (the same
// pixels either way), with the vertex values held, is below the two old ones' by more than
// rounding noise. Each flip lowers the total, so the search ends. Triangles stay positively
// oriented, their count and the values do not change. Deterministic.
FlipReport flip_edges(Mesh& mesh, const Planes& target);

}  // namespace tristream::encoder
