// SPDX-License-Identifier: MIT
#include "reference/methods/voronoi.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "geometry/circumcentre.h"
#include "geometry/delaunay.h"
#include "geometry/predicates.h"
#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/domain.h"
#include "reference/gradients.h"
#include "reference/methods/zienkiewicz.h"

namespace tristream {
namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Mesh triangles by a uniform grid of buckets, to find a triangle containing a point.
class TriangleGrid {
 public:
  TriangleGrid(const Mesh& mesh, double width, double height) : mesh_(mesh) {
    const double n = std::max<double>(1, mesh.triangles.size());
    cell_ = std::max(1.0, 2 * std::sqrt(std::max(1.0, width * height) / n));
    nx_ = std::max(1, int(std::ceil(width / cell_)) + 1);
    ny_ = std::max(1, int(std::ceil(height / cell_)) + 1);
    start_.assign(std::size_t(nx_) * ny_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
      for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        int x0, x1, y0, y1;
        range(t, x0, x1, y0, y1);
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const std::size_t c = std::size_t(y) * nx_ + x;
            if (pass == 0) ++start_[c + 1];
            else items_[fill[c]++] = t;
          }
      }
      if (pass == 0) {
        for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
        items_.resize(start_.back());
      }
    }
  }

  // A triangle whose closed interior contains p, or no_neighbour.
  std::uint32_t find(const Point& p) const {
    const int x = bucket(p.x, nx_);
    const int y = bucket(p.y, ny_);
    const std::size_t c = std::size_t(y) * nx_ + x;
    // The first triangle of the bucket that holds p (closed); signs as orient2d's, from
    // detail::orient_filtered (reference/coverage.h).
    for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
      const auto& v = mesh_.triangles[items_[k]].v;
      const Point &a = mesh_.points[v[0]], &b = mesh_.points[v[1]], &d = mesh_.points[v[2]];
      if (detail::orient_filtered(a, b, p, false) >= 0 && detail::orient_filtered(b, d, p, false) >= 0 &&
          detail::orient_filtered(d, a, p, false) >= 0)
        return items_[k];
    }
    return no_neighbour;
  }

 private:
  void range(std::uint32_t t, int& x0, int& x1, int& y0, int& y1) const {
    const auto& v = mesh_.triangles[t].v;
    const Point &a = mesh_.points[v[0]], &b = mesh_.points[v[1]], &c = mesh_.points[v[2]];
    x0 = bucket(std::min({a.x, b.x, c.x}), nx_);
    x1 = bucket(std::max({a.x, b.x, c.x}), nx_);
    y0 = bucket(std::min({a.y, b.y, c.y}), ny_);
    y1 = bucket(std::max({a.y, b.y, c.y}), ny_);
  }

  // clamp(floor(x / cell_), 0, n - 1), without a library call for floor.
  int bucket(double x, int n) const {
    const double u = x / cell_;
    const double c = u < 0 ? -1.0 : u > n ? double(n) : u;
    const int i = int(c);
    return std::clamp(i - (i > c), 0, n - 1);
  }

  const Mesh& mesh_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::uint32_t> start_, items_;
};

// The lowest-numbered triangle of mesh (orient2d > 0 winding) that holds p (closed), as
// TriangleGrid::find() gives it, by a visibility walk from triangle t: when the walk ends
// with p strictly inside a triangle, that triangle is the only one; with p inside an edge
// shared by two triangles, the lower of the two (a valid mesh does not overlap). No_neighbour
// when the walk cannot tell: it leaves the mesh, takes long (it may cycle in a triangulation
// that is not Delaunay), or ends with p at a vertex or on a boundary edge.
// `exact`: every coordinate (the mesh's and p's) a multiple of 1/2 of magnitude <= 2^20; the
// orientation determinant then has no rounding (products of differences are multiples of 1/4
// below 2^42), which spares the exact predicate for circumcentres on an edge (the midpoint
// of a right triangle's hypotenuse).
std::uint32_t walk_to_owner(const Mesh& mesh, const Topology& topo, std::uint32_t t, const Point& p, bool exact) {
  for (int steps = 0; steps < 64; ++steps) {
    const auto& v = mesh.triangles[t].v;
    int cross = -1, zeros = 0, zero_edge = 0;
    for (int e = 0; e < 3 && cross < 0; ++e) {
      const double o = detail::orient_filtered(mesh.points[v[e]], mesh.points[v[e == 2 ? 0 : e + 1]], p, exact);
      if (o < 0) cross = e;
      if (o == 0) ++zeros, zero_edge = e;
    }
    if (cross < 0) {
      if (zeros == 0) return t;
      if (zeros > 1) return no_neighbour;
      const std::uint32_t n = topo.neighbour[3 * t + zero_edge];
      return n == no_neighbour ? no_neighbour : std::min(t, n);
    }
    t = topo.neighbour[3 * t + cross];
    if (t == no_neighbour) return no_neighbour;
  }
  return no_neighbour;
}

// Whether v is a multiple of 1/2 of magnitude <= 2^20.
bool on_half_grid(double v) { return std::abs(v) <= 0x1p20 && 2 * v == std::trunc(2 * v); }

// Barycentric coordinates of p in triangle t of mesh (orient2d > 0 winding).
std::array<double, 3> barycentric(const Mesh& mesh, std::uint32_t t, const Point& p) {
  const auto& v = mesh.triangles[t].v;
  const Point &p0 = mesh.points[v[0]], &p1 = mesh.points[v[1]], &p2 = mesh.points[v[2]];
  const double area = cross(p1.x - p0.x, p1.y - p0.y, p2.x - p0.x, p2.y - p0.y);
  const double l0 = cross(p1.x - p.x, p1.y - p.y, p2.x - p.x, p2.y - p.y) / area;
  const double l1 = cross(p2.x - p.x, p2.y - p.y, p0.x - p.x, p0.y - p.y) / area;
  return {l0, l1, 1.0 - l0 - l1};
}

}  // namespace

VoronoiDiagram::VoronoiDiagram(std::span<const Point> points) : sites_(points.size()) {
  mesh_.points.assign(points.begin(), points.end());
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) {
    x0 = x1 = points[0].x;
    y0 = y1 = points[0].y;
    for (const Point& p : points) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  }
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const double s = 20 * std::max({x1 - x0, y1 - y0, 1.0});
  mesh_.points.push_back({cx, cy - s});
  mesh_.points.push_back({cx - s, cy + s});
  mesh_.points.push_back({cx + s, cy + s});
  mesh_.triangles = delaunay_triangulation(mesh_.points);
  topo_ = build_topology(mesh_);

  std::vector<Point> centre(mesh_.triangles.size());
  for (std::size_t t = 0; t < centre.size(); ++t) {
    const auto& v = mesh_.triangles[t].v;
    centre[t] = circumcentre(mesh_.points[v[0]], mesh_.points[v[1]], mesh_.points[v[2]]);
  }
  auto index_of = [&](std::uint32_t t, std::uint32_t v) {
    const auto& tv = mesh_.triangles[t].v;
    return tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
  };

  cell_start_.assign(1, 0);
  neighbour_start_.assign(1, 0);
  std::vector<std::int8_t> edge_cocircular(3 * mesh_.triangles.size(), -1);  // -1: not asked yet
  std::vector<std::uint32_t> ring;
  for (std::uint32_t v = 0; v < sites_; ++v) {
    ring.clear();
    if (topo_.vertex_start[v] < topo_.vertex_start[v + 1]) {
      // Around v: crossing edge v -> next of each triangle; v is inside the far triangle, so
      // the ring closes.
      const std::uint32_t first = topo_.vertex_triangles[topo_.vertex_start[v]];
      std::uint32_t t = first;
      do {
        ring.push_back(t);
        t = topo_.neighbour[3 * t + index_of(t, v)];
      } while (t != first && t != no_neighbour && ring.size() <= mesh_.triangles.size());
    }
    const std::size_t m = ring.size();
    const std::size_t cell_begin = cell_points_.size();
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint32_t prev = ring[(i + m - 1) % m], t = ring[i];
      // prev and t share edge v -> x; they have one circumcentre iff t's third vertex lies on
      // prev's circumcircle.
      const int k = index_of(prev, v);
      const std::uint32_t x = mesh_.triangles[prev].v[(k + 1) % 3];
      std::uint32_t opposite = 0;
      for (std::uint32_t w : mesh_.triangles[t].v)
        if (w != v && w != x) opposite = w;
      const auto& pv = mesh_.triangles[prev].v;
      auto cocircular = [&] {
        return incircle(mesh_.points[pv[0]], mesh_.points[pv[1]], mesh_.points[pv[2]], mesh_.points[opposite]) == 0;
      };
      bool same_centre = false;
      if (m > 1) {
        // Cocircularity of the four points is symmetric: the answer is kept for the edge,
        // which the ring of x asks about again.
        if (topo_.neighbour[3 * prev + k] == t) {
          std::int8_t& known = edge_cocircular[3 * std::size_t(prev) + k];
          if (known < 0) {
            known = cocircular();
            edge_cocircular[3 * std::size_t(t) + index_of(t, x)] = known;
          }
          same_centre = known;
        } else {
          same_centre = cocircular();
        }
      }
      if (same_centre) continue;
      cell_points_.push_back(centre[t]);
      cell_tris_.push_back(t);
    }
    if (cell_points_.size() == cell_begin && m > 0) {  // all cocircular: cannot happen for distinct sites
      cell_points_.push_back(centre[ring[0]]);
      cell_tris_.push_back(ring[0]);
    }
    cell_start_.push_back(std::uint32_t(cell_points_.size()));
    for (const std::uint32_t t : ring) {
      const std::uint32_t x = mesh_.triangles[t].v[(index_of(t, v) + 1) % 3];
      if (x < sites_) neighbours_.push_back(x), neighbour_points_.push_back(mesh_.points[x]);
    }
    neighbour_start_.push_back(std::uint32_t(neighbours_.size()));
    // The site nearest to v is one of its Delaunay neighbours. A point closer to v than
    // half that distance is strictly nearer to v than to any other site (triangle
    // inequality); the margin covers the rounding of both squared distances.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint32_t k = neighbour_start_[v]; k < neighbour_start_[v + 1]; ++k) {
      const double dx = neighbour_points_[k].x - mesh_.points[v].x, dy = neighbour_points_[k].y - mesh_.points[v].y;
      nearest = std::min(nearest, dx * dx + dy * dy);
    }
    safe_d2_.push_back(0.25 * nearest * (1 - 1e-12));
  }
}

std::span<const Point> VoronoiDiagram::cell(std::uint32_t v) const {
  return {cell_points_.data() + cell_start_[v], cell_points_.data() + cell_start_[v + 1]};
}

std::span<const std::uint32_t> VoronoiDiagram::cell_triangles(std::uint32_t v) const {
  return {cell_tris_.data() + cell_start_[v], cell_tris_.data() + cell_start_[v + 1]};
}

std::uint32_t VoronoiDiagram::nearest_site(const Point& p, std::uint32_t start) const {
  auto d2 = [&](std::uint32_t v) {
    const double dx = mesh_.points[v].x - p.x, dy = mesh_.points[v].y - p.y;
    return dx * dx + dy * dy;
  };
  std::uint32_t v = start;
  double best = d2(v);
  // Strictly nearest (the walk would scan v's neighbours, find none closer and stop).
  if (best < safe_d2_[v]) return v;
  for (std::size_t steps = 0; steps <= sites_; ++steps) {
    std::uint32_t next_k = no_neighbour;
    for (std::uint32_t k = neighbour_start_[v], e = neighbour_start_[v + 1]; k < e; ++k) {
      const double dx = neighbour_points_[k].x - p.x, dy = neighbour_points_[k].y - p.y;
      const double d = dx * dx + dy * dy;  // d2(neighbours_[k])
      if (d < best) best = d, next_k = k;
    }
    if (next_k == no_neighbour) break;
    v = neighbours_[next_k];
  }
  return v;
}

namespace {

// Meyer / Wachspress weights of p in the convex polygon q[0..n) (n >= 3) into w[0..n), given
// corner[j] = cross(q[j] - q[j-1], q[j+1] - q[j]) (independent of p, so a caller with many
// points per polygon computes it once). area, prefix and suffix: scratch of n + 1 doubles.
void meyer_weights(const Point* q, const double* corner, std::size_t n, const Point& p, double* w, double* area,
                   double* prefix, double* suffix) {
  // Eq. 3.12 equals Wachspress's coordinates on a convex polygon: with A_k the doubled area
  // of (p, Q_k, Q_k+1) and C_j that of (Q_j-1, Q_j, Q_j+1),
  //   (cot gamma_j + cot delta_j) / |p - Q_j|^2 = C_j / (A_j-1 A_j).
  // Multiplied through by the product of all A_k, w_j = C_j * prod_{k != j-1, j} A_k: the
  // same weights after normalisation, but stable next to an edge, where the cotangent form
  // divides rounding noise by rounding noise. On edge k's line (A_k == 0) only Q_k and Q_k+1
  // keep a weight, in proportion to the other end's distance: the thesis's fallback, linear
  // interpolation along the edge.
  double scale = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Point& a = q[k];
    const Point& b = q[k + 1 == n ? 0 : k + 1];
    area[k] = cross(a.x - p.x, a.y - p.y, b.x - p.x, b.y - p.y);
    scale = std::max(scale, std::abs(area[k]));
  }
  // prefix[i] = A_0 ... A_i-1, suffix[i] = A_i ... A_n-1.
  prefix[0] = 1;
  suffix[n] = 1;
  if (scale > 0) {
    for (std::size_t k = 0; k < n; ++k) {
      area[k] /= scale;  // keeps the products in range
      prefix[k + 1] = prefix[k] * area[k];
    }
  } else {
    for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] * area[k];
  }
  for (std::size_t k = n; k-- > 0;) suffix[k] = suffix[k + 1] * area[k];
  double sum = 0;
  {
    // j = 0: product of all A_k but A_n-1 and A_0.
    double others = 1;
    for (std::size_t k = 1; k + 1 < n; ++k) others *= area[k];
    w[0] = corner[0] * others;
    sum += w[0];
  }
  for (std::size_t j = 1; j < n; ++j) {
    w[j] = corner[j] * (prefix[j - 1] * suffix[j + 1]);  // all A_k but A_j-1 and A_j
    sum += w[j];
  }
  if (sum != 0 && std::isfinite(sum)) {
    for (std::size_t j = 0; j < n; ++j) w[j] /= sum;
    return;
  }
  // Degenerate (p at a vertex of a polygon with a repeated vertex, or underflow): linear
  // interpolation along the edge nearest to p's line.
  std::size_t k = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (std::abs(area[i]) < std::abs(area[k])) k = i;
  const Point& a = q[k];
  const Point& b = q[(k + 1) % n];
  const double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey;
  const double t = len2 > 0 ? std::clamp(((p.x - a.x) * ex + (p.y - a.y) * ey) / len2, 0.0, 1.0) : 0.0;
  std::fill(w, w + n, 0.0);
  w[k] += 1 - t;
  w[(k + 1) % n] += t;
}

// corner[j] of meyer_weights for polygon q[0..n).
void polygon_corners(const Point* q, std::size_t n, double* corner) {
  for (std::size_t j = 0; j < n; ++j) {
    const Point& q0 = q[(j + n - 1) % n];
    const Point& q1 = q[j];
    const Point& q2 = q[(j + 1) % n];
    corner[j] = cross(q1.x - q0.x, q1.y - q0.y, q2.x - q1.x, q2.y - q1.y);
  }
}

}  // namespace

void meyer_coordinates(std::span<const Point> polygon, const Point& p, std::vector<double>& w) {
  const std::size_t n = polygon.size();
  w.assign(n, 0.0);
  if (n == 0) return;
  if (n < 3) {
    w[0] = 1;
    return;
  }
  thread_local std::vector<double> scratch;
  scratch.resize(4 * (n + 1));
  double* corner = scratch.data();
  polygon_corners(polygon.data(), n, corner);
  meyer_weights(polygon.data(), corner, n, p, w.data(), corner + (n + 1), corner + 2 * (n + 1), corner + 3 * (n + 1));
}

namespace {

// Finds the mesh triangle holding a point: a short walk from a triangle at a nearby vertex,
// and, for the points the walks cannot settle (a few dozen: points at a vertex or on the
// domain's boundary), a grid of buckets built on first use.
class MeshLocator {
 public:
  MeshLocator(const Mesh& mesh, const Topology& topo, double xmax, double ymax)
      : mesh_(mesh), topo_(topo), xmax_(xmax), ymax_(ymax) {
    for (const Point& x : mesh.points) half_grid_ = half_grid_ && on_half_grid(x.x) && on_half_grid(x.y);
  }

  // The walk's start next to vertex x, or no_neighbour.
  std::uint32_t fan_start(std::uint32_t x) const {
    return has_fan(x) ? topo_.vertex_triangles[topo_.vertex_start[x]] : no_neighbour;
  }
  bool has_fan(std::uint32_t x) const {
    return x < mesh_.points.size() && topo_.vertex_start[x] < topo_.vertex_start[x + 1];
  }
  // walk_to_owner from `start`, or no_neighbour.
  std::uint32_t walk(std::uint32_t start, const Point& q) const {
    return walk_to_owner(mesh_, topo_, start, q, half_grid_ && on_half_grid(q.x) && on_half_grid(q.y));
  }
  std::uint32_t grid_find(const Point& q) {
    if (!grid_) grid_.emplace(mesh_, xmax_, ymax_);
    return grid_->find(q);
  }

 private:
  const Mesh& mesh_;
  const Topology& topo_;
  double xmax_, ymax_;
  bool half_grid_ = true;
  std::optional<TriangleGrid> grid_;
};

// The zienkiewicz value of the mesh at each Delaunay triangle's circumcentre inside the image
// rectangle and the mesh's domain (NaN and has_value 0 elsewhere), nc values per triangle.
struct CircumcentreValues {
  std::vector<double> value;
  std::vector<std::uint8_t> has_value;
};

CircumcentreValues circumcentre_values(const Mesh& mesh, const Topology& topo, const Mesh& dt, double xmax, double ymax,
                                       MeshLocator& locator) {
  const int nc = mesh.value_count;
  std::vector<std::vector<Gradient>> gradients;
  for (int c = 0; c < nc; ++c) gradients.push_back(vertex_gradients(mesh, topo, c));
  CircumcentreValues out{std::vector<double>(dt.triangles.size() * nc, std::numeric_limits<double>::quiet_NaN()),
                         std::vector<std::uint8_t>(dt.triangles.size(), 0)};
  for (std::uint32_t t = 0; t < dt.triangles.size(); ++t) {
    const auto& dv = dt.triangles[t].v;
    const Point q = circumcentre(dt.points[dv[0]], dt.points[dv[1]], dt.points[dv[2]]);
    if (!(q.x >= 0 && q.x <= xmax && q.y >= 0 && q.y <= ymax)) continue;
    // The mesh triangle holding q (the lowest-numbered closed one): a short walk from a
    // triangle at one of t's vertices, or where the walk cannot tell, the grid.
    std::uint32_t m = no_neighbour;
    for (const std::uint32_t x : dv)
      if (locator.has_fan(x)) {
        // Start from the mesh triangle with the most vertices in common with t.
        std::uint32_t start = topo.vertex_triangles[topo.vertex_start[x]];
        for (std::uint32_t k = topo.vertex_start[x]; k < topo.vertex_start[x + 1]; ++k) {
          const auto& mv = mesh.triangles[topo.vertex_triangles[k]].v;
          int shared = 0;
          for (const std::uint32_t y : mv) shared += y == dv[0] || y == dv[1] || y == dv[2];
          if (shared == 3) {
            start = topo.vertex_triangles[k];
            break;
          }
        }
        m = locator.walk(start, q);
        break;
      }
    if (m == no_neighbour) m = locator.grid_find(q);
    if (m == no_neighbour) continue;
    const auto& v = mesh.triangles[m].v;
    const auto l = barycentric(mesh, m, q);
    for (int c = 0; c < nc; ++c) {
      const ZienkiewiczCoefficients k = zienkiewicz_coefficients(
          mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.value(v[0], c), mesh.value(v[1], c),
          mesh.value(v[2], c), gradients[c][v[0]], gradients[c][v[1]], gradients[c][v[2]]);
      out.value[std::size_t(t) * nc + c] = zienkiewicz_value(k, l[0], l[1], l[2]);
    }
    out.has_value[t] = 1;
  }
  return out;
}

// A vertex of a clipped cell and the Delaunay triangle (circumcentre) whose value it takes.
struct CellVertex {
  Point q;
  std::uint32_t source;
};

// Whether the convex polygon `cell` holds point k (on its boundary included).
bool holds_point(std::span<const Point> cell, const Point& k) {
  bool left = false, right = false;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const Point& a = cell[i];
    const Point& b = cell[(i + 1) % cell.size()];
    const double o = cross(b.x - a.x, b.y - a.y, k.x - a.x, k.y - a.y);
    left = left || o > 0;
    right = right || o < 0;
  }
  return !(left && right);
}

// Sutherland-Hodgman of `poly` against x >= 0, x <= xmax, y >= 0, y <= ymax; a point made on
// edge S -> E takes the source of the endpoint inside the current half-plane. `next` is scratch.
void clip_to_rectangle(std::vector<CellVertex>& poly, std::vector<CellVertex>& next, double xmax, double ymax) {
  for (int plane = 0; plane < 4 && !poly.empty(); ++plane) {
    auto dist = [&](const Point& q) {  // >= 0 inside
      switch (plane) {
        case 0: return q.x;
        case 1: return xmax - q.x;
        case 2: return q.y;
        default: return ymax - q.y;
      }
    };
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const CellVertex& a = poly[i];
      const CellVertex& b = poly[(i + 1) % poly.size()];
      const double da = dist(a.q), db = dist(b.q);
      if (da >= 0) next.push_back(a);
      if ((da >= 0) != (db >= 0) && da != 0 && db != 0) {
        const double t = da / (da - db);
        Point q{a.q.x + t * (b.q.x - a.q.x), a.q.y + t * (b.q.y - a.q.y)};
        if (plane == 0) q.x = 0;
        if (plane == 1) q.x = xmax;
        if (plane == 2) q.y = 0;
        if (plane == 3) q.y = ymax;
        next.push_back({q, da >= 0 ? a.source : b.source});
      }
    }
    std::swap(poly, next);
  }
}

// Per site, its cell clipped to the rectangle when every vertex of it has a value, else
// nothing (the bilinear pre-fill): what every pixel of a cell reads, per clipped vertex its
// point, its corner term of meyer_weights (independent of the pixel) and its values.
struct ClippedCells {
  std::vector<std::uint32_t> start;  // site s: [start[s], start[s + 1])
  std::vector<Point> point;
  std::vector<double> corner, value;  // value: nc per vertex
  std::size_t max_cell = 0;

  bool interpolates(std::uint32_t site) const { return start[site] < start[site + 1]; }
};

ClippedCells clip_cells(const VoronoiDiagram& voronoi, const CircumcentreValues& values, int nc, double xmax,
                        double ymax) {
  const std::size_t sites = voronoi.site_count();
  ClippedCells cells;
  cells.start.assign(sites + 1, 0);
  std::vector<CellVertex> clipped, poly, next;
  const Point corners[4] = {{0, 0}, {xmax, 0}, {xmax, ymax}, {0, ymax}};
  for (std::uint32_t s = 0; s < sites; ++s) {
    cells.start[s] = std::uint32_t(clipped.size());
    const auto cell = voronoi.cell(s);
    const auto tris = voronoi.cell_triangles(s);
    // A cell holding a corner of the rectangle is left to the bilinear pre-fill.
    bool holds_corner = false;
    for (const Point& k : corners) holds_corner = holds_corner || holds_point(cell, k);
    if (holds_corner || cell.size() < 3) continue;
    poly.clear();
    for (std::size_t i = 0; i < cell.size(); ++i) poly.push_back({cell[i], tris[i]});
    clip_to_rectangle(poly, next, xmax, ymax);
    bool valued = poly.size() >= 3;
    for (const CellVertex& x : poly) valued = valued && values.has_value[x.source];
    if (valued) clipped.insert(clipped.end(), poly.begin(), poly.end());
  }
  cells.start[sites] = std::uint32_t(clipped.size());
  cells.point.resize(clipped.size());
  cells.corner.resize(clipped.size());
  cells.value.resize(clipped.size() * nc);
  for (std::uint32_t s = 0; s < sites; ++s) {
    const std::uint32_t b = cells.start[s], e = cells.start[s + 1];
    cells.max_cell = std::max<std::size_t>(cells.max_cell, e - b);
    for (std::uint32_t x = b; x < e; ++x) {
      cells.point[x] = clipped[x].q;
      for (int c = 0; c < nc; ++c)
        cells.value[std::size_t(x) * nc + c] = values.value[std::size_t(clipped[x].source) * nc + c];
    }
    if (e > b) polygon_corners(cells.point.data() + b, e - b, cells.corner.data() + b);
  }
  return cells;
}

// The linear interpolant of the mesh at p in triangle t.
void write_bilinear(const Mesh& mesh, std::uint32_t t, const Point& p, int i, int j, Field& out) {
  const auto& v = mesh.triangles[t].v;
  const auto l = barycentric(mesh, t, p);
  for (int c = 0; c < mesh.value_count; ++c)
    out.at(i, j, c) = l[0] * mesh.value(v[0], c) + l[1] * mesh.value(v[1], c) + l[2] * mesh.value(v[2], c);
}

}  // namespace

void render_voronoi(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const Topology topo = build_topology(mesh);
  const double xmax = domain_width - 1, ymax = domain_height - 1;
  // The domain's pixels: all of them when the mesh covers the rectangle, otherwise those the
  // mesh's coverage rule assigns (with their triangle, for the bilinear pre-fill).
  std::vector<std::uint32_t> domain;
  if (!covers_rectangle(mesh, xmax, ymax)) domain = owning_triangles(mesh, topo, map);
  const int nc = mesh.value_count;
  const VoronoiDiagram voronoi(mesh.points);
  MeshLocator locator(mesh, topo, xmax, ymax);
  const ClippedCells cells =
      clip_cells(voronoi, circumcentre_values(mesh, topo, voronoi.delaunay(), xmax, ymax, locator), nc, xmax, ymax);

  const std::size_t stride = cells.max_cell + 1;
  std::vector<double> scratch(4 * stride);
  double* const w = scratch.data();
  std::uint32_t site = 0, row_site = 0;  // nearest sites of the last pixel and of the row start
  for (int j = 0; j < out.height; ++j) {
    site = row_site;
    for (int i = 0; i < out.width; ++i) {
      const std::size_t k = std::size_t(j) * out.width + i;
      if (!domain.empty() && domain[k] == no_neighbour) continue;
      const Point p = map.sample(i, j);
      if (domain.empty() && !(p.x >= 0 && p.x <= xmax && p.y >= 0 && p.y <= ymax)) continue;
      // The nearest site: a short greedy walk from the previous pixel's.
      site = voronoi.nearest_site(p, site);
      if (i == 0) row_site = site;
      if (cells.interpolates(site)) {
        const std::uint32_t b = cells.start[site];
        const std::size_t n = cells.start[site + 1] - b;
        meyer_weights(cells.point.data() + b, cells.corner.data() + b, n, p, w, w + stride, w + 2 * stride,
                      w + 3 * stride);
        const double* const val = cells.value.data() + std::size_t(b) * nc;
        for (int c = 0; c < nc; ++c) {
          double sum = 0;
          for (std::size_t x = 0; x < n; ++x) sum += w[x] * val[x * nc + c];
          out.at(i, j, c) = sum;
        }
        continue;
      }
      // Bilinear pre-fill, in the mesh triangle holding p: the domain's owner, else from a
      // triangle at the nearest site (a mesh vertex), else the grid.
      std::uint32_t t = no_neighbour;
      if (!domain.empty()) {
        t = domain[k];
      } else {
        const std::uint32_t start = locator.fan_start(site);
        if (start != no_neighbour) t = locator.walk(start, p);
        if (t == no_neighbour) t = locator.grid_find(p);
      }
      if (t != no_neighbour) write_bilinear(mesh, t, p, i, j, out);
    }
  }
}

}  // namespace tristream
