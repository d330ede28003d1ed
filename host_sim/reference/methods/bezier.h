/* SPDX-License-Identifier: MIT */
#pragma once
// Interpolation on the second-degree Bezier triangle patch of each triangle and its three
// edge neighbours (thesis §3.3, §4.2; docs/CONVENTIONS.md), averaged where patches overlap.
//
// Variants (RenderOptions::variant):
// - "thesis": a and b stepped by bezier_thesis_step from 0 while a <= 1 and b <= 1 - a, each
//   sample rounded to the nearest pixel and added to sum and count buffers; the bilinear
//   pre-fill counts as one sample in every domain pixel.
// - "" (default): the same surfaces, every pixel of a patch taken once (tessellation into
//   micro-triangles plus per-pixel inversion of the patch mapping, methods/patch/raster.h);
//   the value is the mean of the patches over the pixel, or bilinear where no patch reaches.
// Border triangles (fewer than three neighbours) have no patch (§4.2); a mesh without
// interior triangles renders as bilinear. Pixels outside the domain stay NaN.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "reference/methods/patch/control.h"
#include "reference/methods/patch/raster.h"
#include "reference/render.h"

namespace tristream {

inline constexpr double bezier_thesis_step = 0.006;

// P(a, b, c) = a^2 P200 + b^2 P020 + c^2 P002 + 2ab P110 + 2bc P011 + 2ac P101 with
// c = 1 - a - b, for position (output pixels) and every value channel.
class BezierPatch {
 public:
  explicit BezierPatch(const PatchControl& control);

  // Position and its partial derivatives with respect to a and b (c = 1 - a - b).
  void position(double a, double b, double& x, double& y, double& x_a, double& x_b, double& y_a,
                double& y_b) const {
    const XY& k = pos_[0];
    const XY& ks = pos_[1];
    const XY& kt = pos_[2];
    const XY& kss = pos_[3];
    const XY& kst = pos_[4];
    const XY& ktt = pos_[5];
    const XY p = k + a * (ks + a * kss + b * kst) + b * (kt + b * ktt);
    const XY pa = ks + 2 * a * kss + b * kst;
    const XY pb = kt + a * kst + 2 * b * ktt;
    x = p[0], y = p[1], x_a = pa[0], x_b = pb[0], y_a = pa[1], y_b = pb[1];
  }
  Point position(double a, double b) const { return {x_(a, b), y_(a, b)}; }
  // control.channels values at (a, b).
  void values(double a, double b, double* out) const {
    const detail::Quadratic2* q = value_.data();
    for (std::size_t c = 0, n = value_.size(); c < n; ++c) out[c] = q[c](a, b);
  }
  // The same added to sum[0..channels).
  void add_values(double a, double b, double* sum) const {
    const detail::Quadratic2* q = value_.data();
    for (std::size_t c = 0, n = value_.size(); c < n; ++c) sum[c] += q[c](a, b);
  }
  // Solves position(a, b) = (x, y) by Newton's method from (a, b) near the solution. The map
  // is quadratic, so after a step d the residual is exactly -(k_aa d_a^2 + k_ab d_a d_b +
  // k_bb d_b^2) and the Jacobian grows by the Hessian times d: one evaluation, then cheap
  // steps, until a step is shorter than detail::newton_step (patch/raster.h). Returns false,
  // leaving (a, b) alone, when the Jacobian is singular (unless the start already solves the
  // equation to detail::exact_residual: then true), the solution lies detail::newton_reach
  // or more from the start, or Newton does not settle in newton_iterations steps (beside a
  // fold, see patch/raster.h).
  bool solve(double x, double y, double& a, double& b) const;
  // The closed parameter domain a, b, c >= 0, widened by detail::domain_tolerance.
  static bool in_domain(double a, double b) {
    constexpr double e = detail::domain_tolerance;
    return a >= -e && b >= -e && 1 - a - b >= -e;
  }
  // How far (a, b) lies outside the domain (the largest violated constraint; <= 0 inside).
  static double outside_by(double a, double b) { return std::max({-a, -b, a + b - 1}); }
  // A point inside the domain.
  static std::pair<double, double> centre() { return {1.0 / 3, 1.0 / 3}; }
  // The sides of the parameter domain for the exact variant's rows (patch/scan.h): side k
  // (b = 0, a = 0, c = 0) at f in [0, 1] has parameters side(k, f).
  static constexpr int side_count = 3;
  static std::pair<double, double> side(int k, double f) {
    return k == 0 ? std::pair{f, 0.0} : k == 1 ? std::pair{0.0, f} : std::pair{f, 1 - f};
  }
  // True when the Jacobian determinant provably keeps one sign over the domain (patch/scan.h).
  bool unfolded() const;
  // For the exact variant (patch/raster.h): true, with no cells, when unfolded(); false
  // otherwise (the patch takes the tessellation).
  bool fold_cells(std::vector<detail::FoldCell>& cells) const {
    cells.clear();
    return unfolded();
  }
  // Subdivisions n per side for the exact variant (patch/raster.h): the second derivatives
  // along the three grid directions are 2 (P200 - 2 P101 + P002), 2 (P020 - 2 P011 + P002)
  // and 2 (P200 - 2 P110 + P020), constant.
  int subdivisions() const;
  // Tessellates the patch (subdivisions() per side, node (i, j) at a = i / n, b = j / n) and
  // calls visit(x, y, a, b) for every pixel of the width x height image that a micro-triangle
  // covers, with the micro-triangle's linear guess of its parameters, then for the pixels
  // near each boundary arc beyond its chord (detail::visit_boundary_side), guessed from the
  // chord, and for the pixel nearest a side's cusp, started on it (both
  // detail::visit_boundary_side): the candidates of patch/raster.h, every pixel of the patch
  // among them, some more than once.
  template <class Visit>
  void tessellate(int width, int height, std::vector<detail::MicroVertex>& node, Visit&& visit) const;

 private:
  using XY = detail::XY;
  // Whether (a, b) solves position(a, b) = (x, y) to detail::exact_residual (solve's last resort).
  bool exact_start(double x, double y, double a, double b) const;
  detail::Quadratic2 x_, y_;                // position in (a, b)
  XY pos_[6];                               // x_ and y_ coefficients as pairs
  std::vector<detail::Quadratic2> value_;  // one per value channel
};

template <class Visit>
void BezierPatch::tessellate(int width, int height, std::vector<detail::MicroVertex>& node, Visit&& visit) const {
  const int n = subdivisions();
  // Node (i, j) has a = i / n, b = j / n; row j holds n + 1 - j nodes.
  auto index = [n](int i, int j) { return std::size_t(j) * (n + 1) - std::size_t(j) * (j - 1) / 2 + i; };
  node.resize(index(0, n) + 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n - j; ++i) {
      const double a = double(i) / n, b = double(j) / n;
      const Point p = position(a, b);
      if (!detail::snap(p.x, p.y, a, b, node[index(i, j)])) return;  // absurd coordinates: no patch
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n - j; ++i) {
      // Its edges on the domain's boundary own their points: a pixel on a chord gets this guess.
      const unsigned boundary = (j == 0 ? 1u : 0u) | (i + 1 + j == n ? 2u : 0u) | (i == 0 ? 4u : 0u);
      detail::rasterize_micro_triangle(node[index(i, j)], node[index(i + 1, j)], node[index(i, j + 1)], width, height,
                                       visit, boundary);
      if (i + 1 < n - j)
        detail::rasterize_micro_triangle(node[index(i + 1, j)], node[index(i + 1, j + 1)], node[index(i, j + 1)], width,
                                         height, visit);
    }
  std::array<detail::BoundaryArc, side_count> arcs;
  if (!detail::side_arcs(*this, arcs)) return;
  for (int k = 0; k < side_count; ++k)
    detail::visit_boundary_side(*this, n, k, arcs[std::size_t(k)], width, height, visit);
}

inline bool BezierPatch::solve(double x, double y, double& a, double& b) const {
  const XY& kaa = pos_[3];
  const XY& kab = pos_[4];
  const XY& kbb = pos_[5];
  double px, py, xa, xb, ya, yb;
  position(a, b, px, py, xa, xb, ya, yb);
  XY r{x - px, y - py};
  XY ja{xa, ya}, jb{xb, yb};  // columns of the Jacobian
  double ca = a, cb = b;
  for (int iteration = 0; iteration < detail::newton_iterations; ++iteration) {
    // A singular Jacobian gives infinite or NaN steps, which never pass the test below.
    const double inverse = 1 / (ja[0] * jb[1] - jb[0] * ja[1]);
    const double da = (jb[1] * r[0] - jb[0] * r[1]) * inverse;
    const double db = (ja[0] * r[1] - ja[1] * r[0]) * inverse;
    ca += da, cb += db;
    if (std::fabs(da) + std::fabs(db) < detail::newton_step) {
      // Far from the start is another solution than the one sought (beside a fold).
      if (!(std::fabs(ca - a) + std::fabs(cb - b) < detail::newton_reach)) return false;
      a = ca, b = cb;
      return true;
    }
    r = -(kaa * (da * da) + kab * (da * db) + kbb * (db * db));
    ja += 2 * da * kaa + db * kab;
    jb += da * kab + 2 * db * kbb;
  }
  // Where the Jacobian is singular (a side's cusp, see detail::visit_boundary_side) Newton
  // cannot step, not even from the solution itself (elsewhere such a start converges at
  // once): a start that already solves the equation stays as it is, as in CoonsPatch::solve.
  return exact_start(x, y, a, b);
}

void render_bezier(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out);

}  // namespace tristream
