// SPDX-License-Identifier: MIT
#include "encoder/hermite_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "encoder/barycentric.h"
#include "encoder/mesh_adjacency.h"
#include "encoder/pixel_scan.h"
#include "model/topology.h"
#include "reference/gradients.h"
#include "reference/methods/clough_tocher.h"
#include "reference/methods/zienkiewicz.h"

namespace tristream::encoder {
namespace {

// Unknowns per vertex and channel: the value, then the gradient's x and y.
constexpr int per_vertex = 3;
constexpr double core_max_gradient = 32767;  // TS_MAX_GRADIENT of firmware_core/include/tristream/config.h
constexpr int core_gradient_frac_bits = 12;  // TS_GRADIENT_FRAC_BITS

// The interpolant of one triangle as nine basis functions: w[i][k] is the weight at a point of
// corner i's value (k = 0) or gradient component (k = 1: x, 2: y). Built by evaluating the
// reference's own coefficients for unit data, so it is the reference's interpolant exactly.
class TriangleBasis {
 public:
  TriangleBasis(HermiteMethod method, const std::array<Point, 3>& p) : method_(method) {
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < per_vertex; ++k) {
        std::array<double, 3> f{};
        std::array<Gradient, 3> g{};
        if (k == 0) f[i] = 1;
        else if (k == 1) g[i].gx = 1;
        else g[i].gy = 1;
        if (method == HermiteMethod::zienkiewicz)
          z_[i][k] = zienkiewicz_coefficients(p[0], p[1], p[2], f[0], f[1], f[2], g[0], g[1], g[2]);
        else
          ct_[i][k] = clough_tocher_triangle(p, f, g);
      }
  }

  void weights(double l0, double l1, double l2, double w[3][per_vertex]) const {
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < per_vertex; ++k)
        w[i][k] = method_ == HermiteMethod::zienkiewicz ? zienkiewicz_value(z_[i][k], l0, l1, l2)
                                                        : clough_tocher_value(ct_[i][k], l0, l1, l2);
  }

 private:
  HermiteMethod method_;
  ZienkiewiczCoefficients z_[3][per_vertex];
  CloughTocherTriangle ct_[3][per_vertex];
};

std::array<IntPoint, 3> pixel_corners(const Mesh& mesh, std::size_t t, const Planes& target) {
  std::array<IntPoint, 3> p;
  for (int e = 0; e < 3; ++e) {
    const Point& q = mesh.points[mesh.triangles[t].v[e]];
    if (q.x != std::floor(q.x) || q.y != std::floor(q.y) || q.x < 0 || q.y < 0 || q.x >= target.width ||
        q.y >= target.height)
      throw std::invalid_argument("hermite fit: vertices must be pixel positions");
    p[e] = {std::int32_t(q.x), std::int32_t(q.y)};
  }
  if (orient(p[0], p[1], p[2]) <= 0) throw std::invalid_argument("hermite fit: triangles must be positively oriented");
  return p;
}

// Calls visit(x, y, l0, l1, l2) for every pixel of triangle t with its barycentric coordinates.
template <class Visit>
void for_each_pixel(const std::array<IntPoint, 3>& p, Visit&& visit) {
  const BarycentricPlanes b = barycentric_planes(p);
  scan_triangle(p, [&](int x, int y) {
    double l[3];
    for (int e = 0; e < 3; ++e) l[e] = b.ax[e] * x + b.ay[e] * y + b.a0[e];
    visit(x, y, l[0], l[1], l[2]);
  });
}

// The normal equations in 3 x 3 blocks, one per entry of the vertices' rows (as
// fit_least_squares's matrix).
struct BlockMatrix : VertexRows {
  using Block = std::array<double, per_vertex * per_vertex>;
  std::vector<Block> block;

  explicit BlockMatrix(const Mesh& mesh) : VertexRows(vertex_rows(mesh)), block(col.size(), Block{}) {}

  // out = A in, over unknowns 3 v + k.
  void multiply(const std::vector<double>& in, std::vector<double>& out) const {
    const std::size_t n = row.size() - 1;
    for (std::size_t i = 0; i < n; ++i) {
      double s[per_vertex] = {};
      for (std::size_t e = row[i]; e < row[i + 1]; ++e) {
        const Block& b = block[e];
        const double* x = &in[per_vertex * std::size_t(col[e])];
        for (int k = 0; k < per_vertex; ++k)
          for (int l = 0; l < per_vertex; ++l) s[k] += b[k * per_vertex + l] * x[l];
      }
      for (int k = 0; k < per_vertex; ++k) out[per_vertex * i + k] = s[k];
    }
  }
};

// The inverse of the free part of each diagonal block (the first unknown held when
// `values_fixed`): block-Jacobi preconditioning. A block that is not positive definite (a vertex no
// triangle uses has no value term) falls back to the inverse of its diagonal, 0 where that is 0: the
// preconditioner stays finite and positive semi-definite, and such an unknown keeps its start.
std::vector<BlockMatrix::Block> inverse_diagonal(const BlockMatrix& a, bool values_fixed) {
  const std::size_t n = a.row.size() - 1;
  std::vector<BlockMatrix::Block> inv(n, BlockMatrix::Block{});
  for (std::size_t v = 0; v < n; ++v) {
    const auto& d = a.block[a.row[v]];
    auto& r = inv[v];
    auto diagonal = [&] {
      r = BlockMatrix::Block{};
      for (int k = values_fixed ? 1 : 0; k < per_vertex; ++k)
        r[k * per_vertex + k] = d[k * per_vertex + k] > 0 ? 1 / d[k * per_vertex + k] : 0;
    };
    if (values_fixed) {
      const double a11 = d[4], a12 = d[5], a21 = d[7], a22 = d[8];
      const double det = a11 * a22 - a12 * a21;
      if (!(a11 > 0 && det > 1e-12 * a11 * a22)) {
        diagonal();
        continue;
      }
      r[4] = a22 / det, r[5] = -a12 / det, r[7] = -a21 / det, r[8] = a11 / det;
      continue;
    }
    const double c00 = d[4] * d[8] - d[5] * d[7], c01 = d[5] * d[6] - d[3] * d[8], c02 = d[3] * d[7] - d[4] * d[6];
    const double det = d[0] * c00 + d[1] * c01 + d[2] * c02;
    if (!(d[0] > 0 && c00 > 0 && det > 1e-12 * d[0] * d[4] * d[8])) {
      diagonal();
      continue;
    }
    r[0] = c00 / det, r[3] = c01 / det, r[6] = c02 / det;
    r[1] = (d[2] * d[7] - d[1] * d[8]) / det, r[4] = (d[0] * d[8] - d[2] * d[6]) / det,
    r[7] = (d[1] * d[6] - d[0] * d[7]) / det;
    r[2] = (d[1] * d[5] - d[2] * d[4]) / det, r[5] = (d[2] * d[3] - d[0] * d[5]) / det,
    r[8] = (d[0] * d[4] - d[1] * d[3]) / det;
  }
  return inv;
}

struct Solve {
  int iterations = 0;
  double residual = 0;
};

// Preconditioned conjugate gradients for A x = b from x; with `values_fixed` the values stay as
// they are and only the gradients move (the residual is kept zero on the values).
Solve conjugate_gradients(const BlockMatrix& a, const std::vector<double>& b, std::vector<double>& x,
                          bool values_fixed) {
  const std::size_t n = a.row.size() - 1, m = per_vertex * n;
  const auto inv = inverse_diagonal(a, values_fixed);
  std::vector<double> r(m), z(m), p(m), q(m);
  auto mask = [&](std::vector<double>& u) {
    if (values_fixed)
      for (std::size_t v = 0; v < n; ++v) u[per_vertex * v] = 0;
  };
  auto precondition = [&](const std::vector<double>& in, std::vector<double>& out) {
    for (std::size_t v = 0; v < n; ++v)
      for (int k = 0; k < per_vertex; ++k) {
        double s = 0;
        for (int l = 0; l < per_vertex; ++l) s += inv[v][k * per_vertex + l] * in[per_vertex * v + l];
        out[per_vertex * v + k] = s;
      }
  };
  a.multiply(x, q);
  double bnorm = 0;
  for (std::size_t i = 0; i < m; ++i) r[i] = b[i] - q[i];
  mask(r);
  std::vector<double> bm = b;
  mask(bm);
  for (double v : bm) bnorm += v * v;
  bnorm = std::sqrt(bnorm);
  precondition(r, z);
  p = z;
  double rz = 0;
  for (std::size_t i = 0; i < m; ++i) rz += r[i] * z[i];
  Solve s;
  constexpr int max_iterations = 5000;
  constexpr double tolerance = 1e-9;
  double rnorm = 0;
  for (; s.iterations < max_iterations; ++s.iterations) {
    rnorm = 0;
    for (double ri : r) rnorm += ri * ri;
    rnorm = std::sqrt(rnorm);
    if (bnorm == 0 || rnorm <= tolerance * bnorm) break;
    a.multiply(p, q);
    mask(q);
    double pq = 0;
    for (std::size_t i = 0; i < m; ++i) pq += p[i] * q[i];
    if (!(pq > 0 && rz > 0)) break;  // nothing left the preconditioner can see
    const double alpha = rz / pq;
    for (std::size_t i = 0; i < m; ++i) x[i] += alpha * p[i], r[i] -= alpha * q[i];
    precondition(r, z);
    double rz_next = 0;
    for (std::size_t i = 0; i < m; ++i) rz_next += r[i] * z[i];
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < m; ++i) p[i] = z[i] + beta * p[i];
  }
  s.residual = bnorm == 0 ? 0 : rnorm / bnorm;
  return s;
}

}  // namespace

HermiteFitReport fit_hermite(Mesh& mesh, const Planes& target, const HermiteFitOptions& options) {
  if (mesh.value_count != target.channels)
    throw std::invalid_argument("hermite fit: mesh and target differ in channel count");
  if (options.gradient_step_bits < 0 || options.gradient_step_bits > core_gradient_frac_bits + 8)
    throw std::invalid_argument("hermite fit: gradient step bits out of range");
  const std::size_t n = mesh.vertex_count();
  const int ch = target.channels;
  const std::size_t m = per_vertex * n;

  // Normal equations: one matrix for every channel, a right-hand side each.
  BlockMatrix a(mesh);
  std::vector<std::vector<double>> b(ch, std::vector<double>(m, 0.0));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto p = pixel_corners(mesh, t, target);
    const auto& v = mesh.triangles[t].v;
    const TriangleBasis basis(options.method, {mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]});
    // The triangle's 9 x 9 matrix, symmetric: its upper half summed over the pixels, unknown
    // i * per_vertex + k being corner i's k.
    constexpr int d = 3 * per_vertex;
    double local[d][d] = {};
    for_each_pixel(p, [&](int x, int y, double l0, double l1, double l2) {
      double w[3][per_vertex];
      basis.weights(l0, l1, l2, w);
      const double* u = &w[0][0];
      for (int r = 0; r < d; ++r)
        for (int q = r; q < d; ++q) local[r][q] += u[r] * u[q];
      for (int c = 0; c < ch; ++c) {
        const double value = target.at(x, y, c);
        for (int i = 0; i < 3; ++i)
          for (int k = 0; k < per_vertex; ++k) b[c][per_vertex * v[i] + k] += w[i][k] * value;
      }
    });
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        auto& blk = a.block[a.entry(v[i], v[j])];
        for (int k = 0; k < per_vertex; ++k)
          for (int l = 0; l < per_vertex; ++l) {
            const int r = i * per_vertex + k, q = j * per_vertex + l;
            blk[k * per_vertex + l] += r <= q ? local[r][q] : local[q][r];
          }
      }
  }

  // The pull of each gradient towards the surface estimate of the current values.
  const Topology topo = build_topology(mesh);
  std::vector<double> weight(n);
  for (std::size_t v = 0; v < n; ++v) {
    auto& d = a.block[a.row[v]];
    weight[v] = std::max(options.regularisation * 0.5 * (d[4] + d[8]), 1e-9);
    d[4] += weight[v];
    d[8] += weight[v];
  }

  HermiteFitReport report;
  std::vector<double> x(m), gradients(2 * n * std::size_t(ch));
  for (int c = 0; c < ch; ++c) {
    const std::vector<Gradient> estimate = estimated_vertex_gradients(mesh, topo, c);
    for (std::size_t v = 0; v < n; ++v) {
      b[c][per_vertex * v + 1] += weight[v] * estimate[v].gx;
      b[c][per_vertex * v + 2] += weight[v] * estimate[v].gy;
      x[per_vertex * v] = mesh.value(v, c);
      x[per_vertex * v + 1] = estimate[v].gx;
      x[per_vertex * v + 2] = estimate[v].gy;
    }
    const Solve joint = conjugate_gradients(a, b[c], x, false);
    for (std::size_t v = 0; v < n; ++v) x[per_vertex * v] = std::clamp(std::round(x[per_vertex * v]), 0.0, 255.0);
    const Solve held = conjugate_gradients(a, b[c], x, true);
    report.iterations += joint.iterations + held.iterations;
    report.residual = std::max({report.residual, joint.residual, held.residual});
    const double unit = std::ldexp(1.0, options.gradient_step_bits - core_gradient_frac_bits);
    const double limit = std::floor(core_max_gradient / unit) * unit;
    for (std::size_t v = 0; v < n; ++v) {
      mesh.values[v * ch + c] = x[per_vertex * v];
      for (int k = 0; k < 2; ++k)
        gradients[(v * ch + c) * 2 + k] =
            std::clamp(std::round(x[per_vertex * v + 1 + k] / unit) * unit, -limit, limit);
    }
  }
  mesh.gradients = std::move(gradients);
  return report;
}

double hermite_squared_error(const Mesh& mesh, const Planes& target, HermiteMethod method) {
  if (mesh.value_count != target.channels)
    throw std::invalid_argument("hermite fit: mesh and target differ in channel count");
  const Topology topo = build_topology(mesh);
  const int ch = target.channels;
  std::vector<std::vector<Gradient>> g;
  for (int c = 0; c < ch; ++c) g.push_back(vertex_gradients(mesh, topo, c));
  double sse = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto p = pixel_corners(mesh, t, target);
    const auto& v = mesh.triangles[t].v;
    const TriangleBasis basis(method, {mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]]});
    for_each_pixel(p, [&](int x, int y, double l0, double l1, double l2) {
      double w[3][per_vertex];
      basis.weights(l0, l1, l2, w);
      for (int c = 0; c < ch; ++c) {
        double value = 0;
        for (int i = 0; i < 3; ++i)
          value += w[i][0] * mesh.value(v[i], c) + w[i][1] * g[c][v[i]].gx + w[i][2] * g[c][v[i]].gy;
        const double e = value - target.at(x, y, c);
        sse += e * e;
      }
    });
  }
  return sse;
}

}  // namespace tristream::encoder
