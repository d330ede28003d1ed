/* SPDX-License-Identifier: MIT */
#pragma once
// Piecewise linear interpolation on the Voronoi diagram (thesis §3.5, §4.3; docs/CONVENTIONS.md),
// reproduced as the thesis describes it, weaknesses included:
// - The Voronoi diagram comes from the Delaunay triangulation of the mesh's vertices plus
//   three far vertices around them (for a 512 x 512 image the thesis used (256, -10000),
//   (-10000, 10000), (10000, 10000); here: the centre of the vertices' bounding box c and
//   S = 20 * its larger side, giving c + (0, -S), c + (-S, S), c + (S, S)), so every cell of a
//   mesh vertex is a bounded convex polygon of circumcentres.
// - A cell vertex (circumcentre) gets the value of the zienkiewicz interpolant of the mesh at
//   that point; a circumcentre outside the mesh's domain has no value.
// - Cells are clipped to the image rectangle [0, W-1] x [0, H-1] (Sutherland-Hodgman). A
//   vertex made by clipping edge Q_in -> Q_out takes the value of Q_in, the cell vertex on
//   the same edge that is inside (the thesis's rule).
// - A pixel takes the value of the polygon barycentric coordinates of Meyer, Lee, Barr and
//   Desbrun (Eq. 3.12) in the clipped cell of its nearest vertex; on an edge they become the
//   thesis's fallback, linear interpolation along the edge. (The cotangent form with the
//   thesis's exact "cross product == 0" test is unstable: circumcentres carry rounding, so a
//   pixel on an edge gets a tiny non-zero cross product and arbitrary weights; see
//   meyer_coordinates.)
// - Bilinear pre-fill (§4.3): pixels whose cell cannot be interpolated keep the bilinear value
//   of the mesh: cells holding a corner of the image rectangle (the thesis found clipping them
//   "practically impossible") and cells with a vertex that has no value.
// Only pixels in the mesh's domain are written.
#include <cstdint>
#include <span>
#include <vector>

#include "model/topology.h"
#include "reference/render.h"

namespace tristream {

class VoronoiDiagram {
 public:
  // Delaunay triangulation of `points` (distinct, not all collinear) and three far vertices,
  // numbered points.size() .. points.size() + 2.
  explicit VoronoiDiagram(std::span<const Point> points);

  std::size_t site_count() const { return sites_; }
  // The cell of site v: its Voronoi vertices in order around v, one per distinct
  // circumcentre (cocircular Delaunay neighbours, which share a circumcentre, give one).
  std::span<const Point> cell(std::uint32_t v) const;
  // The Delaunay triangle whose circumcentre is each vertex of cell(v).
  std::span<const std::uint32_t> cell_triangles(std::uint32_t v) const;
  // The site nearest to p (a greedy walk over Delaunay neighbours from site `start`; ties
  // keep the site reached first).
  std::uint32_t nearest_site(const Point& p, std::uint32_t start) const;

  // The triangulation with the far vertices (orient2d > 0 triangles) and its adjacency.
  const Mesh& delaunay() const { return mesh_; }
  const Topology& delaunay_topology() const { return topo_; }

 private:
  std::size_t sites_ = 0;
  Mesh mesh_;
  Topology topo_;
  std::vector<std::uint32_t> cell_start_;       // cell v: [cell_start_[v], cell_start_[v+1])
  std::vector<Point> cell_points_;
  std::vector<std::uint32_t> cell_tris_;
  std::vector<std::uint32_t> neighbour_start_;  // Delaunay neighbours of each site
  std::vector<std::uint32_t> neighbours_;
  std::vector<Point> neighbour_points_;  // the point of each entry of neighbours_
  std::vector<double> safe_d2_;  // per site: a point this close (squared) has it as its only nearest site
};

// Meyer et al. barycentric coordinates of p in the convex polygon `polygon` (thesis
// Eq. 3.12), one weight per polygon vertex into `w`, summing to 1. Evaluated in the
// equivalent Wachspress product form, which stays exact next to edges; on an edge's line it
// is the thesis's fallback, linear interpolation between that edge's two ends.
void meyer_coordinates(std::span<const Point> polygon, const Point& p, std::vector<double>& w);

// ChannelRenderer (see above).
void render_voronoi(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                    Field& out);

}  // namespace tristream
