// SPDX-License-Identifier: MIT
#include "geometry/mesh_check.h"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <vector>

#include "geometry/predicates.h"

namespace tristream {
namespace {

constexpr std::uint32_t none = 0xFFFFFFFFu;

bool lex_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

int sign(double v) { return (v > 0) - (v < 0); }

// An undirected edge from its lexicographically smaller end `lo` to `hi`, with the triangle on
// each side: `above` on the orient2d(lo, hi, .) > 0 side, `below` on the other.
struct Edge {
  std::uint32_t lo, hi;
  std::uint32_t above = none, below = none;
  std::uint32_t any_triangle() const { return above != none ? above : below; }
};

class Sweep {
 public:
  Sweep(std::span<const Point> points, std::span<const Triangle> triangles) : p_(points), t_(triangles) {}

  std::optional<MeshDefect> run() {
    if (auto d = collect_edges()) return d;
    const Groups ending = group_by(&Edge::hi), starting = group_by(&Edge::lo);
    Status status(Below{this});
    std::vector<Status::iterator> where(edges_.size());
    for (std::uint32_t v : events()) {
      for (std::uint32_t k = ending.start[v]; k < ending.start[v + 1]; ++k) {
        const auto after = status.erase(where[ending.edges[k]]);
        if (after != status.begin() && after != status.end())
          if (auto d = meet(*std::prev(after), *after)) return d;
      }
      const auto at = status.lower_bound(p_[v]);  // the first edge not below v
      if (auto d = check_vertex(status, at, v)) return d;
      for (std::uint32_t k = starting.start[v]; k < starting.start[v + 1]; ++k) {
        const std::uint32_t e = starting.edges[k];
        const auto [it, inserted] = status.insert(e);
        if (!inserted) return collinear(e, *it);
        where[e] = it;
        if (it != status.begin())
          if (auto d = meet(*std::prev(it), e)) return d;
        if (auto next = std::next(it); next != status.end())
          if (auto d = meet(e, *next)) return d;
      }
    }
    return std::nullopt;
  }

 private:
  // Orders the edges crossing the sweep line from below to above; also compares an edge with a
  // point. Valid while no two edges in the status cross, which the sweep checks as it goes.
  struct Below {
    using is_transparent = void;
    const Sweep* s;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      const Edge& ea = s->edges_[a];
      const Edge& eb = s->edges_[b];
      const Point &alo = s->p_[ea.lo], &ahi = s->p_[ea.hi], &blo = s->p_[eb.lo], &bhi = s->p_[eb.hi];
      if (ea.lo == eb.lo) return orient2d(alo, ahi, bhi) > 0;
      if (lex_less(alo, blo)) {
        const double o = orient2d(alo, ahi, blo);
        return o != 0 ? o > 0 : orient2d(alo, ahi, bhi) > 0;
      }
      const double o = orient2d(blo, bhi, alo);
      return o != 0 ? o < 0 : orient2d(blo, bhi, ahi) < 0;
    }
    bool operator()(std::uint32_t a, const Point& q) const {
      return orient2d(s->p_[s->edges_[a].lo], s->p_[s->edges_[a].hi], q) > 0;
    }
    bool operator()(const Point& q, std::uint32_t a) const {
      return orient2d(s->p_[s->edges_[a].lo], s->p_[s->edges_[a].hi], q) < 0;
    }
  };
  using Status = std::set<std::uint32_t, Below>;

  // Edge indices grouped by one end: those of vertex v are edges[start[v] .. start[v + 1]).
  struct Groups {
    std::vector<std::uint32_t> start, edges;
  };
  Groups group_by(std::uint32_t Edge::*end) const {
    Groups g{std::vector<std::uint32_t>(p_.size() + 1, 0), std::vector<std::uint32_t>(edges_.size())};
    for (const Edge& e : edges_) ++g.start[e.*end + 1];
    for (std::size_t i = 0; i < p_.size(); ++i) g.start[i + 1] += g.start[i];
    std::vector<std::uint32_t> fill(g.start.begin(), g.start.end() - 1);
    for (std::uint32_t i = 0; i < edges_.size(); ++i) g.edges[fill[edges_[i].*end]++] = i;
    return g;
  }

  // Every vertex some edge uses, in lexicographic order.
  std::vector<std::uint32_t> events() const {
    std::vector<char> used(p_.size(), 0);
    for (const Edge& e : edges_) used[e.lo] = used[e.hi] = 1;
    std::vector<std::uint32_t> order;
    for (std::uint32_t v = 0; v < p_.size(); ++v)
      if (used[v]) order.push_back(v);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return lex_less(p_[a], p_[b]); });
    return order;
  }

  // With the edges ending at v removed and those starting there not yet inserted, every edge in
  // the status passes v: v must not lie on the first edge not below it (`at`), and the edge just
  // below v must not have above it a triangle v does not belong to.
  template <class Set>
  std::optional<MeshDefect> check_vertex(const Set& status, typename Set::const_iterator at, std::uint32_t v) const {
    if (at != status.end() && orient2d(p_[edges_[*at].lo], p_[edges_[*at].hi], p_[v]) == 0)
      return t_junction(*at, v);
    if (at == status.begin()) return std::nullopt;
    const std::uint32_t t = edges_[*std::prev(at)].above;
    if (t != none && !has_vertex(t, v)) return MeshDefect{MeshDefect::Kind::overlap, t, triangle_of(v), 0};
    return std::nullopt;
  }

  // Two edges from one end in the same direction: the shorter one's other end is inside the longer.
  MeshDefect collinear(std::uint32_t e, std::uint32_t f) const {
    const bool e_shorter = lex_less(p_[edges_[e].hi], p_[edges_[f].hi]);
    return t_junction(e_shorter ? f : e, e_shorter ? edges_[e].hi : edges_[f].hi);
  }

  static std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }

  // Every edge once, with the triangle on each side; the same side taken twice is an overlap.
  std::optional<MeshDefect> collect_edges() {
    std::unordered_map<std::uint64_t, std::uint32_t> index;
    index.reserve(t_.size() * 2);
    edges_.reserve(t_.size() * 3 / 2 + 3);
    for (std::uint32_t t = 0; t < t_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        std::uint32_t a = t_[t].v[k], b = t_[t].v[(k + 1) % 3];
        // The triangle is on the left of a -> b (positive orientation).
        const bool forward = lex_less(p_[a], p_[b]);
        if (!forward) std::swap(a, b);
        const auto [it, fresh] = index.try_emplace(key(a, b), std::uint32_t(edges_.size()));
        if (fresh) edges_.push_back(Edge{a, b});
        Edge& e = edges_[it->second];
        std::uint32_t& side = forward ? e.above : e.below;
        if (side != none) return MeshDefect{MeshDefect::Kind::overlap, side, t, 0};
        side = t;
      }
    vertex_triangle_.assign(p_.size(), none);
    for (std::uint32_t t = 0; t < t_.size(); ++t)
      for (std::uint32_t v : t_[t].v)
        if (vertex_triangle_[v] == none) vertex_triangle_[v] = t;
    return std::nullopt;
  }

  bool has_vertex(std::uint32_t t, std::uint32_t v) const {
    return t_[t].v[0] == v || t_[t].v[1] == v || t_[t].v[2] == v;
  }
  std::uint32_t triangle_of(std::uint32_t v) const { return vertex_triangle_[v]; }

  MeshDefect t_junction(std::uint32_t edge, std::uint32_t v) const {
    return MeshDefect{MeshDefect::Kind::t_junction, edges_[edge].any_triangle(), triangle_of(v), v};
  }

  bool inside(const Edge& e, std::uint32_t v) const {
    return lex_less(p_[e.lo], p_[v]) && lex_less(p_[v], p_[e.hi]) && orient2d(p_[e.lo], p_[e.hi], p_[v]) == 0;
  }

  // Edges that meet other than at a shared end: a crossing or a vertex inside an edge.
  std::optional<MeshDefect> meet(std::uint32_t a, std::uint32_t b) const {
    const Edge& ea = edges_[a];
    const Edge& eb = edges_[b];
    if (ea.lo == eb.lo || ea.lo == eb.hi || ea.hi == eb.lo || ea.hi == eb.hi) return std::nullopt;
    for (std::uint32_t v : {eb.lo, eb.hi})
      if (inside(ea, v)) return t_junction(a, v);
    for (std::uint32_t v : {ea.lo, ea.hi})
      if (inside(eb, v)) return t_junction(b, v);
    const Point &alo = p_[ea.lo], &ahi = p_[ea.hi], &blo = p_[eb.lo], &bhi = p_[eb.hi];
    if (sign(orient2d(alo, ahi, blo)) * sign(orient2d(alo, ahi, bhi)) < 0 &&
        sign(orient2d(blo, bhi, alo)) * sign(orient2d(blo, bhi, ahi)) < 0)
      return MeshDefect{MeshDefect::Kind::overlap, ea.any_triangle(), eb.any_triangle(), 0};
    return std::nullopt;
  }

  std::span<const Point> p_;
  std::span<const Triangle> t_;
  std::vector<Edge> edges_;
  std::vector<std::uint32_t> vertex_triangle_;
};

}  // namespace

std::optional<MeshDefect> find_mesh_defect(std::span<const Point> points, std::span<const Triangle> triangles) {
  return Sweep(points, triangles).run();
}

}  // namespace tristream
