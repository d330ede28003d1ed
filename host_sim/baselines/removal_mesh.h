/* SPDX-License-Identifier: MIT */
#pragma once
// A Delaunay triangulation of pixel positions that shrinks by vertex removal, for greedy
// point removal (baselines/gpr.h). It starts as every pixel of a W x H rectangle and keeps
// tiling [0, W-1] x [0, H-1]: the four corners stay, and a vertex on a side leaves a hole
// closed by that side. Removal fills the hole with Delaunay ears (exact predicates,
// geometry/predicates.h): an ear is convex and no vertex of the hole's boundary lies strictly
// inside its circumcircle. Such ears are triangles of a Delaunay triangulation of the
// boundary, whose edges are Delaunay edges, so the mesh stays Delaunay. Cocircular
// boundaries (the pixel lattice) have several; the first ear in boundary order is taken, so
// the result is the same on every run.
#include <array>
#include <cstdint>
#include <vector>

#include "encoder/pixel_scan.h"
#include "model/triangulation.h"

namespace tristream::baselines {

class RemovalMesh {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  using Corners = std::array<std::uint32_t, 3>;

  // Every pixel of the width x height rectangle (at least 2 x 2), vertex y * width + x; each
  // cell split by its diagonal from (x, y) to (x + 1, y + 1).
  RemovalMesh(int width, int height);

  // The triangles around vertex v and the boundary of the hole its removal leaves: the link
  // a0, a1, ..., am in the Mesh winding (triangle k is (v, a_k, a_k+1)). For an interior
  // vertex the link is a cycle (triangles[k] has link edge a_k -> a_(k+1 mod m+1)); for a
  // vertex on a side it is a chain from one neighbour on that side to the other, closed by
  // the side (am -> a0 passes through v).
  struct Star {
    std::vector<std::uint32_t> triangles;
    std::vector<std::uint32_t> link;
    bool on_side = false;
  };
  void star(std::uint32_t v, Star& out) const;

  // The Delaunay ears that fill the hole of `s`, each in the Mesh winding. Throws
  // std::logic_error when no ear is found (not a hole of this mesh).
  void fill(const Star& s, std::vector<Corners>& out) const;

  // Removes v, whose star is `s` and whose hole `fill` fills (as fill() gives them); appends
  // the slots of the new triangles to `created`.
  void remove(std::uint32_t v, const Star& s, const std::vector<Corners>& fill, std::vector<std::uint32_t>& created);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t vertex_count() const { return alive_count_; }
  bool alive(std::uint32_t v) const { return alive_[v] != 0; }
  bool is_corner(std::uint32_t v) const;
  encoder::IntPoint pixel(std::uint32_t v) const {
    return {std::int32_t(v % std::uint32_t(width_)), std::int32_t(v / std::uint32_t(width_))};
  }

  // Slots 0 .. slot_count() - 1, live or free.
  std::size_t slot_count() const { return tri_.size(); }
  bool is_live(std::uint32_t t) const { return tri_[t].v[0] != none; }
  const Corners& vertices(std::uint32_t t) const { return tri_[t].v; }

 private:
  struct Slot {
    Corners v;
    Corners n;  // n[e]: the triangle across edge v[e] -> v[(e + 1) % 3], or none on a side
  };
  Point point(std::uint32_t v) const { return {double(v % std::uint32_t(width_)), double(v / std::uint32_t(width_))}; }
  static int index_of(const Slot& s, std::uint32_t v);
  std::uint32_t new_slot(const Corners& v);

  int width_, height_;
  std::size_t alive_count_;
  std::vector<Slot> tri_;
  std::vector<std::uint32_t> free_;
  std::vector<std::uint32_t> vertex_triangle_;  // a live triangle of each live vertex
  std::vector<std::uint8_t> alive_;
  // Scratch of remove(): the hole's boundary edges a -> b with the triangle beyond.
  struct Outside {
    std::uint32_t a, b, slot;
    int edge;
  };
  std::vector<Outside> outside_;
  mutable std::vector<std::uint32_t> polygon_;  // scratch of fill()
};

}  // namespace tristream::baselines
