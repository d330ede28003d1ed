/* SPDX-License-Identifier: MIT */
#pragma once
// A post-pass of the encoder: vertices move to neighbouring pixels where that lowers the
// squared error of the linear interpolant, the mesh stays a (Delaunay) triangulation and the
// values stay least-squares fits.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "encoder/planes.h"
#include "model/triangulation.h"

namespace tristream::encoder {

struct RelocateReport {
  int passes = 0;          // passes run
  std::size_t moves = 0;   // vertex moves
  double sse_before = 0;   // linear_squared_error before and after
  double sse_after = 0;
};

// `mesh`: a triangulation of distinct pixel positions tiling [0, W-1] x [0, H-1] of `target`
// (a Delaunay one when `keep_delaunay`), with least-squares values (unrounded or rounded). The
// triangles (connectivity) never change. One pass visits the vertices in index order; each
// tries its 8 neighbouring pixels (border vertices slide along their side, the corners stay)
// where every triangle around it keeps a positive orientation (so the mesh stays a
// triangulation) and, with `keep_delaunay`, every edge of those triangles stays locally
// Delaunay (so the mesh stays a Delaunay triangulation), re-chooses its own value by least
// squares over its triangles, and takes the position of least local squared error. Later
// passes try only vertices next to a move; a pass without moves ends the search. Each move
// lowers the squared error of the pixels it affects, so the total never rises. At the end all
// values are refitted by least squares (unrounded). Deterministic. `first_tried` (one flag per
// vertex), when given, limits the first pass to the flagged vertices, as if the others had been
// tried already (after a change to part of a relocated mesh).
RelocateReport relocate_vertices(Mesh& mesh, const Planes& target, int passes, bool keep_delaunay = true,
                                 const std::vector<std::uint8_t>* first_tried = nullptr);

}  // namespace tristream::encoder
