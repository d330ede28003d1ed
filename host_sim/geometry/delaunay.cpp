// SPDX-License-Identifier: MIT
#include "geometry/delaunay.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "geometry/predicates.h"

namespace tristream {

DelaunayBuilder::DelaunayBuilder(const Point& a, const Point& b, const Point& c) {
  const double o = orient2d(a, b, c);
  if (o == 0) throw std::invalid_argument("DelaunayBuilder: the first three points are collinear");
  points_ = {a, b, c};
  const std::array<std::uint32_t, 3> v = o > 0 ? std::array<std::uint32_t, 3>{0, 1, 2}
                                               : std::array<std::uint32_t, 3>{0, 2, 1};
  tri_.resize(4);
  tri_[0].v = v;
  for (int e = 0; e < 3; ++e) {
    // Ghost e + 1 lies across edge e of the solid triangle: (v[e+1], v[e], ghost).
    tri_[e + 1].v = {v[(e + 1) % 3], v[e], ghost_vertex};
    tri_[0].n[e] = std::uint32_t(e + 1);
    tri_[e + 1].n[0] = 0;
    // Edge 1 of ghost e+1 (v[e] -> ghost) meets edge 2 (ghost -> v[e]) of the ghost of edge e-1.
    tri_[e + 1].n[1] = std::uint32_t((e + 2) % 3 + 1);
    tri_[e + 1].n[2] = std::uint32_t((e + 1) % 3 + 1);
  }
  solid_count_ = 1;
  mark_.assign(tri_.size(), 0);
}

std::uint32_t DelaunayBuilder::locate(const Point& p, std::uint32_t hint) const {
  std::uint32_t t = hint;
  if (t >= tri_.size() || !is_live(t)) t = last_;
  if (is_ghost(t)) t = tri_[t].n[0];
  std::uint32_t came_from = no_triangle;
  for (;; ++work_) {
    // Stochastic visibility walk (Devillers, Pion, Teillaud 2002): a pseudo-random first
    // edge guarantees termination on any triangulation; the state makes it deterministic.
    walk_state_ ^= walk_state_ << 13;
    walk_state_ ^= walk_state_ >> 7;
    walk_state_ ^= walk_state_ << 17;
    const int first = int(walk_state_ % 3);
    const Slot& s = tri_[t];
    std::uint32_t next = no_triangle;
    for (int k = 0; k < 3; ++k) {
      const int e = (first + k) % 3;
      if (s.n[e] == came_from) continue;
      if (orient2d(points_[s.v[e]], points_[s.v[(e + 1) % 3]], p) < 0) {
        next = s.n[e];
        break;
      }
    }
    if (next == no_triangle) return t;
    if (is_ghost(next)) return next;
    came_from = t;
    t = next;
  }
}

bool DelaunayBuilder::in_conflict(std::uint32_t t, const Point& p) const {
  const Slot& s = tri_[t];
  if (s.v[2] != ghost_vertex)
    return incircle(points_[s.v[0]], points_[s.v[1]], points_[s.v[2]], p) > 0;
  // A ghost's "circumdisk" is the open outer half-plane of its hull edge plus the edge's
  // relative interior.
  const Point& u = points_[s.v[0]];
  const Point& v = points_[s.v[1]];
  const double o = orient2d(u, v, p);
  if (o != 0) return o > 0;
  if (u.x != v.x) return (p.x > u.x && p.x < v.x) || (p.x < u.x && p.x > v.x);
  return (p.y > u.y && p.y < v.y) || (p.y < u.y && p.y > v.y);
}

std::uint32_t DelaunayBuilder::new_slot() {
  if (!free_.empty()) {
    const std::uint32_t t = free_.back();
    free_.pop_back();
    return t;
  }
  tri_.push_back({});
  mark_.push_back(0);
  return std::uint32_t(tri_.size() - 1);
}

std::uint32_t DelaunayBuilder::insert(const Point& p, std::uint32_t hint) {
  destroyed_.clear();
  created_.clear();
  const std::uint32_t start = locate(p, hint);
  if (!is_ghost(start))
    for (std::uint32_t v : tri_[start].v)
      if (points_[v].x == p.x && points_[v].y == p.y) return v;

  // Stamps: mark_[t] == stamp_ when t is in the cavity, stamp_ + 1 when tested and not.
  if (stamp_ >= 0xFFFFFFF0u) {
    std::fill(mark_.begin(), mark_.end(), 0);
    stamp_ = 0;
  }
  stamp_ += 2;
  const std::uint32_t in = stamp_, out = stamp_ + 1;

  // The cavity: the triangles whose open circumdisk contains p, connected, star-shaped
  // from p; every boundary edge sees p strictly on its inner side (exact predicates).
  boundary_.clear();
  stack_.assign(1, start);
  mark_[start] = in;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    destroyed_.push_back(t);
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = tri_[t].n[e];
      if (mark_[u] == in) continue;
      if (mark_[u] != out) {
        ++work_;
        if (in_conflict(u, p)) {
          mark_[u] = in;
          stack_.push_back(u);
          continue;
        }
        mark_[u] = out;
      }
      int f = 0;
      while (tri_[u].n[f] != t) ++f;
      boundary_.push_back({tri_[t].v[e], tri_[t].v[(e + 1) % 3], u, f});
    }
  }

  const std::uint32_t pv = std::uint32_t(points_.size());
  points_.push_back(p);
  for (std::uint32_t t : destroyed_) {
    if (!is_ghost(t)) --solid_count_;
    tri_[t].v[0] = dead_mark;
    free_.push_back(t);
  }
  // One new triangle (a, b, p) per boundary edge a->b; new triangles meet along the spokes
  // p-a. The boundary is one closed cycle, so each vertex starts exactly one edge.
  created_.resize(boundary_.size());
  for (std::size_t i = 0; i < boundary_.size(); ++i) {
    const BoundaryEdge& be = boundary_[i];
    const std::uint32_t t = new_slot();
    created_[i] = t;
    tri_[t].v = {be.a, be.b, pv};
    tri_[t].n = {be.outside, no_triangle, no_triangle};
    tri_[be.outside].n[be.outside_edge] = t;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& by_start = spoke_scratch_;
  by_start.resize(boundary_.size());
  for (std::size_t i = 0; i < boundary_.size(); ++i) by_start[i] = {boundary_[i].a, created_[i]};
  std::sort(by_start.begin(), by_start.end());
  for (std::size_t i = 0; i < boundary_.size(); ++i) {
    const std::uint32_t t = created_[i];
    // Edge 1 (b -> p) meets edge 2 (p -> b) of the triangle whose boundary edge starts at b.
    const auto it = std::lower_bound(by_start.begin(), by_start.end(),
                                     std::pair<std::uint32_t, std::uint32_t>{boundary_[i].b, 0});
    tri_[t].n[1] = it->second;
    tri_[it->second].n[2] = t;
  }
  for (std::uint32_t t : created_) {
    Slot& s = tri_[t];
    // Keep the ghost vertex in position 2 (rotation keeps the cyclic order and the winding).
    if (s.v[0] == ghost_vertex) {
      std::rotate(s.v.begin(), s.v.begin() + 1, s.v.end());
      std::rotate(s.n.begin(), s.n.begin() + 1, s.n.end());
    } else if (s.v[1] == ghost_vertex) {
      std::rotate(s.v.begin(), s.v.begin() + 2, s.v.end());
      std::rotate(s.n.begin(), s.n.begin() + 2, s.n.end());
    } else {
      ++solid_count_;
    }
  }
  last_ = created_.front();
  return pv;
}

std::vector<Triangle> DelaunayBuilder::triangles() const {
  std::vector<Triangle> out;
  out.reserve(solid_count_);
  for (std::uint32_t t = 0; t < tri_.size(); ++t)
    if (is_live(t) && !is_ghost(t)) out.push_back({tri_[t].v});
  return out;
}

namespace {

// Position of (x, y) along a Hilbert curve over a 2^16 x 2^16 grid.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0;
    const std::uint32_t ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
  }
  return d;
}

// The round of point i in a biased randomised insertion order (Amenta, Choi and Rote 2003):
// round r of `rounds` holds about half of the points not in rounds before it, chosen by a hash
// of the index (SplitMix64's finaliser), so the order is the same on every run and machine.
int insertion_round(std::uint64_t i, int rounds) {
  std::uint64_t z = i + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  int zeros = 0;  // trailing zero bits: 0 with probability 1/2, 1 with 1/4, ...
  while (zeros < rounds - 1 && (z & 1) == 0) {
    z >>= 1;
    ++zeros;
  }
  return rounds - 1 - zeros;  // the last round (about half the points) is rounds - 1
}

}  // namespace

std::vector<Triangle> delaunay_triangulation(std::span<const Point> points, std::uint64_t* work) {
  const std::size_t n = points.size();
  if (n < 3) return {};
  std::size_t third = 2;
  while (third < n && orient2d(points[0], points[1], points[third]) == 0) ++third;
  if (third == n) return {};

  // Rounds of growing random subsets, each in Hilbert order: the random rounds bound the
  // expected work of every insertion (a plain Hilbert order is quadratic on points along a few
  // lines: each row's points can meet a fan of the other row's), the Hilbert order within a
  // round keeps each walk short.
  double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  for (const Point& p : points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const double sx = x1 > x0 ? 65535.0 / (x1 - x0) : 0.0;
  const double sy = y1 > y0 ? 65535.0 / (y1 - y0) : 0.0;
  int rounds = 1;
  while (rounds < 40 && (std::size_t(1) << rounds) < n / 8) ++rounds;  // the first round: about 8 points
  std::vector<std::pair<std::pair<int, std::uint64_t>, std::uint32_t>> order;
  order.reserve(n);
  for (std::size_t i = 2; i < n; ++i) {
    if (i == third) continue;
    const auto hx = std::uint32_t(std::clamp((points[i].x - x0) * sx, 0.0, 65535.0));
    const auto hy = std::uint32_t(std::clamp((points[i].y - y0) * sy, 0.0, 65535.0));
    order.push_back({{insertion_round(i, rounds), hilbert_index(hx, hy)}, std::uint32_t(i)});
  }
  std::sort(order.begin(), order.end());

  DelaunayBuilder builder(points[0], points[1], points[third]);
  std::vector<std::uint32_t> input_index = {0, 1, std::uint32_t(third)};
  input_index.reserve(n);
  for (const auto& [key, i] : order) {
    const std::uint32_t v = builder.insert(points[i]);
    if (v == input_index.size()) input_index.push_back(i);  // else a duplicate: not a vertex
  }
  if (work) *work = builder.work();
  std::vector<Triangle> triangles = builder.triangles();
  for (Triangle& t : triangles)
    for (std::uint32_t& v : t.v) v = input_index[v];
  return triangles;
}

}  // namespace tristream
