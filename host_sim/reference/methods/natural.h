/* SPDX-License-Identifier: MIT */
#pragma once
// Natural-neighbour (Sibson) interpolation (thesis §3.6, §4.4; docs/CONVENTIONS.md).
//
// The weights come from a Delaunay triangulation of the mesh's vertices (the file's own
// triangles when they already are one, checked exactly; otherwise they only decide which
// pixels are in the domain): the natural neighbours of a point p are the vertices of its
// Bowyer-Watson cavity (the triangles whose circumcircle strictly contains p), and the weight
// of neighbour v is the area that p's Voronoi cell would steal from v's cell, over the area
// of p's cell. The stolen piece of v's cell is the polygon [g(u, v), c(T1), ..., c(Tm),
// g(v, w)]: c(T) the circumcentres of the cavity triangles around v, g the circumcentres of
// p with the cavity boundary edges (u, v) and (v, w).
// Nothing is rebuilt per pixel. When the mesh covers the image rectangle the renderer sweeps
// each row: every circumcircle meets the row in one run of columns (its ends settled by exact
// incircle tests), and the circles active at a column are that point's cavity. Otherwise each
// domain pixel's cavity is grown from the previous pixel's start triangle while its circle
// still contains the point (else a walk from there locates it). Incircle decisions are exact:
// a floating-point filter with precomputed per-triangle terms, then geometry/predicates.h.
//
// Exact for every point of the closed convex hull: a point on a vertex gets that vertex
// alone; a point on a hull edge gets the linear interpolation of the edge's two ends (the
// limit of Sibson's coordinates there, where p's cell becomes unbounded).
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/render.h"

namespace tristream {

struct NeighbourWeight {
  std::uint32_t vertex = 0;
  double weight = 0;
};

class SibsonCoordinates {
 public:
  // Builds the Delaunay triangulation of `points` (distinct; at least three not collinear,
  // otherwise every query returns false).
  explicit SibsonCoordinates(std::span<const Point> points);
  // Uses `delaunay`'s triangles as they are: the caller guarantees that they form a Delaunay
  // triangulation of its points (for example: is_locally_delaunay() and a convex domain).
  SibsonCoordinates(const Mesh& delaunay, const Topology& topo);

  // Sibson coordinates of p: non-negative weights summing to 1, one per natural neighbour,
  // into `out` (cleared first). Returns false, with `out` empty, when p is outside the
  // convex hull. Point location walks from where the last query ended.
  bool compute(const Point& p, std::vector<NeighbourWeight>& out);
  // The same when triangle t of delaunay() is known to contain p (closed); no walk.
  bool compute_in(const Point& p, std::uint32_t t, std::vector<NeighbourWeight>& out);
  // The same for a p known to lie in the closed hull: the cavity search starts from the last
  // start when its circle still contains p, which skips point location.
  bool compute_in_hull(const Point& p, std::vector<NeighbourWeight>& out);

  // Calls visit(i, j, weights) for every output pixel whose sample point lies in the hull,
  // in rows. The caller guarantees that the hull is the rectangle [0, xmax] x [0, ymax]
  // (covers_rectangle()). Instead of a search per pixel it sweeps each row: every circumcircle
  // meets the row in one run of columns, found with a few exact tests at its ends, and the
  // circles active at a column are the point's cavity.
  using SampleVisit = std::function<void(int i, int j, const std::vector<NeighbourWeight>& weights)>;
  void for_each_sample(const PixelMapping& map, double xmax, double ymax, const SampleVisit& visit);

  // The triangle where the next compute() starts its walk (the last one located).
  std::uint32_t hint() const { return hint_; }
  void set_hint(std::uint32_t t) { hint_ = t; }

  // The Delaunay triangulation used (points as given, triangles with orient2d > 0).
  const Mesh& delaunay() const { return mesh_; }
  const Topology& delaunay_topology() const { return topo_; }

 private:
  friend void render_natural(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                             Field& out);
  void prepare();  // circumcentres, incircle terms and scratch of the triangulation
  // The row sweep of for_each_sample() with the visitor inlined, in steps: the circles by row
  // (sweep_circles), each row's runs of columns inside them as events (row_events, circle_run),
  // and the pixels of the row with the circles active there (sweep_row). Types in natural.cpp.
  struct SweepCircles;
  struct RowEvents;
  struct ActiveCircles;
  template <class Visit>
  void sweep(const PixelMapping& map, double xmax, double ymax, Visit&& visit);
  SweepCircles sweep_circles(const PixelMapping& map) const;
  std::pair<int, int> circle_run(const SweepCircles& circles, const PixelMapping& map, std::uint32_t slot, int j) const;
  void row_events(const SweepCircles& circles, const PixelMapping& map, int j, RowEvents& events) const;
  template <class Visit>
  void sweep_row(const SweepCircles& circles, const RowEvents& events, const PixelMapping& map, double xmax,
                 double ymax, int j, ActiveCircles& cavity, std::vector<NeighbourWeight>& weights, Visit&& visit);
  // A triangle whose closed interior contains p, or no_neighbour when p is outside the hull.
  std::uint32_t locate(const Point& p);
  // The weights from the cavity grown from t0, whose circle strictly contains p.
  bool cavity_coordinates(const Point& p, std::uint32_t t0, std::vector<NeighbourWeight>& out);
  // The weights from the stolen areas, given the cavity and membership in it.
  template <class Inside>
  bool stolen_areas(const Point& p, std::span<const std::uint32_t> cavity, Inside inside,
                    std::vector<NeighbourWeight>& out);
  void next_query();  // a fresh stamp for mark_ and vertex_slot_
  bool on_hull_edge(const Point& p, std::uint32_t a, std::uint32_t b, std::vector<NeighbourWeight>& out) const;
  // incircle(triangle t, p) > 0, decided exactly. With `exact` (integer_points_ and p on the
  // integer grid [0, exact_limit]^2) the floating-point evaluation has no rounding at all.
  bool in_circle(std::uint32_t t, const Point& p, bool exact) const;
  bool in_circle(std::uint32_t t, const Point& p) const { return in_circle(t, p, exact_point(p)); }
  bool exact_point(const Point& p) const {
    return integer_points_ && p.x >= 0 && p.x <= exact_limit && p.y >= 0 && p.y <= exact_limit &&
           p.x == std::uint32_t(p.x) && p.y == std::uint32_t(p.y);
  }

  // The lifted incircle determinant of triangle (a, b, c) expanded along p's row, relative
  // to a: F(p) = alpha dx + beta dy + gamma (dx^2 + dy^2), dx = p.x - a.x, dy = p.y - a.y,
  // positive iff p is strictly inside; *_abs are the matching permanents for the error bound.
  // For integer coordinates in [0, exact_limit] every term is an integer below 2^52 (all
  // differences D <= 2^12: |alpha|, |beta| <= 4 D^3, |gamma| <= 2 D^2, |F| <= 12 D^4), so F
  // is computed without rounding and its sign is the exact predicate's.
  static constexpr double exact_limit = 4096;
  struct alignas(64) CircleTest {
    double ax, ay, alpha, beta, gamma, alpha_abs, beta_abs, gamma_abs;
  };
  // What the stolen-area pass reads of a triangle, in one place: its circumcentre, vertices
  // and neighbours (topo_.neighbour order).
  struct TriangleRecord {
    Point centre;
    std::uint32_t v[3];
    std::uint32_t n[3];
  };

  Mesh mesh_;  // the Delaunay triangulation (points and triangles only)
  Topology topo_;
  std::vector<TriangleRecord> tri_;
  std::vector<CircleTest> circle_;
  bool integer_points_ = false;  // every point an integer in [0, exact_limit]
  std::uint32_t hint_ = 0;
  // Scratch of compute_in().
  struct VertexSlot {
    std::uint32_t stamp = 0, index = 0;  // query number, index in the stolen-area scratch
  };
  struct StolenPolygon {
    double sum;         // shoelace sum so far, relative to p
    Point first, last;  // g of the boundary edges into and out of a cavity boundary vertex
    std::uint32_t vertex;
  };
  std::vector<std::uint64_t> mark_;  // per triangle: 2 * query number + (in the cavity) when tested
  std::uint32_t query_ = 0;
  std::vector<std::uint32_t> stack_, cavity_;
  std::vector<VertexSlot> vertex_slot_;  // per vertex
  std::vector<StolenPolygon> polygon_;
};

// ChannelRenderer: every mesh-domain pixel (the domain lies inside the vertices' hull).
void render_natural(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                    Field& out);

}  // namespace tristream
