// SPDX-License-Identifier: MIT
#include "reference/methods/clough_tocher.h"

#include <vector>

#include "model/topology.h"
#include "reference/coverage.h"

namespace tristream {
namespace {

double dot(const Gradient& g, double x, double y) { return g.gx * x + g.gy * y; }

}  // namespace

CloughTocherTriangle clough_tocher_triangle(const std::array<Point, 3>& p, const std::array<double, 3>& f,
                                            const std::array<Gradient, 3>& g) {
  const Point s{(p[0].x + p[1].x + p[2].x) / 3, (p[0].y + p[1].y + p[2].y) / 3};
  // Edge ordinates b[i][j] next to V_i on edge V_i V_j, and p_i next to V_i towards S.
  double b[3][3]{};
  std::array<double, 3> pi{}, e{}, q{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      if (j != i) b[i][j] = f[i] + dot(g[i], p[j].x - p[i].x, p[j].y - p[i].y) / 3;
    pi[i] = f[i] + dot(g[i], s.x - p[i].x, s.y - p[i].y) / 3;
  }
  // e[k]: the 111 ordinate of piece k on edge (V_k, V_k+1).
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const double ex = p[j].x - p[i].x, ey = p[j].y - p[i].y;
    const double dx = s.x - (p[i].x + p[j].x) / 2, dy = s.y - (p[i].y + p[j].y) / 2;
    const Gradient gm{(g[i].gx + g[j].gx) / 2, (g[i].gy + g[j].gy) / 2};
    const double gd = dot(gm, dx, dy);
    const double d_at_m = gd + 1.5 * (dx * ex + dy * ey) / (ex * ex + ey * ey) * ((f[j] - f[i]) - dot(gm, ex, ey));
    e[k] = (b[i][j] + b[j][i]) / 2 + (2 * d_at_m - gd) / 3;
  }
  // q_i next to S on the inner edge V_i S: pieces i (edge i, i+1) and i-1 (edge i-1, i) meet there.
  for (int i = 0; i < 3; ++i) q[i] = (pi[i] + e[i] + e[(i + 2) % 3]) / 3;
  const double fs = (q[0] + q[1] + q[2]) / 3;

  CloughTocherTriangle ct;
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    ct.piece[k] = {f[i], f[j], fs, b[i][j], b[j][i], pi[i], pi[j], q[i], q[j], e[k]};
  }
  return ct;
}

double clough_tocher_value(const CloughTocherTriangle& ct, double l0, double l1, double l2) {
  const double l[3] = {l0, l1, l2};
  // The point is in piece k = (V_k, V_k+1, S) when the coordinate of V_k+2 is the smallest;
  // with S the centroid, its coordinates there are (l_k - l_m, l_k+1 - l_m, 3 l_m).
  int m = 2;
  if (l[0] <= l[1] && l[0] <= l[2]) m = 0;
  else if (l[1] <= l[2]) m = 1;
  const int k = (m + 1) % 3;
  const double u = l[k] - l[m], v = l[(k + 1) % 3] - l[m], w = 3 * l[m];
  const auto& o = ct.piece[k];
  return o[0] * u * u * u + o[1] * v * v * v + o[2] * w * w * w +
         3 * (o[3] * u * u * v + o[4] * u * v * v + o[5] * u * u * w + o[6] * v * v * w + o[7] * u * w * w +
              o[8] * v * w * w) +
         6 * o[9] * u * v * w;
}

void render_clough_tocher(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                          Field& out) {
  const Topology topo = build_topology(mesh);
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const int nc = mesh.value_count;
  std::vector<std::vector<Gradient>> gradients;
  for (int c = 0; c < nc; ++c) gradients.push_back(vertex_gradients(mesh, topo, c));

  std::vector<CloughTocherTriangle> ct(nc);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const std::array<Point, 3> p{mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]};
    for (int c = 0; c < nc; ++c)
      ct[c] = clough_tocher_triangle(p, {mesh.value(v[0], c), mesh.value(v[1], c), mesh.value(v[2], c)},
                                     {gradients[c][v[0]], gradients[c][v[1]], gradients[c][v[2]]});
    for_each_owned_pixel(mesh, topo, t, map, [&](int i, int j, double l0, double l1, double l2) {
      for (int c = 0; c < nc; ++c) out.at(i, j, c) = clough_tocher_value(ct[c], l0, l1, l2);
    });
  }
}

}  // namespace tristream
