// SPDX-License-Identifier: MIT
#include "encoder/least_squares.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "encoder/mesh_adjacency.h"
#include "encoder/pixel_scan.h"

namespace tristream::encoder {
namespace {

struct TriangleScan {
  std::array<IntPoint, 3> p;
  double area2;  // orient2d of the triangle
};

std::vector<TriangleScan> prepare(const Mesh& mesh, const Planes& target) {
  if (mesh.value_count != target.channels)
    throw std::invalid_argument("least squares: mesh and target differ in channel count");
  std::vector<TriangleScan> out(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      const Point& q = mesh.points[mesh.triangles[t].v[e]];
      if (q.x != std::floor(q.x) || q.y != std::floor(q.y) || q.x < 0 || q.y < 0 || q.x >= target.width ||
          q.y >= target.height)
        throw std::invalid_argument("least squares: vertices must be pixel positions");
      out[t].p[e] = {std::int32_t(q.x), std::int32_t(q.y)};
    }
    const auto& p = out[t].p;
    out[t].area2 = double(std::int64_t(p[1].x - p[0].x) * (p[2].y - p[0].y) -
                          std::int64_t(p[1].y - p[0].y) * (p[2].x - p[0].x));
  }
  return out;
}

// Barycentric coordinates of pixel (x, y): l[i] is the weight of vertex i.
inline void barycentric(const TriangleScan& s, int x, int y, double l[3]) {
  for (int i = 0; i < 3; ++i) {
    const IntPoint& b = s.p[(i + 1) % 3];
    const IntPoint& c = s.p[(i + 2) % 3];
    l[i] = double(std::int64_t(c.x - b.x) * (y - b.y) - std::int64_t(c.y - b.y) * (x - b.x)) / s.area2;
  }
}

}  // namespace

double linear_squared_error(const Mesh& mesh, const Planes& target) {
  const auto scans = prepare(mesh, target);
  const int ch = target.channels;
  double sse = 0;
  for (std::size_t t = 0; t < scans.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    scan_triangle(scans[t].p, [&](int x, int y) {
      double l[3];
      barycentric(scans[t], x, y, l);
      for (int c = 0; c < ch; ++c) {
        const double value = l[0] * mesh.value(v[0], c) + l[1] * mesh.value(v[1], c) + l[2] * mesh.value(v[2], c);
        const double e = value - target.at(x, y, c);
        sse += e * e;
      }
    });
  }
  return sse;
}

LeastSquaresReport fit_least_squares(Mesh& mesh, const Planes& target, bool round_values) {
  const auto scans = prepare(mesh, target);
  const std::size_t n = mesh.vertex_count();
  const int ch = target.channels;

  // Sparsity: vertex v couples with itself and its edge neighbours.
  const VertexRows rows = vertex_rows(mesh);
  const auto& row = rows.row;
  const auto& col = rows.col;
  auto entry = [&](std::uint32_t i, std::uint32_t j) { return rows.entry(i, j); };
  std::vector<double> a(col.size(), 0.0), b(n * ch, 0.0);
  for (std::size_t t = 0; t < scans.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    std::size_t idx[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) idx[i][j] = entry(v[i], v[j]);
    scan_triangle(scans[t].p, [&](int x, int y) {
      double l[3];
      barycentric(scans[t], x, y, l);
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) a[idx[i][j]] += l[i] * l[j];
        for (int c = 0; c < ch; ++c) b[v[i] * ch + c] += l[i] * target.at(x, y, c);
      }
    });
  }

  LeastSquaresReport report;
  std::vector<double> x(n), r(n), z(n), p(n), q(n);
  for (int c = 0; c < ch; ++c) {
    double bnorm = 0;
    for (std::size_t v = 0; v < n; ++v) {
      x[v] = mesh.value(v, c);
      bnorm += b[v * ch + c] * b[v * ch + c];
    }
    bnorm = std::sqrt(bnorm);
    auto multiply = [&](const std::vector<double>& in, std::vector<double>& out) {
      for (std::size_t i = 0; i < n; ++i) {
        double s = 0;
        for (std::size_t k = row[i]; k < row[i + 1]; ++k) s += a[k] * in[col[k]];
        out[i] = s;
      }
    };
    multiply(x, q);
    double rz = 0, rnorm = 0;
    for (std::size_t i = 0; i < n; ++i) {
      r[i] = b[i * ch + c] - q[i];
      z[i] = r[i] / a[row[i]];
      p[i] = z[i];
      rz += r[i] * z[i];
    }
    int it = 0;
    constexpr int max_iterations = 2000;
    constexpr double tolerance = 1e-10;
    for (; it < max_iterations; ++it) {
      rnorm = 0;
      for (double ri : r) rnorm += ri * ri;
      if (bnorm == 0 || std::sqrt(rnorm) <= tolerance * bnorm) break;
      multiply(p, q);
      double pq = 0;
      for (std::size_t i = 0; i < n; ++i) pq += p[i] * q[i];
      const double alpha = rz / pq;
      double rz_next = 0;
      for (std::size_t i = 0; i < n; ++i) {
        x[i] += alpha * p[i];
        r[i] -= alpha * q[i];
        z[i] = r[i] / a[row[i]];
        rz_next += r[i] * z[i];
      }
      const double beta = rz_next / rz;
      rz = rz_next;
      for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
    }
    report.iterations = it;
    report.residual = std::max(report.residual, bnorm == 0 ? 0.0 : std::sqrt(rnorm) / bnorm);
    for (std::size_t v = 0; v < n; ++v)
      mesh.values[v * ch + c] = std::clamp(round_values ? std::round(x[v]) : x[v], 0.0, 255.0);
  }
  return report;
}

}  // namespace tristream::encoder
