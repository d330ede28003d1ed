// SPDX-License-Identifier: MIT
#include "encoder/flips.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "encoder/barycentric.h"
#include "encoder/mesh_adjacency.h"
#include "encoder/pixel_scan.h"

namespace tristream::encoder {
namespace {

class Flipper {
 public:
  Flipper(Mesh& mesh, const Planes& target)
      : mesh_(mesh), target_(target), ch_(target.channels), across_(triangle_neighbours(mesh)) {
    sse_.resize(mesh.triangles.size());
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) sse_[t] = error(mesh.triangles[t].v);
  }

  // The squared error of the whole mesh: the sum of its triangles'.
  double total() const {
    double sum = 0;
    for (double e : sse_) sum += e;
    return sum;
  }

  std::size_t run(std::vector<std::uint8_t>& touched) {
    touched.assign(mesh_.points.size(), 0);
    std::size_t flips = 0;
    std::deque<std::uint32_t> work;
    std::vector<std::uint8_t> queued(mesh_.triangles.size(), 1);
    for (std::uint32_t t = 0; t < mesh_.triangles.size(); ++t) work.push_back(t);
    while (!work.empty()) {
      const std::uint32_t t = work.front();
      work.pop_front();
      queued[t] = 0;
      for (int e = 0; e < 3; ++e) {
        const std::uint32_t n = across_[t][e];
        if (n == no_neighbour) continue;
        std::array<std::uint32_t, 4> touched_triangles;
        if (!try_flip(t, e, touched_triangles)) continue;
        ++flips;
        for (std::uint32_t v : mesh_.triangles[t].v) touched[v] = 1;
        for (std::uint32_t v : mesh_.triangles[n].v) touched[v] = 1;
        for (std::uint32_t u : {t, n, touched_triangles[0], touched_triangles[1], touched_triangles[2],
                                touched_triangles[3]})
          if (u != no_neighbour && !queued[u]) queued[u] = 1, work.push_back(u);
        break;  // t is another triangle now: it is queued again
      }
    }
    return flips;
  }

 private:
  IntPoint position(std::uint32_t v) const {
    return {std::int32_t(mesh_.points[v].x), std::int32_t(mesh_.points[v].y)};
  }

  // Squared error over the pixels triangle (v0, v1, v2) owns, with the vertices' values.
  double error(const std::array<std::uint32_t, 3>& v) const {
    const std::array<IntPoint, 3> p{position(v[0]), position(v[1]), position(v[2])};
    const BarycentricPlanes b = barycentric_planes(p);
    const double* value[3] = {&mesh_.values[v[0] * ch_], &mesh_.values[v[1] * ch_], &mesh_.values[v[2] * ch_]};
    double sse = 0;
    scan_triangle(p, [&](int x, int y) {
      double l[3];
      for (int e = 0; e < 3; ++e) l[e] = b.ax[e] * x + b.ay[e] * y + b.a0[e];
      const float* px = &target_.v[(std::size_t(y) * target_.width + x) * ch_];
      for (int c = 0; c < ch_; ++c) {
        const double d = l[0] * value[0][c] + l[1] * value[1][c] + l[2] * value[2][c] - px[c];
        sse += d * d;
      }
    });
    return sse;
  }

  // Replaces `old` by `now` among n's neighbours.
  void repoint(std::uint32_t n, std::uint32_t old, std::uint32_t now) {
    if (n == no_neighbour) return;
    for (std::uint32_t& m : across_[n])
      if (m == old) m = now;
  }

  // Edge e of t1 is a -> b with c opposite; t2 across it is b -> a with d opposite. The quadrilateral
  // a, d, b, c is strictly convex iff (c, a, d) and (d, b, c) are positively oriented; those are
  // the triangles after the flip. `touched` receives the four outer neighbours.
  bool try_flip(std::uint32_t t1, int e1, std::array<std::uint32_t, 4>& touched) {
    const std::uint32_t t2 = across_[t1][e1];
    const auto& T1 = mesh_.triangles[t1].v;
    const auto& T2 = mesh_.triangles[t2].v;
    const std::uint32_t a = T1[e1], b = T1[(e1 + 1) % 3], c = T1[(e1 + 2) % 3];
    int e2 = 0;
    while (e2 < 3 && T2[e2] != b) ++e2;
    if (e2 == 3) return false;  // not edge to edge (the input breaks the precondition)
    const std::uint32_t d = T2[(e2 + 2) % 3];
    const IntPoint pa = position(a), pb = position(b), pc = position(c), pd = position(d);
    if (orient(pc, pa, pd) <= 0 || orient(pd, pb, pc) <= 0) return false;
    const std::array<std::uint32_t, 3> n1{c, a, d}, n2{d, b, c};
    const double before = sse_[t1] + sse_[t2];
    const double s1 = error(n1), s2 = error(n2);
    // A flip must gain more than rounding noise: no endless back-and-forth on ties.
    if (!(s1 + s2 < before - 1e-9 * (1 + before))) return false;
    const std::uint32_t n_bc = across_[t1][(e1 + 1) % 3], n_ca = across_[t1][(e1 + 2) % 3];
    const std::uint32_t n_ad = across_[t2][(e2 + 1) % 3], n_db = across_[t2][(e2 + 2) % 3];
    mesh_.triangles[t1].v = n1;
    mesh_.triangles[t2].v = n2;
    across_[t1] = {n_ca, n_ad, t2};
    across_[t2] = {n_db, n_bc, t1};
    repoint(n_ad, t2, t1);
    repoint(n_bc, t1, t2);
    sse_[t1] = s1;
    sse_[t2] = s2;
    touched = {n_bc, n_ca, n_ad, n_db};
    return true;
  }

  Mesh& mesh_;
  const Planes& target_;
  int ch_;
  std::vector<std::array<std::uint32_t, 3>> across_;
  std::vector<double> sse_;  // each triangle's squared error
};

}  // namespace

FlipReport flip_edges(Mesh& mesh, const Planes& target) {
  FlipReport report;
  Flipper flipper(mesh, target);
  report.sse_before = flipper.total();
  report.flips = flipper.run(report.touched);
  report.sse_after = flipper.total();
  return report;
}

}  // namespace tristream::encoder
