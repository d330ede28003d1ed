#include "reference/methods/natural.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/delaunay.h"
#include "geometry/predicates.h"
#include "model/topology.h"

namespace tristream {
namespace {

// Circumcentre of (o, a, b) minus o. Finite whenever o, a, b are not collinear.
[[gnu::always_inline]] inline Point circumcentre_from(const Point& o, const Point& a, const Point& b) {
  const double ax = a.x - o.x, ay = a.y - o.y;
  const double bx = b.x - o.x, by = b.y - o.y;
  const double r = 0.5 / (ax * by - ay * bx);
  const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
  return {(by * a2 - ay * b2) * r, (ax * b2 - bx * a2) * r};
}

// floor and ceil of x as int, for x within int range (std::floor and std::ceil are library
// calls without SSE4.1).
inline int floor_int(double x) {
  const int i = int(x);
  return i - (i > x);
}
inline int ceil_int(double x) {
  const int i = int(x);
  return i + (i < x);
}

// The filter's error bound relative to the permanent: Shewchuk's incircle bound is
// (10 + 96 eps) eps for the same sum of six lift x coordinate x coordinate products;
// 32 eps leaves a wide margin.
constexpr double circle_filter = 32 * std::numeric_limits<double>::epsilon();

}  // namespace

SibsonCoordinates::SibsonCoordinates(std::span<const Point> points) {
  mesh_.points.assign(points.begin(), points.end());
  mesh_.triangles = delaunay_triangulation(points);
  topo_ = build_topology(mesh_);
  prepare();
}

SibsonCoordinates::SibsonCoordinates(const Mesh& delaunay, const Topology& topo) {
  mesh_.points = delaunay.points;
  mesh_.triangles = delaunay.triangles;
  topo_ = topo;
  prepare();
}

bool is_locally_delaunay(const Mesh& mesh, const Topology& topo) {
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (topo.vertex_start[v] == topo.vertex_start[v + 1]) return false;  // in no triangle
  // Integer coordinates in [0, 4096]: incircle's determinant (relative to d, as in
  // geometry/predicates.cpp) has no rounding (differences <= 2^12, each of its three terms
  // below 2^50), so its sign is the exact predicate's.
  bool small = true;
  for (const Point& q : mesh.points)
    small = small && q.x >= 0 && q.x <= 4096 && q.y >= 0 && q.y <= 4096 && q.x == std::uint32_t(q.x) &&
            q.y == std::uint32_t(q.y);
  auto inside = [small](const Point& a, const Point& b, const Point& c, const Point& d) {
    if (!small) return incircle(a, b, c, d) > 0;
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
    const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady) > 0;
  };
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t n = topo.neighbour[3 * t + e];
      if (n == no_neighbour || n < t) continue;  // each interior edge once
      std::uint32_t opposite = 0;
      for (std::uint32_t w : mesh.triangles[n].v)
        if (w != v[e] && w != v[(e + 1) % 3]) opposite = w;
      if (inside(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[opposite])) return false;
    }
  }
  return true;
}

void SibsonCoordinates::prepare() {
  const std::size_t nt = mesh_.triangles.size();
  tri_.resize(nt);
  circle_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& v = mesh_.triangles[t].v;
    const Point& a = mesh_.points[v[0]];
    const Point& b = mesh_.points[v[1]];
    const Point& c = mesh_.points[v[2]];
    const Point cc = circumcentre_from(a, b, c);
    TriangleRecord& r = tri_[t];
    r.centre = {a.x + cc.x, a.y + cc.y};
    for (int e = 0; e < 3; ++e) {
      r.v[e] = v[e];
      r.n[e] = topo_.neighbour[3 * t + e];
    }
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double lb = bx * bx + by * by, lc = cx * cx + cy * cy;
    circle_[t] = {a.x,
                  a.y,
                  lb * cy - by * lc,
                  bx * lc - lb * cx,
                  -(bx * cy - by * cx),
                  std::abs(lb * cy) + std::abs(by * lc),
                  std::abs(bx * lc) + std::abs(lb * cx),
                  std::abs(bx * cy) + std::abs(by * cx)};
  }
  mark_.assign(nt, 0);
  vertex_slot_.assign(mesh_.points.size(), VertexSlot{});
  integer_points_ = true;
  for (const Point& q : mesh_.points)
    integer_points_ = integer_points_ && q.x >= 0 && q.x <= exact_limit && q.y >= 0 && q.y <= exact_limit &&
                      q.x == std::uint32_t(q.x) && q.y == std::uint32_t(q.y);
}

inline bool SibsonCoordinates::in_circle(std::uint32_t t, const Point& p, bool exact) const {
  const CircleTest& k = circle_[t];
  const double dx = p.x - k.ax, dy = p.y - k.ay, l = dx * dx + dy * dy;
  const double f = k.alpha * dx + k.beta * dy + k.gamma * l;
  if (exact) return f > 0;
  const double bound = circle_filter * (k.alpha_abs * std::abs(dx) + k.beta_abs * std::abs(dy) + k.gamma_abs * l);
  if (f > bound) return true;
  if (f < -bound) return false;
  const auto& v = mesh_.triangles[t].v;
  return incircle(mesh_.points[v[0]], mesh_.points[v[1]], mesh_.points[v[2]], p) > 0;
}

std::uint32_t SibsonCoordinates::locate(const Point& p) {
  if (mesh_.triangles.empty()) return no_neighbour;
  // Visibility walk; it terminates on a Delaunay triangulation (Edelsbrunner 1990), and the
  // step budget only guards against a broken invariant.
  std::uint32_t t = hint_ < mesh_.triangles.size() ? hint_ : 0;
  for (std::size_t steps = 0; steps <= 4 * mesh_.triangles.size() + 8; ++steps) {
    const auto& v = mesh_.triangles[t].v;
    int cross = -1;
    for (int e = 0; e < 3 && cross < 0; ++e)
      if (orient2d(mesh_.points[v[e]], mesh_.points[v[(e + 1) % 3]], p) < 0) cross = e;
    if (cross < 0) return hint_ = t;
    const std::uint32_t n = topo_.neighbour[3 * t + cross];
    if (n == no_neighbour) return no_neighbour;  // beyond a hull edge: outside the hull
    t = n;
  }
  return no_neighbour;
}

bool SibsonCoordinates::on_hull_edge(const Point& p, std::uint32_t a, std::uint32_t b,
                                     std::vector<NeighbourWeight>& out) const {
  // p on the line of hull edge a-b: when on the segment, linear along it (the limit of
  // Sibson's coordinates there) and true; false beyond the segment.
  const Point& pa = mesh_.points[a];
  const Point& pb = mesh_.points[b];
  const double s = std::abs(pb.x - pa.x) >= std::abs(pb.y - pa.y) ? (p.x - pa.x) / (pb.x - pa.x) : (p.y - pa.y) / (pb.y - pa.y);
  if (!(s >= 0 && s <= 1)) return false;
  out.clear();
  out.push_back({a, 1.0 - s});
  out.push_back({b, s});
  return true;
}

bool SibsonCoordinates::compute(const Point& p, std::vector<NeighbourWeight>& out) {
  const std::uint32_t t = locate(p);
  if (t == no_neighbour) {
    out.clear();
    return false;
  }
  return compute_in(p, t, out);
}

bool SibsonCoordinates::compute_in_hull(const Point& p, std::vector<NeighbourWeight>& out) {
  // The cavity only needs a start whose circle strictly contains p; for the next pixel the
  // last start usually still does. (A vertex is strictly inside no Delaunay circle, so p is
  // not a vertex on this path.)
  if (hint_ < mesh_.triangles.size() && in_circle(hint_, p)) return cavity_coordinates(p, hint_, out);
  return compute(p, out);
}

bool SibsonCoordinates::compute_in(const Point& p, std::uint32_t t0, std::vector<NeighbourWeight>& out) {
  out.clear();
  const auto& tv = mesh_.triangles[t0].v;
  for (int k = 0; k < 3; ++k) {
    const Point& q = mesh_.points[tv[k]];
    if (q.x == p.x && q.y == p.y) {
      out.push_back({tv[k], 1.0});
      return true;
    }
  }
  // p lies in the closed t0 and on none of its vertices, so strictly inside its circle.
  return cavity_coordinates(p, t0, out);
}

void SibsonCoordinates::next_query() {
  if (++query_ == 0) {
    std::fill(mark_.begin(), mark_.end(), 0);
    std::fill(vertex_slot_.begin(), vertex_slot_.end(), VertexSlot{});
    query_ = 1;
  }
}

bool SibsonCoordinates::cavity_coordinates(const Point& p, std::uint32_t t0, std::vector<NeighbourWeight>& out) {
  // The cavity: triangles whose circumcircle strictly contains p, a connected set around t0.
  next_query();
  const bool exact = exact_point(p);
  cavity_.clear();
  stack_.assign(1, t0);
  mark_[t0] = 2 * std::uint64_t(query_) + 1;
  while (!stack_.empty()) {
    const std::uint32_t t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t n = topo_.neighbour[3 * t + e];
      if (n != no_neighbour && (mark_[n] >> 1) != query_) {
        const bool in = in_circle(n, p, exact);
        mark_[n] = 2 * std::uint64_t(query_) + in;
        if (in) stack_.push_back(n);
      }
    }
  }
  const std::uint64_t in_mark = 2 * std::uint64_t(query_) + 1;
  return stolen_areas(p, cavity_, [&](std::uint32_t n) { return n != no_neighbour && mark_[n] == in_mark; }, out);
}

template <class Inside>
bool SibsonCoordinates::stolen_areas(const Point& p, std::span<const std::uint32_t> cavity, Inside inside,
                                     std::vector<NeighbourWeight>& out) {
  out.clear();
  // The stolen polygon of a cavity boundary vertex w, between boundary edges u -> w and
  // w -> x (cavity on their left), is [g(u, w), c(T1), ..., c(Tm), g(w, x)]: c(T) the
  // circumcentres of the cavity triangles around w, g the circumcentre of p with a boundary
  // edge. Its shoelace sum is accumulated edge by edge, with coordinates relative to p:
  // crossing cavity edge a -> b from T to the cavity triangle N adds c(T) x c(N) to a's
  // polygon; boundary edge a -> b of T adds c(T) x g to a's and g x c(T) to b's, and
  // closes a's polygon with g x (a's first point) and opens b's with g. (Every vertex of a
  // cavity triangle is on the cavity boundary.) The caller has called next_query().
  // Scratch for every vertex of the cavity (at most three per triangle), so the pass below
  // never grows it.
  if (polygon_.size() < 3 * cavity.size()) polygon_.resize(3 * cavity.size() + 16);
  StolenPolygon* const poly = polygon_.data();
  VertexSlot* const slots = vertex_slot_.data();
  const TriangleRecord* const tri = tri_.data();
  const Point* const points = mesh_.points.data();
  const std::uint32_t query = query_;
  std::uint32_t count = 0;
  auto slot_of = [&](std::uint32_t v) __attribute__((always_inline)) {
    VertexSlot& s = slots[v];
    if (s.stamp != query) {
      s.stamp = query;
      s.index = count;
      poly[count] = {0.0, {}, {}, v};
      ++count;
    }
    return s.index;
  };
  for (const std::uint32_t t : cavity) {
    const TriangleRecord& r = tri[t];
    const Point ct = {r.centre.x - p.x, r.centre.y - p.y};
    // Edge a -> b of t with neighbour n across it; false when p turns out to be on a hull
    // edge (out then holds the result).
    auto edge = [&](std::uint32_t a, std::uint32_t b, std::uint32_t n) __attribute__((always_inline)) {
      if (inside(n)) {
        const Point cn = {tri[n].centre.x - p.x, tri[n].centre.y - p.y};
        poly[slot_of(a)].sum += ct.x * cn.y - cn.x * ct.y;
        return true;
      }
      if (n == no_neighbour && orient2d(points[a], points[b], p) == 0) {
        // p is on the hull boundary. On this edge: linear along it. On the line but beyond
        // the segment (collinear hull vertices): the edge holding p is a boundary edge too.
        return !on_hull_edge(p, a, b, out);
      }
      const Point g = circumcentre_from(p, points[a], points[b]);
      const std::uint32_t sa = slot_of(a);
      poly[sa].sum += ct.x * g.y - g.x * ct.y;
      poly[sa].last = g;
      const std::uint32_t sb = slot_of(b);
      poly[sb].sum += g.x * ct.y - ct.x * g.y;
      poly[sb].first = g;
      return true;
    };
    if (!edge(r.v[0], r.v[1], r.n[0]) || !edge(r.v[1], r.v[2], r.n[1]) || !edge(r.v[2], r.v[0], r.n[2])) return true;
  }
  double total = 0;
  if (out.capacity() < count) out.reserve(2 * count);
  for (std::uint32_t k = 0; k < count; ++k) {
    const Point& l = poly[k].last;
    const Point& f = poly[k].first;
    // The polygon runs clockwise in the orient2d > 0 frame, hence the minus sign. A true
    // stolen area is >= 0; rounding could leave a tiny negative for a sliver: taken as 0.
    const double stolen = std::max(0.0, -0.5 * (poly[k].sum + l.x * f.y - f.x * l.y));
    out.push_back({poly[k].vertex, stolen});
    total += stolen;
  }
  if (!(total > 0)) {  // cannot happen for p strictly inside the hull; never divide by 0
    out.clear();
    return false;
  }
  const double inv = 1.0 / total;
  for (NeighbourWeight& nw : out) nw.weight *= inv;
  return true;
}

void SibsonCoordinates::for_each_sample(const PixelMapping& map, double xmax, double ymax, const SampleVisit& visit) {
  sweep(map, xmax, ymax, visit);
}

template <class Visit>
void SibsonCoordinates::sweep(const PixelMapping& map, double xmax, double ymax, Visit&& visit) {
  const std::size_t nt = mesh_.triangles.size();
  const int width = map.out_width, height = map.out_height;
  std::vector<NeighbourWeight> weights;
  bool finite = true;
  for (const TriangleRecord& r : tri_) finite = finite && std::isfinite(r.centre.x) && std::isfinite(r.centre.y);
  if (!finite) {  // a sliver whose circumcentre overflowed: the per-pixel search needs no circle
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i)
        if (compute(map.sample(i, j), weights)) visit(i, j, weights);
    return;
  }
  // Sample points on the integer grid with integer vertices: incircle signs without rounding
  // (see CircleTest), and a vertex of t is then on its circle with F == 0 exactly.
  const bool exact = integer_points_ && map.sx == 1 && map.sy == 1 && width - 1 <= exact_limit &&
                     height - 1 <= exact_limit;
  // Each circle: centre and squared radius, and (used when exact) its incircle terms, in one
  // cache line for the row passes (indexed by slot, see below).
  struct alignas(64) Disk {
    double cx, cy, r2;
    double ax, ay, alpha, beta, gamma;  // as in CircleTest
  };
  std::vector<Disk> disk(nt);
  // With exact: the vertex at each pixel, if any (sample point (i, j) is pixel (i, j)).
  std::vector<std::uint32_t> vertex_at;
  if (exact) {
    vertex_at.assign(std::size_t(width) * height, no_neighbour);
    for (std::uint32_t v = 0; v < mesh_.points.size(); ++v) {
      const Point& q = mesh_.points[v];
      if (q.x < width && q.y < height) vertex_at[std::size_t(q.y) * width + std::size_t(q.x)] = v;
    }
  }
  // Rows whose sample line can meet each triangle's circle (with a row of margin).
  std::vector<int> first_row(nt), last_row(nt);
  for (std::uint32_t t = 0; t < nt; ++t) {
    const Point& a = mesh_.points[mesh_.triangles[t].v[0]];
    const Point& c = tri_[t].centre;
    const double r = std::sqrt((a.x - c.x) * (a.x - c.x) + (a.y - c.y) * (a.y - c.y));
    const double lo = (c.y - r) / map.sy, hi = (c.y + r) / map.sy;
    first_row[t] = lo < 1 ? 0 : lo > height ? height : int(lo) - 1;
    last_row[t] = hi < -1 ? -1 : hi > height - 2 ? height - 1 : int(hi) + 1;
  }
  // The circles renumbered by first row (counting sort; "slot" s, triangle order within a
  // row), so that the circles of neighbouring rows sit together in disk[]: the row passes
  // then read it from cache instead of in the triangles' order, which has no locality.
  std::vector<std::uint32_t> triangle_of(nt);  // slot -> triangle
  {
    std::vector<std::uint32_t> start(std::size_t(height) + 2, 0);
    for (std::uint32_t t = 0; t < nt; ++t) ++start[std::size_t(std::min(first_row[t], height)) + 1];
    for (int j = 0; j <= height; ++j) start[j + 1] += start[j];
    for (std::uint32_t t = 0; t < nt; ++t) triangle_of[start[std::min(first_row[t], height)]++] = t;
  }
  for (std::uint32_t s = 0; s < nt; ++s) {
    const std::uint32_t t = triangle_of[s];
    const Point& a = mesh_.points[mesh_.triangles[t].v[0]];
    const Point& c = tri_[t].centre;
    const CircleTest& k = circle_[t];
    disk[s] = {c.x, c.y, (a.x - c.x) * (a.x - c.x) + (a.y - c.y) * (a.y - c.y), k.ax, k.ay, k.alpha, k.beta, k.gamma};
  }
  // Each row's circles (slots), bucketed.
  std::vector<std::uint32_t> row_start(std::size_t(height) + 1, 0), row_items;
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int j = first_row[t]; j <= last_row[t]; ++j) ++row_start[j + 1];
  for (int j = 0; j < height; ++j) row_start[j + 1] += row_start[j];
  row_items.resize(row_start[height]);
  {
    std::vector<std::uint32_t> fill(row_start.begin(), row_start.end() - 1);
    for (std::uint32_t s = 0; s < nt; ++s) {
      const std::uint32_t t = triangle_of[s];
      for (int j = first_row[t]; j <= last_row[t]; ++j) row_items[fill[j]++] = s;
    }
  }
  // A column's events in increasing triangle order, as the active set's order (and with it
  // the order of the sums in stolen_areas) depends on it. Buckets hold a few items.
  auto sort_buckets = [&](std::vector<std::uint32_t>& items, const std::vector<std::uint32_t>& start) {
    for (int i = 0; i <= width; ++i)
      for (std::uint32_t k = start[i] + 1; k < start[i + 1]; ++k)
        for (std::uint32_t m = k; m > start[i] && items[m - 1] > items[m]; --m) std::swap(items[m - 1], items[m]);
  };

  // Per row: each circle's run of columns strictly inside it, from the chord's estimate
  // settled by exact tests at its ends (the run is an interval: a disk meets a line in a
  // segment). Entering and leaving columns become events; the sweep keeps the active set,
  // which for a point strictly inside the hull is its Bowyer-Watson cavity.
  std::vector<std::uint32_t> enter_start(std::size_t(width) + 2), leave_start(std::size_t(width) + 2);
  std::vector<std::uint32_t> enter_items, leave_items, enter_fill, leave_fill;
  std::vector<std::pair<int, int>> run;  // per row item: [first, last] column, first > last if none
  std::vector<std::uint32_t> active, position(nt, 0);
  std::vector<std::uint8_t> is_active(nt, 0);
  for (int j = 0; j < height; ++j) {
    const double y = map.sample(0, j).y;
    const std::uint32_t b0 = row_start[j], b1 = row_start[j + 1];
    run.assign(b1 - b0, {0, -1});
    std::fill(enter_start.begin(), enter_start.end(), 0);
    std::fill(leave_start.begin(), leave_start.end(), 0);
    for (std::uint32_t k = b0; k < b1; ++k) {
      const std::uint32_t t = triangle_of[row_items[k]];
      const auto& tv = mesh_.triangles[t].v;
      const Disk& d = disk[row_items[k]];
      auto in = [&](int i) {
        const Point p = map.sample(i, j);
        if (exact) {  // in_circle(t, p, true) from this cache line
          const double dx = p.x - d.ax, dy = p.y - d.ay, l = dx * dx + dy * dy;
          return d.alpha * dx + d.beta * dy + d.gamma * l > 0;
        }
        // A vertex of t is on its circle: skip the exact test the filter would need there.
        for (const std::uint32_t v : tv)
          if (mesh_.points[v].x == p.x && mesh_.points[v].y == p.y) return false;
        return in_circle(t, p, false);
      };
      const double dy = y - d.cy;
      const double h = std::sqrt(std::max(0.0, d.r2 - dy * dy));
      const double cx = d.cx / map.sx, hx = h / map.sx;
      // Columns are clamped to the image (the estimates lie far inside int range there).
      auto clamp_col = [&](double x) { return x < -1 ? -1.0 : x > width ? double(width) : x; };
      const double lo = clamp_col(cx - hx), hi = clamp_col(cx + hx);
      int first = floor_int(lo) + 1, last = ceil_int(hi) - 1;  // strictly inside
      first = std::max(first, 0);
      last = std::min(last, width - 1);
      if (first > last) {
        // The estimate says no column: the nearest columns to the centre settle it.
        const int c0 = floor_int(clamp_col(cx));
        first = width, last = -1;
        for (int c = std::max(c0, 0); c <= std::min(c0 + 1, width - 1); ++c)
          if (in(c)) first = std::min(first, c), last = std::max(last, c);
        if (first > last) continue;
      } else {
        if (!in(first) || !in(last)) {
          // Shrink to exact ends (only possible by rounding, at most a column or two).
          while (first <= last && !in(first)) ++first;
          while (last >= first && !in(last)) --last;
          if (first > last) continue;
        }
      }
      while (first > 0 && in(first - 1)) --first;
      while (last < width - 1 && in(last + 1)) ++last;
      run[k - b0] = {first, last};
      ++enter_start[first + 1];
      ++leave_start[last + 2];
    }
    for (int i = 0; i <= width; ++i) {
      enter_start[i + 1] += enter_start[i];
      leave_start[i + 1] += leave_start[i];
    }
    enter_items.resize(enter_start[width + 1]);
    leave_items.resize(leave_start[width + 1]);
    enter_fill.assign(enter_start.begin(), enter_start.end());
    leave_fill.assign(leave_start.begin(), leave_start.end());
    for (std::uint32_t k = b0; k < b1; ++k) {
      const auto [first, last] = run[k - b0];
      if (first > last) continue;
      const std::uint32_t t = triangle_of[row_items[k]];
      enter_items[enter_fill[first]++] = t;
      leave_items[leave_fill[last + 1]++] = t;
    }
    sort_buckets(enter_items, enter_start);
    sort_buckets(leave_items, leave_start);
    for (int i = 0; i < width; ++i) {
      for (std::uint32_t k = leave_start[i]; k < leave_start[i + 1]; ++k) {
        const std::uint32_t t = leave_items[k];
        const std::uint32_t moved = active.back();
        active[position[t]] = moved;
        position[moved] = position[t];
        active.pop_back();
        is_active[t] = 0;
      }
      for (std::uint32_t k = enter_start[i]; k < enter_start[i + 1]; ++k) {
        const std::uint32_t t = enter_items[k];
        position[t] = std::uint32_t(active.size());
        active.push_back(t);
        is_active[t] = 1;
      }
      const Point p = map.sample(i, j);
      bool ok;
      if (!(p.x >= 0 && p.x <= xmax && p.y >= 0 && p.y <= ymax)) {
        ok = compute(p, weights);  // the caller's rectangle is the hull; outside it by rounding
      } else if (active.empty()) {
        // In no circle: p is a vertex (its value alone, as compute() gives).
        const std::uint32_t v = exact ? vertex_at[std::size_t(j) * width + i] : no_neighbour;
        if (v != no_neighbour) {
          weights.assign(1, {v, 1.0});
          ok = true;
        } else {
          ok = compute(p, weights);
        }
      } else {
        next_query();
        ok = stolen_areas(p, active, [&](std::uint32_t n) { return n != no_neighbour && is_active[n]; }, weights);
        hint_ = active[0];
      }
      if (ok) visit(i, j, weights);
    }
    for (const std::uint32_t t : active) is_active[t] = 0;  // runs end within the row
    active.clear();
  }
}

std::vector<std::uint32_t> owning_triangles(const Mesh& mesh, const Topology& topo, const PixelMapping& map) {
  const int width = map.out_width;
  std::vector<std::uint32_t> owner(std::size_t(width) * map.out_height, no_neighbour);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const Point* corner[3] = {&mesh.points[v[0]], &mesh.points[v[1]], &mesh.points[v[2]]};
    // The same ownership rule as for_each_owned_pixel: inclusive[k][e] with k = 0 elsewhere,
    // 1 in column 0, 2 in row 0, 3 at pixel (0, 0).
    bool inclusive[4][3];
    for (int k = 0; k < 4; ++k)
      for (int e = 0; e < 3; ++e)
        inclusive[k][e] = topo.is_boundary_edge(t, e) ||
                          owns_edge_points(*corner[e], *corner[(e + 1) % 3], k & 1 ? 1 : -1, k & 2 ? 1 : -1);
    auto inside = [&](int i, int j) {
      const Point p = map.sample(i, j);
      const bool* incl = inclusive[(i == 0 ? 1 : 0) + (j == 0 ? 2 : 0)];
      for (int e = 0; e < 3; ++e) {
        const double o = orient2d(*corner[e], *corner[(e + 1) % 3], p);
        if (!(o > 0 || (o == 0 && incl[e]))) return false;
      }
      return true;
    };
    const double xmin = std::min({corner[0]->x, corner[1]->x, corner[2]->x});
    const double xmax = std::max({corner[0]->x, corner[1]->x, corner[2]->x});
    // Rows whose sample y lies in [ymin, ymax] (with a margin far above rounding).
    const double ymin = std::min({corner[0]->y, corner[1]->y, corner[2]->y});
    const double ymax = std::max({corner[0]->y, corner[1]->y, corner[2]->y});
    const int j0 = std::max(map.first_row(ymin), int(std::ceil(ymin / map.sy - 1e-7)));
    const int j1 = std::min(map.last_row(ymax), int(std::floor(ymax / map.sy + 1e-7)));
    // x = a.x + (y - a.y) * slope on each edge line; the kind of bound it gives.
    double slope[3];
    int kind[3];  // +1: upper bound on x, -1: lower bound, 0: horizontal edge
    for (int e = 0; e < 3; ++e) {
      const Point& a = *corner[e];
      const Point& b = *corner[(e + 1) % 3];
      const double dy = b.y - a.y;
      kind[e] = dy > 0 ? 1 : dy < 0 ? -1 : 0;
      slope[e] = dy != 0 ? (b.x - a.x) / dy : 0.0;
    }
    const double inv_sx = 1.0 / map.sx;
    // The estimates below are within about 1e-12 (domain units) of the exact edge lines, far
    // inside these margins (relative to the sample spacing).
    constexpr double near = 1e-7;
    const double near_x = near * map.sx;
    // Column 0 has its own tie rule, so it is tested alone; the span search runs over
    // columns >= 1, where all sample points share one rule and the owned set is an interval.
    const bool has_column0 = map.first_column(xmin) == 0;
    const int i_min = std::max(1, map.first_column(xmin)), i_max = map.last_column(xmax);
    for (int j = j0; j <= j1; ++j) {
      std::uint32_t* row = owner.data() + std::size_t(j) * width;
      if (has_column0 && inside(0, j)) row[0] = t;
      if (i_min > i_max) continue;
      // The row's span from the edge lines in floating point. The estimate is within 1e-9
      // pixel of the true ends, so only an end that close to a sample point (a sample point
      // on an edge or at a vertex) needs an exact test, of that one pixel.
      const double y = map.sample(0, j).y;
      const bool* incl = inclusive[j == 0 ? 2 : 0];
      double lo = xmin, hi = xmax;
      double bound[3] = {0, 0, 0};  // x of each sloped edge's line on this row
      bool empty = false;
      for (int e = 0; e < 3; ++e) {
        const Point& a = *corner[e];
        if (kind[e] != 0) {
          bound[e] = a.x + (y - a.y) * slope[e];
          if (kind[e] > 0) hi = std::min(hi, bound[e]);
          else lo = std::max(lo, bound[e]);
        } else {
          const Point& b = *corner[(e + 1) % 3];
          const double f = (b.x - a.x) * (y - a.y);  // exact sign: the row against a horizontal edge
          if (f < 0 || (f == 0 && !incl[e])) empty = true;
        }
      }
      if (empty) continue;
      // Whether column i (>= 1) of this row is owned: edges whose line is clearly away from
      // the sample point are decided by the estimate, the others by an exact orient2d.
      auto owned = [&](int i) {
        const Point p = map.sample(i, j);
        for (int e = 0; e < 3; ++e) {
          if (kind[e] == 0) continue;  // decided above for the whole row
          const double d = kind[e] > 0 ? bound[e] - p.x : p.x - bound[e];  // >= 0: inside
          if (d > near_x) continue;
          if (d < -near_x) return false;
          const double o = orient2d(*corner[e], *corner[(e + 1) % 3], p);
          if (!(o > 0 || (o == 0 && incl[e]))) return false;
        }
        return true;
      };
      // lo and hi lie in the bounding box, so the columns fit an int; ceil and floor by
      // truncation (std::ceil is a library call without SSE4.1).
      const double l = lo * inv_sx, h = hi * inv_sx;
      int cl = int(l), fh = int(h);
      cl += cl < l;
      fh -= fh > h;
      if (cl > fh + 2) continue;  // no candidate pixel
      int il = std::clamp(cl, i_min, i_max + 1);
      int ih = std::clamp(fh, i_min - 1, i_max);
      if (cl - l < near && il == cl && il <= i_max && !owned(il)) ++il;
      else if (l - (cl - 1) < near && il - 1 == cl - 1 && il - 1 >= i_min && owned(il - 1)) --il;
      if (h - fh < near && ih == fh && ih >= i_min && !owned(ih)) --ih;
      else if (fh + 1 - h < near && ih + 1 == fh + 1 && ih + 1 <= i_max && owned(ih + 1)) ++ih;
      if (il > ih) continue;
      std::fill(row + il, row + ih + 1, t);
    }
  }
  return owner;
}

namespace {

// Twice the area of a mesh's triangles, summed. Exact for coordinates on a fine enough
// binary grid (pixel positions, halves, ...).
double doubled_area(const Mesh& mesh) {
  double sum = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) sum += mesh.doubled_area(t);
  return sum;
}

}  // namespace

bool covers_rectangle(const Mesh& mesh, double xmax, double ymax) {
  int corners = 0;
  for (const Point& p : mesh.points) {
    if (p.x < 0 || p.x > xmax || p.y < 0 || p.y > ymax) return false;
    corners += (p.x == 0 || p.x == xmax) && (p.y == 0 || p.y == ymax);
  }
  return corners == 4 && doubled_area(mesh) == 2 * xmax * ymax;
}

void render_natural(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions&, Field& out) {
  const PixelMapping map(domain_width, domain_height, out.width, out.height);
  const double xmax = domain_width - 1, ymax = domain_height - 1;
  const Topology topo = build_topology(mesh);
  const bool full = covers_rectangle(mesh, xmax, ymax);
  // A mesh that covers the rectangle (its hull) and is locally Delaunay is a Delaunay
  // triangulation of its vertices, and is used as is; otherwise one is built.
  SibsonCoordinates sibson = full && is_locally_delaunay(mesh, topo) ? SibsonCoordinates(mesh, topo)
                                                                     : SibsonCoordinates(mesh.points);
  // Pixels of the domain: every sample point of the rectangle when the mesh covers it,
  // otherwise those the mesh's own coverage rule assigns. Either way they lie in the hull.
  std::vector<std::uint32_t> domain;
  if (!full) domain = owning_triangles(mesh, topo, map);
  const int nc = mesh.value_count;
  auto write = [&](int i, int j, const std::vector<NeighbourWeight>& weights) {
    for (int c = 0; c < nc; ++c) {
      double sum = 0;
      for (const NeighbourWeight& nw : weights) sum += nw.weight * mesh.value(nw.vertex, c);
      out.at(i, j, c) = sum;
    }
  };
  if (full) {
    sibson.sweep(map, xmax, ymax, write);
    return;
  }
  std::vector<NeighbourWeight> weights;
  std::uint32_t row_start = 0;  // where the next row's first search starts: this row's start
  for (int j = 0; j < out.height; ++j) {
    sibson.set_hint(row_start);
    for (int i = 0; i < out.width; ++i) {
      if (i == 1) row_start = sibson.hint();
      if (domain[std::size_t(j) * out.width + i] == no_neighbour) continue;
      if (sibson.compute_in_hull(map.sample(i, j), weights)) write(i, j, weights);
    }
  }
}

}  // namespace tristream
