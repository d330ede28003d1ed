// SPDX-License-Identifier: MIT
#include "encoder/relocate.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "encoder/least_squares.h"
#include "encoder/pixel_scan.h"
#include "geometry/predicates.h"

namespace tristream::encoder {
namespace {

constexpr int max_channels = 4;

std::int64_t orient(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
  return std::int64_t(b.x - a.x) * (c.y - a.y) - std::int64_t(b.y - a.y) * (c.x - a.x);
}

// Sums over the star of one vertex (its triangles, the vertex at a trial position) that give
// the local squared error as a function of the vertex's value: e0 is the error with the
// current value, phi the vertex's barycentric weight.
struct StarSums {
  double ee = 0;
  double phi2 = 0;
  std::array<double, max_channels> ephi{};
  // Squared error with the vertex's value chosen by least squares.
  double best(int channels) const {
    double s = ee;
    if (phi2 > 0)
      for (int c = 0; c < channels; ++c) s -= ephi[c] * ephi[c] / phi2;
    return s;
  }
};

class Relocator {
 public:
  Relocator(Mesh& mesh, const Planes& target) : mesh_(mesh), target_(target), ch_(target.channels) {
    occupied_.assign(std::size_t(target.width) * target.height, 0);
    active_.assign(mesh.vertex_count(), 1);
    for (const Point& p : mesh.points) occupied_[std::size_t(p.y) * target.width + std::size_t(p.x)] = 1;
    const std::size_t n = mesh.vertex_count();
    start_.assign(n + 1, 0);
    for (const Triangle& t : mesh.triangles)
      for (std::uint32_t v : t.v) ++start_[v + 1];
    for (std::size_t v = 0; v < n; ++v) start_[v + 1] += start_[v];
    star_.resize(start_[n]);
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (std::uint32_t v : mesh.triangles[t].v) star_[fill[v]++] = std::uint32_t(t);
    // Neighbours: the triangle across edge e (v[e], v[e + 1]) of each triangle.
    struct HalfEdge {
      std::uint64_t key;
      std::uint32_t t;
      int e;
    };
    std::vector<HalfEdge> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int e = 0; e < 3; ++e) {
        const std::uint64_t a = mesh.triangles[t].v[e], b = mesh.triangles[t].v[(e + 1) % 3];
        edges.push_back({std::min(a, b) << 32 | std::max(a, b), std::uint32_t(t), e});
      }
    std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
      return x.key != y.key ? x.key < y.key : x.t < y.t;
    });
    across_.assign(mesh.triangles.size(), {none, none, none});
    for (std::size_t i = 0; i + 1 < edges.size(); ++i)
      if (edges[i].key == edges[i + 1].key) {
        across_[edges[i].t][edges[i].e] = edges[i + 1].t;
        across_[edges[i + 1].t][edges[i + 1].e] = edges[i].t;
      }
  }

  // One pass over the vertices; returns the number of moves.
  std::size_t pass() {
    std::size_t moves = 0;
    const int w = target_.width, h = target_.height;
    for (std::uint32_t v = 0; v < mesh_.vertex_count(); ++v) {
      if (!active_[v]) continue;
      active_[v] = 0;
      const IntPoint at = position(v);
      const bool fixed_x = at.x == 0 || at.x == w - 1, fixed_y = at.y == 0 || at.y == h - 1;
      if (fixed_x && fixed_y) continue;
      StarSums here = sums(v, at);
      double best = here.best(ch_);
      IntPoint best_at = at;
      StarSums best_sums = here;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (fixed_x && dx != 0) || (fixed_y && dy != 0)) continue;
          const IntPoint q{at.x + dx, at.y + dy};
          if (q.x < 0 || q.y < 0 || q.x >= w || q.y >= h || occupied_[std::size_t(q.y) * w + q.x]) continue;
          if (!valid(v, q)) continue;
          const StarSums s = sums(v, q);
          // A move must gain more than rounding noise: no endless back-and-forth on ties.
          if (s.best(ch_) < best - 1e-9 * (1 + here.ee)) best = s.best(ch_), best_at = q, best_sums = s;
        }
      if (best_at.x != at.x || best_at.y != at.y) {
        occupied_[std::size_t(at.y) * w + at.x] = 0;
        occupied_[std::size_t(best_at.y) * w + best_at.x] = 1;
        mesh_.points[v] = {double(best_at.x), double(best_at.y)};
        ++moves;
        for (std::size_t i = start_[v]; i < start_[v + 1]; ++i)
          for (std::uint32_t u : mesh_.triangles[star_[i]].v) active_[u] = 1;
      }
      if (best_sums.phi2 > 0)
        for (int c = 0; c < ch_; ++c)
          mesh_.values[v * ch_ + c] =
              std::clamp(mesh_.values[v * ch_ + c] - best_sums.ephi[c] / best_sums.phi2, 0.0, 255.0);
    }
    return moves;
  }

 private:
  IntPoint position(std::uint32_t v) const {
    return {std::int32_t(mesh_.points[v].x), std::int32_t(mesh_.points[v].y)};
  }

  // The corners of star triangle t with vertex v at q; `k` receives v's index in it.
  std::array<IntPoint, 3> corners(std::uint32_t t, std::uint32_t v, const IntPoint& q, int& k) const {
    std::array<IntPoint, 3> p;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = mesh_.triangles[t].v[e];
      p[e] = u == v ? q : position(u);
      if (u == v) k = e;
    }
    return p;
  }

  // With v at q, every triangle of v's star keeps a positive orientation and every edge of
  // those triangles stays locally Delaunay (the vertex beyond it is not strictly inside the
  // circumcircle): then the whole mesh is still a Delaunay triangulation.
  bool valid(std::uint32_t v, const IntPoint& q) const {
    for (std::size_t i = start_[v]; i < start_[v + 1]; ++i) {
      int k = 0;
      const auto p = corners(star_[i], v, q, k);
      if (orient(p[0], p[1], p[2]) <= 0) return false;
    }
    const Point qp{double(q.x), double(q.y)};
    for (std::size_t i = start_[v]; i < start_[v + 1]; ++i) {
      const std::uint32_t t = star_[i];
      Point c[3];
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t u = mesh_.triangles[t].v[e];
        c[e] = u == v ? qp : mesh_.points[u];
      }
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t n = across_[t][e];
        if (n == none) continue;
        const auto& nv = mesh_.triangles[n].v;
        const std::uint32_t a = mesh_.triangles[t].v[e], b = mesh_.triangles[t].v[(e + 1) % 3];
        for (std::uint32_t o : nv)
          if (o != a && o != b && incircle(c[0], c[1], c[2], mesh_.points[o]) > 0) return false;
      }
    }
    return true;
  }

  StarSums sums(std::uint32_t v, const IntPoint& q) const {
    StarSums s;
    for (std::size_t i = start_[v]; i < start_[v + 1]; ++i) {
      const std::uint32_t t = star_[i];
      int k = 0;
      const auto p = corners(t, v, q, k);
      const double area2 = double(orient(p[0], p[1], p[2]));
      // l_e(x, y) = (ax[e] x + ay[e] y + a0[e]) / area2, from the edge opposite corner e.
      double ax[3], ay[3], a0[3], val[3][max_channels];
      for (int e = 0; e < 3; ++e) {
        const IntPoint& b = p[(e + 1) % 3];
        const IntPoint& c = p[(e + 2) % 3];
        ax[e] = -(c.y - b.y) / area2;
        ay[e] = (c.x - b.x) / area2;
        a0[e] = (double(c.y - b.y) * b.x - double(c.x - b.x) * b.y) / area2;
        for (int ch = 0; ch < ch_; ++ch) val[e][ch] = mesh_.value(mesh_.triangles[t].v[e], ch);
      }
      scan_triangle(p, [&](int x, int y) {
        double l[3];
        for (int e = 0; e < 3; ++e) l[e] = ax[e] * x + ay[e] * y + a0[e];
        const double phi = l[k];
        s.phi2 += phi * phi;
        const float* px = &target_.v[(std::size_t(y) * target_.width + x) * ch_];
        for (int c = 0; c < ch_; ++c) {
          const double e0 = l[0] * val[0][c] + l[1] * val[1][c] + l[2] * val[2][c] - px[c];
          s.ee += e0 * e0;
          s.ephi[c] += e0 * phi;
        }
      });
    }
    return s;
  }

  Mesh& mesh_;
  const Planes& target_;
  int ch_;
  std::vector<std::uint8_t> occupied_;
  std::vector<std::uint8_t> active_;  // v or a neighbour moved since v was last tried
  std::vector<std::size_t> start_;   // star of v: star_[start_[v] .. start_[v + 1])
  std::vector<std::uint32_t> star_;  // triangle indices
  static constexpr std::uint32_t none = 0xFFFFFFFFu;
  std::vector<std::array<std::uint32_t, 3>> across_;
};

}  // namespace

RelocateReport relocate_vertices(Mesh& mesh, const Planes& target, int passes) {
  RelocateReport report;
  report.sse_before = linear_squared_error(mesh, target);
  // Every move and value change lowers the squared error of its star, the only pixels it
  // affects, so the total falls monotonically; the refit at the end lowers it further.
  Relocator relocator(mesh, target);
  for (int i = 0; i < passes; ++i) {
    const std::size_t moves = relocator.pass();
    report.moves += moves;
    ++report.passes;
    if (moves == 0) break;
  }
  fit_least_squares(mesh, target, false);
  report.sse_after = linear_squared_error(mesh, target);
  return report;
}

}  // namespace tristream::encoder
