// SPDX-License-Identifier: MIT
#include "encoder/relocate.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "encoder/barycentric.h"
#include "encoder/least_squares.h"
#include "encoder/mesh_adjacency.h"
#include "encoder/pixel_scan.h"
#include "geometry/predicates.h"

namespace tristream::encoder {
namespace {

constexpr int max_channels = 4;

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

// The interpolant (each channel) and the vertex's weight phi along one run of pixels: values at
// the run's first pixel and steps per pixel.
struct RunLine {
  double phi = 0, dphi = 0;
  std::array<double, max_channels> value{}, dvalue{};
};

// Adds a run of n pixels (px: CH floats each) to s. Values are taken at offsets i (value + i *
// dvalue, not stepped) and the sums go to two interleaved sets of accumulators, so that no
// chain of dependent additions sets the pace.
template <int CH>
void add_run(const RunLine& line, const float* px, int n, StarSums& s) {
  double ee[2][CH] = {}, ephi[2][CH] = {}, phi2[2] = {};
  auto pixel = [&](int i, int j) {
    const double phi = line.phi + line.dphi * i;
    phi2[j] += phi * phi;
    for (int c = 0; c < CH; ++c) {
      const double e = line.value[c] + line.dvalue[c] * i - px[i * CH + c];
      ee[j][c] += e * e;
      ephi[j][c] += e * phi;
    }
  };
  int i = 0;
  for (; i + 1 < n; i += 2) pixel(i, 0), pixel(i + 1, 1);
  if (i < n) pixel(i, 0);
  s.phi2 += phi2[0] + phi2[1];
  for (int c = 0; c < CH; ++c) {
    s.ee += ee[0][c] + ee[1][c];
    s.ephi[c] += ephi[0][c] + ephi[1][c];
  }
}

class Relocator {
 public:
  Relocator(Mesh& mesh, const Planes& target, bool keep_delaunay, const std::vector<std::uint8_t>* first_tried)
      : mesh_(mesh), target_(target), ch_(target.channels), keep_delaunay_(keep_delaunay) {
    if (ch_ < 1 || ch_ > max_channels)
      throw std::invalid_argument("relocate: expected 1 to " + std::to_string(max_channels) + " channels");
    occupied_.assign(std::size_t(target.width) * target.height, 0);
    if (first_tried && first_tried->size() != mesh.vertex_count())
      throw std::invalid_argument("relocate: expected one first_tried flag per vertex");
    active_ = first_tried ? *first_tried : std::vector<std::uint8_t>(mesh.vertex_count(), 1);
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
    across_ = triangle_neighbours(mesh);
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
    if (!keep_delaunay_) return true;
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
        if (n == no_neighbour) continue;
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
      const BarycentricPlanes b = barycentric_planes(p);
      const double(&ax)[3] = b.ax, (&ay)[3] = b.ay, (&a0)[3] = b.a0;
      double val[3][max_channels];
      for (int e = 0; e < 3; ++e)
        for (int ch = 0; ch < ch_; ++ch) val[e][ch] = mesh_.value(mesh_.triangles[t].v[e], ch);
      // Along a run the interpolant and phi are linear in x: their values at the run's start
      // and their x-derivatives.
      RunLine line;
      line.dphi = ax[k];
      for (int c = 0; c < ch_; ++c) line.dvalue[c] = ax[0] * val[0][c] + ax[1] * val[1][c] + ax[2] * val[2][c];
      scan_triangle_runs(p, [&](int y, int first, int last) {
        double l[3];
        for (int e = 0; e < 3; ++e) l[e] = ax[e] * first + ay[e] * y + a0[e];
        line.phi = l[k];
        for (int c = 0; c < ch_; ++c) line.value[c] = l[0] * val[0][c] + l[1] * val[1][c] + l[2] * val[2][c];
        const float* px = &target_.v[(std::size_t(y) * target_.width + first) * ch_];
        switch (ch_) {
          case 1: add_run<1>(line, px, last - first + 1, s); break;
          case 2: add_run<2>(line, px, last - first + 1, s); break;
          case 3: add_run<3>(line, px, last - first + 1, s); break;
          default: add_run<4>(line, px, last - first + 1, s); break;  // at most max_channels
        }
      });
    }
    return s;
  }

  Mesh& mesh_;
  const Planes& target_;
  int ch_;
  bool keep_delaunay_;
  std::vector<std::uint8_t> occupied_;
  std::vector<std::uint8_t> active_;  // v or a neighbour moved since v was last tried
  std::vector<std::size_t> start_;   // star of v: star_[start_[v] .. start_[v + 1])
  std::vector<std::uint32_t> star_;  // triangle indices
  std::vector<std::array<std::uint32_t, 3>> across_;
};

}  // namespace

RelocateReport relocate_vertices(Mesh& mesh, const Planes& target, int passes, bool keep_delaunay,
                                 const std::vector<std::uint8_t>* first_tried) {
  RelocateReport report;
  report.sse_before = linear_squared_error(mesh, target);
  // Every move and value change lowers the squared error of its star, the only pixels it
  // affects, so the total falls monotonically; the refit at the end lowers it further.
  Relocator relocator(mesh, target, keep_delaunay, first_tried);
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
