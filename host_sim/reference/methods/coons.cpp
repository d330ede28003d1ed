// SPDX-License-Identifier: MIT
#include "reference/methods/coons.h"

#include <algorithm>
#include <cmath>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/methods/patch/raster.h"

namespace tristream {
namespace {

// Corner control points (P200, P020, P002 = 0, 1, 2) joined by each boundary curve, and the
// middle point of the curve joining two corners.
constexpr int curve_end[3][2] = {{p200, p020}, {p020, p002}, {p200, p002}};
int middle_of(int p, int q) {
  const int lo = std::min(p, q), hi = std::max(p, q);
  return lo == p200 ? (hi == p020 ? p110 : p101) : p011;
}

// sqrt of the exact sum for integer coordinates: equal lengths stay equal (ties pick the first).
double length(const Point& p, const Point& q) {
  const double dx = p.x - q.x, dy = p.y - q.y;
  return std::sqrt(dx * dx + dy * dy);
}

void splat_thesis(const CoonsPatch& patch, int channels, detail::PatchCanvas& canvas) {
  std::vector<double> value(channels);
  const int steps = int(std::floor(1.0 / coons_thesis_step + 1e-9));
  for (int iu = 0; iu <= steps; ++iu) {
    const double u = iu * coons_thesis_step;
    for (int iv = 0; iv <= steps; ++iv) {
      const double v = iv * coons_thesis_step;
      const Point p = patch.position(u, v);
      if (!(std::fabs(p.x) <= detail::max_patch_coordinate && std::fabs(p.y) <= detail::max_patch_coordinate)) continue;
      patch.values(u, v, value.data());
      canvas.add(int(std::floor(p.x + 0.5)), int(std::floor(p.y + 0.5)), value.data());
    }
  }
}

}  // namespace

CoonsPatch::CoonsPatch(const PatchControl& control) {
  double best = -1;
  for (int k = 0; k < 3; ++k) {
    const Point& s = control.domain[curve_end[k][0]];
    const Point& e = control.domain[curve_end[k][1]];
    const Point& m = control.domain[middle_of(curve_end[k][0], curve_end[k][1])];
    const double l = length(s, m) + length(m, e);
    if (l > best) best = l, longest_ = k;
  }
  const int a = curve_end[longest_][0], b = curve_end[longest_][1];
  const int c = 3 - a - b;  // the corner the longest curve misses (corners are 0, 1, 2)
  const int m = middle_of(a, b), m_ac = middle_of(a, c), m_bc = middle_of(c, b);
  corner_ = {a, m, b, c};

  value_.resize(std::size_t(control.channels));
  for (std::size_t d = 0; d < value_.size() + 2; ++d) {
    auto x = [&](int k) {
      if (d == 0) return control.pixel[k].x;
      if (d == 1) return control.pixel[k].y;
      return control.value[k * control.channels + int(d - 2)];
    };
    Component& q = d == 0 ? x_ : d == 1 ? y_ : value_[d - 2];
    const Parabola split = Parabola::through(x(a), x(m), x(b));
    q.A = x(a), q.M = x(m), q.B = x(b), q.C = x(c);
    q.b1 = Parabola::through(q.A, split(0.25), q.M);
    q.a2 = Parabola::through(q.M, split(0.75), q.B);
    q.a1 = Parabola::through(q.A, x(m_ac), q.C);
    q.b2 = Parabola::through(q.C, x(m_bc), q.B);
    q.expand();
  }
  const double Component::*coefficient[8] = {&Component::k,   &Component::ku,  &Component::kv,   &Component::kuv,
                                              &Component::kuu, &Component::kvv, &Component::kuuv, &Component::kuvv};
  for (int i = 0; i < 8; ++i) pos_[i] = XY{x_.*coefficient[i], y_.*coefficient[i]};
}


bool CoonsPatch::solve(double x, double y, double& u, double& v) const {
  const XY target{x, y};
  double cu = u, cv = v;
  XY p, pu, pv;
  position(cu, cv, p, pu, pv);
  XY r = target - p;
  // A start that is already the solution (a pixel on a tessellation node, such as a patch
  // corner) stays: at the corner M the Jacobian is singular (the split curve runs straight
  // through it), where a step would only add noise.
  if (std::fabs(r[0]) + std::fabs(r[1]) < detail::exact_residual) return true;
  for (int iteration = 0; iteration < detail::newton_iterations; ++iteration) {
    // A singular Jacobian gives infinite or NaN steps, which fail the reach test below.
    const double inverse = 1 / (pu[0] * pv[1] - pv[0] * pu[1]);
    const double du = (pv[1] * r[0] - pv[0] * r[1]) * inverse, dv = (pu[0] * r[1] - pu[1] * r[0]) * inverse;
    cu += du, cv += dv;
    if (!(std::fabs(cu - u) + std::fabs(cv - v) < detail::newton_reach)) return false;
    if (std::fabs(du) + std::fabs(dv) < detail::newton_step) {
      u = cu, v = cv;
      return true;
    }
    position(cu, cv, p, pu, pv);
    r = target - p;
  }
  return false;
}

void CoonsPatch::Component::expand() {
  // (1-u) a1(v) + u a2(v) + (1-v) b1(u) + v b2(u) - [(1-u)(1-v) A + u(1-v) M + (1-u) v C + u v B]
  k = a1.c + b1.c - A;
  ku = a2.c - a1.c + b1.b + A - M;
  kv = a1.b + b2.c - b1.c + A - C;
  kuv = a2.b - a1.b + b2.b - b1.b - A + M + C - B;
  kuu = b1.a;
  kvv = a1.a;
  kuuv = b2.a - b1.a;
  kuvv = a2.a - a1.a;
}

bool CoonsPatch::fold_cells(std::vector<detail::FoldCell>& cells) const {
  cells.clear();
  // Monomial coefficients m[i][j] of u^i v^j: the position's (degree 2 in each), its
  // partial derivatives', and the Jacobian determinant's (degree 3 in each).
  auto monomials = [](const Component& c, double (&m)[3][3]) {
    m[0][0] = c.k, m[1][0] = c.ku, m[0][1] = c.kv, m[1][1] = c.kuv, m[2][0] = c.kuu, m[0][2] = c.kvv;
    m[2][1] = c.kuuv, m[1][2] = c.kuvv, m[2][2] = 0;
  };
  double mx[3][3], my[3][3];
  monomials(x_, mx), monomials(y_, my);
  auto d_u = [](const double (&m)[3][3], double (&d)[3][3]) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) d[i][j] = i < 2 ? (i + 1) * m[i + 1][j] : 0;
  };
  auto d_v = [](const double (&m)[3][3], double (&d)[3][3]) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) d[i][j] = j < 2 ? (j + 1) * m[i][j + 1] : 0;
  };
  double xu[3][3], xv[3][3], yu[3][3], yv[3][3];
  d_u(mx, xu), d_v(mx, xv), d_u(my, yu), d_v(my, yv);
  // x_u y_v - x_v y_u: x_u and y_u have degree (1, 2), x_v and y_v degree (2, 1).
  double det[4][4] = {};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 2; ++l) det[i + k][j + l] += xu[i][j] * yv[k][l] - yu[i][j] * xv[k][l];
  // Monomials to Bernstein coefficients on [0, 1] along each index: b_i = sum over k <= i
  // of C(i, k) / C(n, k) m_k.
  auto to_bernstein = [](const double* m, int n, int stride, double* b) {
    static constexpr double binomial[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    double out[4];
    for (int i = 0; i <= n; ++i) {
      out[i] = 0;
      for (int k = 0; k <= i; ++k) out[i] += binomial[i][k] / binomial[n][k] * m[k * stride];
    }
    for (int i = 0; i <= n; ++i) b[i * stride] = out[i];
  };
  detail::TensorCell cell;
  for (int j = 0; j < 4; ++j) to_bernstein(&det[0][j], 3, 4, &det[0][j]);
  for (int i = 0; i < 4; ++i) to_bernstein(det[i], 3, 1, cell.det[i]);
  for (int j = 0; j < 3; ++j) to_bernstein(&mx[0][j], 2, 3, &mx[0][j]), to_bernstein(&my[0][j], 2, 3, &my[0][j]);
  for (int i = 0; i < 3; ++i) to_bernstein(mx[i], 2, 1, cell.x[i]), to_bernstein(my[i], 2, 1, cell.y[i]);
  detail::find_fold_cells(cell, 0, [this](double u, double v) { return position(u, v); }, cells);
  return true;
}

void render_coons(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  detail::render_patches<CoonsPatch>(
      "coons", mesh, domain_width, domain_height, options, out, [](const PatchControl&) { return true; },
      splat_thesis, detail::rasterize_exact<CoonsPatch>);
}

}  // namespace tristream
