/* SPDX-License-Identifier: MIT */
#pragma once
// Delaunay triangulation with exact predicates (geometry/predicates.h): a one-shot function
// and an incremental builder (Bowyer-Watson with ghost triangles) that reports which
// triangles each insertion destroyed and created, for the encoder's greedy insertion.
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "model/triangulation.h"

namespace tristream {

// A Delaunay triangulation of `points` (distinct; the caller guarantees it), as indices
// into `points`, every triangle with orient2d > 0 (the Mesh winding). Cocircular input
// (lattices) gets one valid Delaunay triangulation, the same on every run. Every point is a
// vertex; the triangles tile the convex hull. Empty when there are fewer than three points
// or all are collinear. Expected O(n log n) time on any input, points on a few lines included:
// the insertion order is biased-randomised (rounds of growing random subsets, each in Hilbert
// order), from a fixed seed. `work`, when given, receives the builder's work() at the end.
std::vector<Triangle> delaunay_triangulation(std::span<const Point> points, std::uint64_t* work = nullptr);

// An incremental Delaunay triangulation. Triangles live in slots; a slot freed by an
// insertion is reused by a later one. Besides the solid triangles it keeps one ghost
// triangle (u, v, ghost_vertex) per convex-hull edge, with the hull's outside on the
// orient2d(u, v, .) > 0 side, so points outside the hull can be inserted too.
class DelaunayBuilder {
 public:
  static constexpr std::uint32_t ghost_vertex = 0xFFFFFFFFu;
  static constexpr std::uint32_t no_triangle = 0xFFFFFFFFu;

  // Starts with the triangle a, b, c (any order; vertices 0, 1, 2). Throws
  // std::invalid_argument when they are collinear.
  DelaunayBuilder(const Point& a, const Point& b, const Point& c);

  // Inserts p and returns its vertex index (vertices are numbered in insertion order). The
  // point location walks from triangle `hint` (any live slot, or no_triangle). When p equals
  // an existing vertex nothing changes and that vertex's index is returned.
  std::uint32_t insert(const Point& p, std::uint32_t hint = no_triangle);

  // Slots destroyed and slots created by the last insert() (a slot may be in both lists:
  // it was freed and reused). Ghost triangles are included; test with is_ghost().
  std::span<const std::uint32_t> destroyed() const { return destroyed_; }
  std::span<const std::uint32_t> created() const { return created_; }

  // A live triangle whose closure contains p: a solid triangle with orient2d >= 0 on all
  // three edges, or, when p is strictly outside the hull, a ghost triangle whose hull edge
  // p sees from outside.
  std::uint32_t locate(const Point& p, std::uint32_t hint = no_triangle) const;

  std::size_t vertex_count() const { return points_.size(); }
  const std::vector<Point>& points() const { return points_; }
  const Point& point(std::uint32_t v) const { return points_[v]; }

  // Slots (live and free) are numbered 0 .. slot_count() - 1.
  std::size_t slot_count() const { return tri_.size(); }
  bool is_live(std::uint32_t t) const { return tri_[t].v[0] != dead_mark; }
  bool is_ghost(std::uint32_t t) const { return tri_[t].v[2] == ghost_vertex; }
  // Vertices of slot t; for a ghost, v[2] == ghost_vertex.
  const std::array<std::uint32_t, 3>& vertices(std::uint32_t t) const { return tri_[t].v; }
  // Triangle across edge e (joining v[e] and v[(e + 1) % 3]) of slot t.
  std::uint32_t neighbour(std::uint32_t t, int e) const { return tri_[t].n[e]; }

  std::size_t solid_count() const { return solid_count_; }
  // Steps of point location plus triangles tested for conflict, over all insertions so far: a
  // count of the work done, proportional to the time and the same on every machine.
  std::uint64_t work() const { return work_; }
  // The live solid triangles in slot order.
  std::vector<Triangle> triangles() const;

 private:
  static constexpr std::uint32_t dead_mark = 0xFFFFFFFEu;
  struct Slot {
    std::array<std::uint32_t, 3> v;
    std::array<std::uint32_t, 3> n;
  };

  bool in_conflict(std::uint32_t t, const Point& p) const;
  std::uint32_t new_slot();

  std::vector<Point> points_;
  std::vector<Slot> tri_;
  std::vector<std::uint32_t> free_;
  std::size_t solid_count_ = 0;
  std::uint32_t last_ = 0;  // a live slot, the default start of point location
  mutable std::uint64_t walk_state_ = 0x9E3779B97F4A7C15ull;  // deterministic walk choices
  mutable std::uint64_t work_ = 0;
  // Scratch of insert(); destroyed_ and created_ also answer destroyed() and created().
  std::vector<std::uint32_t> destroyed_, created_, stack_;
  struct BoundaryEdge {
    std::uint32_t a, b, outside;  // edge a->b of the cavity, triangle beyond it
    int outside_edge;             // index of the edge in `outside`
  };
  std::vector<BoundaryEdge> boundary_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> spoke_scratch_;  // (start vertex, slot)
  std::vector<std::uint32_t> mark_;  // per slot: insertion stamp when in the cavity
  std::uint32_t stamp_ = 0;
};

}  // namespace tristream
