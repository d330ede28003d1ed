#include "reference/methods/coons.h"

#include <algorithm>
#include <cmath>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/methods/patch_raster.h"

namespace tristream {
namespace {

// Corner control points (P200, P020, P002 = 0, 1, 2) joined by each boundary curve, and the
// middle point of the curve joining two corners.
constexpr int curve_end[3][2] = {{p200, p020}, {p020, p002}, {p200, p002}};
int middle_of(int p, int q) {
  const int lo = std::min(p, q), hi = std::max(p, q);
  return lo == p200 ? (hi == p020 ? p110 : p101) : p011;
}

double length(const Point& p, const Point& q) { return std::hypot(p.x - q.x, p.y - q.y); }

void splat_thesis(const CoonsPatch& patch, int channels, detail::PatchCanvas& canvas) {
  std::vector<double> value(channels);
  const int steps = int(std::floor(1.0 / kCoonsThesisStep + 1e-9));
  for (int iu = 0; iu <= steps; ++iu) {
    const double u = iu * kCoonsThesisStep;
    for (int iv = 0; iv <= steps; ++iv) {
      const double v = iv * kCoonsThesisStep;
      const Point p = patch.position(u, v);
      if (!(std::fabs(p.x) <= detail::kMaxPatchCoordinate && std::fabs(p.y) <= detail::kMaxPatchCoordinate)) continue;
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

std::array<double, 3> CoonsPatch::second_derivatives() const {
  // P_uu = 2 kuu + 2 v kuuv, P_vv = 2 kvv + 2 u kuvv and P_uv = kuv + 2 u kuuv + 2 v kuvv are
  // affine, so their largest norms over the square are at its corners.
  // Largest squared norms first, one square root each (hypot per corner cost more than the rest).
  auto norm2 = [](double x, double y) { return x * x + y * y; };
  double kuu = 0, kvv = 0, kuv = 0;
  for (double v : {0.0, 1.0}) kuu = std::max(kuu, norm2(2 * (x_.kuu + v * x_.kuuv), 2 * (y_.kuu + v * y_.kuuv)));
  for (double u : {0.0, 1.0}) kvv = std::max(kvv, norm2(2 * (x_.kvv + u * x_.kuvv), 2 * (y_.kvv + u * y_.kuvv)));
  for (double u : {0.0, 1.0})
    for (double v : {0.0, 1.0})
      kuv = std::max(kuv, norm2(x_.kuv + 2 * u * x_.kuuv + 2 * v * x_.kuvv, y_.kuv + 2 * u * y_.kuuv + 2 * v * y_.kuvv));
  return {std::sqrt(kuu), std::sqrt(kvv), std::sqrt(kuv)};
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
  if (std::fabs(r[0]) + std::fabs(r[1]) < detail::kExactResidual) return true;
  for (int iteration = 0; iteration < detail::kNewtonIterations; ++iteration) {
    const double det = pu[0] * pv[1] - pv[0] * pu[1];
    if (!(std::fabs(det) > 1e-300)) return false;
    const double inverse = 1 / det;
    const double du = (pv[1] * r[0] - pv[0] * r[1]) * inverse, dv = (pu[0] * r[1] - pu[1] * r[0]) * inverse;
    cu += du, cv += dv;
    if (!(std::fabs(cu - u) + std::fabs(cv - v) < detail::kNewtonReach)) return false;
    if (std::fabs(du) + std::fabs(dv) < detail::kNewtonStep) {
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
  // Bernstein coefficients on the whole square: the determinant (degree 3 in u and in v)
  // from its values on the grid of thirds, the position (degree 2) from the grid of halves,
  // each converted along u, then along v.
  detail::TensorCell cell;
  double f[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) f[i][j] = detail::jacobian_determinant(*this, i / 3.0, j / 3.0);
  for (int j = 0; j < 4; ++j) {
    const double column[4] = {f[0][j], f[1][j], f[2][j], f[3][j]};
    double converted[4];
    detail::cubic_bernstein(column, converted);
    for (int i = 0; i < 4; ++i) f[i][j] = converted[i];
  }
  for (int i = 0; i < 4; ++i) detail::cubic_bernstein(f[i], cell.det[i]);
  double px[3][3], py[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Point p = position(i / 2.0, j / 2.0);
      px[i][j] = p.x, py[i][j] = p.y;
    }
  auto quadratic_bernstein = [](double f0, double f1, double f2, double* b, int stride) {
    b[0] = f0, b[stride] = 2 * f1 - (f0 + f2) / 2, b[2 * stride] = f2;
  };
  for (double (*grid)[3] : {px, py}) {
    for (int j = 0; j < 3; ++j) {
      double column[3];
      quadratic_bernstein(grid[0][j], grid[1][j], grid[2][j], column, 1);
      for (int i = 0; i < 3; ++i) grid[i][j] = column[i];
    }
  }
  for (int i = 0; i < 3; ++i) {
    quadratic_bernstein(px[i][0], px[i][1], px[i][2], cell.x[i], 1);
    quadratic_bernstein(py[i][0], py[i][1], py[i][2], cell.y[i], 1);
  }
  detail::find_fold_cells(cell, 0, [this](double u, double v) { return position(u, v); }, cells);
  return true;
}

std::array<int, 2> CoonsPatch::subdivisions() const {
  const auto [kuu, kvv, kuv] = second_derivatives();
  return {detail::subdivisions_for(2 * (kuu + kuv)), detail::subdivisions_for(2 * (kvv + kuv))};
}

void render_coons(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  detail::render_patches<CoonsPatch>(
      "coons", mesh, domain_width, domain_height, options, out, [](const PatchControl&) { return true; },
      splat_thesis, detail::rasterize_exact<CoonsPatch>);
}

}  // namespace tristream
