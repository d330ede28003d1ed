// SPDX-License-Identifier: MIT
#include "reference/methods/natural.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/circumcentre.h"
#include "geometry/delaunay.h"
#include "geometry/predicates.h"
#include "model/topology.h"
#include "reference/domain.h"

namespace tristream {
namespace {

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
  const double s =
      std::abs(pb.x - pa.x) >= std::abs(pb.y - pa.y) ? (p.x - pa.x) / (pb.x - pa.x) : (p.y - pa.y) / (pb.y - pa.y);
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

// Out of line: inlined into sweep_row's column loop it cost 6% more instructions (callgrind,
// kodim23 grey).
template <class Inside>
[[gnu::noinline]] bool SibsonCoordinates::stolen_areas(const Point& p, std::span<const std::uint32_t> cavity,
                                                       Inside inside, std::vector<NeighbourWeight>& out) {
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

// The circles of the row sweep. Each circle (centre, squared radius and, used when `exact`,
// its incircle terms) fills one cache line, renumbered by first row ("slot" s, triangle order
// within a row) so that the circles of neighbouring rows sit together: the row passes then
// read `disk` from cache instead of in the triangles' order, which has no locality.
struct SibsonCoordinates::SweepCircles {
  struct alignas(64) Disk {
    double cx, cy, r2;
    double ax, ay, alpha, beta, gamma;  // as in CircleTest
  };
  // Sample points on the integer grid with integer vertices: incircle signs without rounding
  // (see CircleTest), and a vertex of t is then on its circle with F == 0 exactly.
  bool exact = false;
  std::vector<Disk> disk;                  // per slot
  std::vector<std::uint32_t> triangle_of;  // slot -> triangle
  std::vector<std::uint32_t> row_start;    // row j's slots: row_items[row_start[j] .. row_start[j+1])
  std::vector<std::uint32_t> row_items;
  std::vector<std::uint32_t> vertex_at;  // with exact: the vertex at each pixel, if any
};

// One row's events: per column, the circles whose run of columns starts there (enter) and
// those whose run ended at the column before (leave), each bucket in increasing triangle
// order, as the active set's order (and with it the order of the sums in stolen_areas)
// depends on it.
struct SibsonCoordinates::RowEvents {
  std::vector<std::uint32_t> enter_start, leave_start, enter_items, leave_items, enter_fill, leave_fill;
  std::vector<std::pair<int, int>> run;  // per row item: [first, last] column, first > last if none
};

// The circles containing the current column's sample point: the point's cavity.
struct SibsonCoordinates::ActiveCircles {
  std::vector<std::uint32_t> active, position;
  std::vector<std::uint8_t> is_active;

  explicit ActiveCircles(std::size_t triangles) : position(triangles, 0), is_active(triangles, 0) {}
  void leave(std::uint32_t t) {
    const std::uint32_t moved = active.back();
    active[position[t]] = moved;
    position[moved] = position[t];
    active.pop_back();
    is_active[t] = 0;
  }
  void enter(std::uint32_t t) {
    position[t] = std::uint32_t(active.size());
    active.push_back(t);
    is_active[t] = 1;
  }
  void clear() {
    for (const std::uint32_t t : active) is_active[t] = 0;
    active.clear();
  }
};

SibsonCoordinates::SweepCircles SibsonCoordinates::sweep_circles(const PixelMapping& map) const {
  const std::size_t nt = mesh_.triangles.size();
  const int width = map.out_width, height = map.out_height;
  SweepCircles circles;
  circles.exact =
      integer_points_ && map.sx == 1 && map.sy == 1 && width - 1 <= exact_limit && height - 1 <= exact_limit;
  if (circles.exact) {
    circles.vertex_at.assign(std::size_t(width) * height, no_neighbour);
    for (std::uint32_t v = 0; v < mesh_.points.size(); ++v) {
      const Point& q = mesh_.points[v];
      if (q.x < width && q.y < height) circles.vertex_at[std::size_t(q.y) * width + std::size_t(q.x)] = v;
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
  // Slots by first row (a counting sort).
  circles.triangle_of.resize(nt);
  {
    std::vector<std::uint32_t> start(std::size_t(height) + 2, 0);
    for (std::uint32_t t = 0; t < nt; ++t) ++start[std::size_t(std::min(first_row[t], height)) + 1];
    for (int j = 0; j <= height; ++j) start[j + 1] += start[j];
    for (std::uint32_t t = 0; t < nt; ++t) circles.triangle_of[start[std::min(first_row[t], height)]++] = t;
  }
  circles.disk.resize(nt);
  for (std::uint32_t s = 0; s < nt; ++s) {
    const std::uint32_t t = circles.triangle_of[s];
    const Point& a = mesh_.points[mesh_.triangles[t].v[0]];
    const Point& c = tri_[t].centre;
    const CircleTest& k = circle_[t];
    circles.disk[s] = {c.x,    c.y,    (a.x - c.x) * (a.x - c.x) + (a.y - c.y) * (a.y - c.y), k.ax, k.ay, k.alpha,
                       k.beta, k.gamma};
  }
  // Each row's circles (slots), bucketed.
  std::vector<std::uint32_t>& row_start = circles.row_start;
  row_start.assign(std::size_t(height) + 1, 0);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int j = first_row[t]; j <= last_row[t]; ++j) ++row_start[j + 1];
  for (int j = 0; j < height; ++j) row_start[j + 1] += row_start[j];
  circles.row_items.resize(row_start[height]);
  std::vector<std::uint32_t> fill(row_start.begin(), row_start.end() - 1);
  for (std::uint32_t s = 0; s < nt; ++s) {
    const std::uint32_t t = circles.triangle_of[s];
    for (int j = first_row[t]; j <= last_row[t]; ++j) circles.row_items[fill[j]++] = s;
  }
  return circles;
}

// The columns of row j strictly inside the circle of `slot`, as [first, last] (first > last:
// none), from the chord's estimate settled by exact tests at its ends (the run is an interval:
// a disk meets a line in a segment).
[[gnu::always_inline]] inline std::pair<int, int> SibsonCoordinates::circle_run(const SweepCircles& circles,
                                                                                const PixelMapping& map,
                                                                                std::uint32_t slot, int j) const {
  const int width = map.out_width;
  const std::uint32_t t = circles.triangle_of[slot];
  const auto& tv = mesh_.triangles[t].v;
  const SweepCircles::Disk& d = circles.disk[slot];
  auto in = [&](int i) {
    const Point p = map.sample(i, j);
    if (circles.exact) {  // in_circle(t, p, true) from this cache line
      const double dx = p.x - d.ax, dy = p.y - d.ay, l = dx * dx + dy * dy;
      return d.alpha * dx + d.beta * dy + d.gamma * l > 0;
    }
    // A vertex of t is on its circle: skip the exact test the filter would need there.
    for (const std::uint32_t v : tv)
      if (mesh_.points[v].x == p.x && mesh_.points[v].y == p.y) return false;
    return in_circle(t, p, false);
  };
  const double dy = map.sample(0, j).y - d.cy;
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
    if (first > last) return {0, -1};
  } else if (!in(first) || !in(last)) {
    // Shrink to exact ends (only possible by rounding, at most a column or two).
    while (first <= last && !in(first)) ++first;
    while (last >= first && !in(last)) --last;
    if (first > last) return {0, -1};
  }
  while (first > 0 && in(first - 1)) --first;
  while (last < width - 1 && in(last + 1)) ++last;
  return {first, last};
}

void SibsonCoordinates::row_events(const SweepCircles& circles, const PixelMapping& map, int j,
                                   RowEvents& events) const {
  const int width = map.out_width;
  const std::uint32_t b0 = circles.row_start[j], b1 = circles.row_start[j + 1];
  events.run.assign(b1 - b0, {0, -1});
  events.enter_start.assign(std::size_t(width) + 2, 0);
  events.leave_start.assign(std::size_t(width) + 2, 0);
  for (std::uint32_t k = b0; k < b1; ++k) {
    const auto [first, last] = circle_run(circles, map, circles.row_items[k], j);
    if (first > last) continue;
    events.run[k - b0] = {first, last};
    ++events.enter_start[first + 1];
    ++events.leave_start[last + 2];
  }
  for (int i = 0; i <= width; ++i) {
    events.enter_start[i + 1] += events.enter_start[i];
    events.leave_start[i + 1] += events.leave_start[i];
  }
  events.enter_items.resize(events.enter_start[width + 1]);
  events.leave_items.resize(events.leave_start[width + 1]);
  events.enter_fill.assign(events.enter_start.begin(), events.enter_start.end());
  events.leave_fill.assign(events.leave_start.begin(), events.leave_start.end());
  for (std::uint32_t k = b0; k < b1; ++k) {
    const auto [first, last] = events.run[k - b0];
    if (first > last) continue;
    const std::uint32_t t = circles.triangle_of[circles.row_items[k]];
    events.enter_items[events.enter_fill[first]++] = t;
    events.leave_items[events.leave_fill[last + 1]++] = t;
  }
  // Buckets hold a few items: insertion sort.
  auto sort_buckets = [&](std::vector<std::uint32_t>& items, const std::vector<std::uint32_t>& start) {
    for (int i = 0; i <= width; ++i)
      for (std::uint32_t k = start[i] + 1; k < start[i + 1]; ++k)
        for (std::uint32_t m = k; m > start[i] && items[m - 1] > items[m]; --m) std::swap(items[m - 1], items[m]);
  };
  sort_buckets(events.enter_items, events.enter_start);
  sort_buckets(events.leave_items, events.leave_start);
}

template <class Visit>
void SibsonCoordinates::sweep_row(const SweepCircles& circles, const RowEvents& events, const PixelMapping& map,
                                  double xmax, double ymax, int j, ActiveCircles& cavity,
                                  std::vector<NeighbourWeight>& weights, Visit&& visit) {
  const int width = map.out_width;
  for (int i = 0; i < width; ++i) {
    for (std::uint32_t k = events.leave_start[i]; k < events.leave_start[i + 1]; ++k)
      cavity.leave(events.leave_items[k]);
    for (std::uint32_t k = events.enter_start[i]; k < events.enter_start[i + 1]; ++k)
      cavity.enter(events.enter_items[k]);
    const Point p = map.sample(i, j);
    bool ok;
    if (!(p.x >= 0 && p.x <= xmax && p.y >= 0 && p.y <= ymax)) {
      ok = compute(p, weights);  // the caller's rectangle is the hull; outside it by rounding
    } else if (cavity.active.empty()) {
      // In no circle: p is a vertex (its value alone, as compute() gives).
      const std::uint32_t v = circles.exact ? circles.vertex_at[std::size_t(j) * width + i] : no_neighbour;
      if (v != no_neighbour) {
        weights.assign(1, {v, 1.0});
        ok = true;
      } else {
        ok = compute(p, weights);
      }
    } else {
      next_query();
      const auto& is_active = cavity.is_active;
      ok = stolen_areas(
          p, cavity.active, [&](std::uint32_t n) { return n != no_neighbour && is_active[n]; }, weights);
      hint_ = cavity.active[0];
    }
    if (ok) visit(i, j, weights);
  }
  cavity.clear();  // runs end within the row
}

// Per row: each circle's run of columns strictly inside it; entering and leaving columns
// become events, and the sweep keeps the active set, which for a point strictly inside the
// hull is its Bowyer-Watson cavity.
template <class Visit>
void SibsonCoordinates::sweep(const PixelMapping& map, double xmax, double ymax, Visit&& visit) {
  std::vector<NeighbourWeight> weights;
  bool finite = true;
  for (const TriangleRecord& r : tri_) finite = finite && std::isfinite(r.centre.x) && std::isfinite(r.centre.y);
  if (!finite) {  // a sliver whose circumcentre overflowed: the per-pixel search needs no circle
    for (int j = 0; j < map.out_height; ++j)
      for (int i = 0; i < map.out_width; ++i)
        if (compute(map.sample(i, j), weights)) visit(i, j, weights);
    return;
  }
  const SweepCircles circles = sweep_circles(map);
  RowEvents events;
  ActiveCircles cavity(mesh_.triangles.size());
  for (int j = 0; j < map.out_height; ++j) {
    row_events(circles, map, j, events);
    sweep_row(circles, events, map, xmax, ymax, j, cavity, weights, visit);
  }
}

namespace {

// The pixels of `domain` (owning_triangles) one by one: each cavity grown from the previous
// pixel's start triangle (a row starts where the previous row's second pixel did).
template <class Write>
void search_domain_pixels(SibsonCoordinates& sibson, const std::vector<std::uint32_t>& domain, const PixelMapping& map,
                          Write&& write) {
  std::vector<NeighbourWeight> weights;
  std::uint32_t row_start = 0;  // where the next row's first search starts: this row's start
  for (int j = 0; j < map.out_height; ++j) {
    sibson.set_hint(row_start);
    for (int i = 0; i < map.out_width; ++i) {
      if (i == 1) row_start = sibson.hint();
      if (domain[std::size_t(j) * map.out_width + i] == no_neighbour) continue;
      if (sibson.compute_in_hull(map.sample(i, j), weights)) write(i, j, weights);
    }
  }
}

}  // namespace

void render_natural(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const double xmax = domain_width - 1, ymax = domain_height - 1;
  const Topology topo = build_topology(mesh);
  const bool full = covers_rectangle(mesh, xmax, ymax);
  // A mesh that covers the rectangle (its hull) and is locally Delaunay is a Delaunay
  // triangulation of its vertices, and is used as is; otherwise one is built.
  SibsonCoordinates sibson =
      full && is_locally_delaunay(mesh, topo) ? SibsonCoordinates(mesh, topo) : SibsonCoordinates(mesh.points);
  const int nc = mesh.value_count;
  auto write = [&](int i, int j, const std::vector<NeighbourWeight>& weights) {
    for (int c = 0; c < nc; ++c) {
      double sum = 0;
      for (const NeighbourWeight& nw : weights) sum += nw.weight * mesh.value(nw.vertex, c);
      out.at(i, j, c) = sum;
    }
  };
  // Pixels of the domain: every sample point of the rectangle when the mesh covers it,
  // otherwise those the mesh's own coverage rule assigns. Either way they lie in the hull.
  if (full) sibson.sweep(map, xmax, ymax, write);
  else search_domain_pixels(sibson, owning_triangles(mesh, topo, map), map, write);
}

}  // namespace tristream
