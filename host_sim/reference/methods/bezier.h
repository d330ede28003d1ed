#pragma once
// Interpolation on the second-degree Bezier triangle patch of each triangle and its three
// edge neighbours (thesis §3.3, §4.2; NOTES.md §3.3), averaged where patches overlap.
//
// Variants (RenderOptions::variant):
// - "thesis": a and b stepped by kBezierThesisStep from 0 while a <= 1 and b <= 1 - a, each
//   sample rounded to the nearest pixel and added to sum and count buffers; the bilinear
//   pre-fill counts as one sample in every domain pixel.
// - "" (default): the same surfaces, every pixel of a patch taken once (tessellation into
//   micro-triangles plus per-pixel inversion of the patch mapping, methods/patch_raster.h);
//   the value is the mean of the patches over the pixel, or bilinear where no patch reaches.
// Border triangles (fewer than three neighbours) have no patch (§4.2); a mesh without
// interior triangles renders as bilinear. Pixels outside the domain stay NaN.
#include <vector>

#include "reference/methods/patch_control.h"
#include "reference/methods/patch_raster.h"
#include "reference/render.h"

namespace tristream {

inline constexpr double kBezierThesisStep = 0.006;

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
  // Solves position(a, b) = (x, y) by Newton's method from (a, b) near the solution. The map
  // is quadratic, so after a step d the residual is exactly -(k_aa d_a^2 + k_ab d_a d_b +
  // k_bb d_b^2) and the Jacobian grows by the Hessian times d: one evaluation, then cheap
  // steps, until a step is shorter than detail::kNewtonStep (patch_raster.h). Returns false,
  // leaving (a, b) alone, when the Jacobian is singular, the iteration moves 0.25 away or does
  // not settle in kNewtonIterations steps (beside a fold, see patch_raster.h).
  bool solve(double x, double y, double& a, double& b) const;
  // The closed parameter domain a, b, c >= 0, widened by detail::kDomainTolerance.
  static bool in_domain(double a, double b) {
    constexpr double e = detail::kDomainTolerance;
    return a >= -e && b >= -e && 1 - a - b >= -e;
  }
  // Subdivisions n per side for the exact variant (patch_raster.h): the second derivatives
  // along the three grid directions are 2 (P200 - 2 P101 + P002), 2 (P020 - 2 P011 + P002)
  // and 2 (P200 - 2 P110 + P020), constant, and each is also a boundary curve's.
  int subdivisions() const;
  // Tessellates the patch (subdivisions() per side, node (i, j) at a = i / n, b = j / n) and
  // calls visit(x, y, a, b) for every pixel of the width x height image that a micro-triangle
  // covers, with the micro-triangle's linear guess of its parameters (patch_raster.h).
  template <class Visit>
  void tessellate(int width, int height, std::vector<detail::MicroVertex>& node, Visit&& visit) const;

 private:
  using XY = detail::XY;
  detail::Quadratic2 x_, y_;                // position in (a, b)
  XY pos_[6];                               // x_ and y_ coefficients as pairs
  std::vector<detail::Quadratic2> value_;  // one per value channel
  double second_derivative_ = 0;               // largest of the three above
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
      detail::rasterize_micro_triangle(node[index(i, j)], node[index(i + 1, j)], node[index(i, j + 1)], width, height,
                                       visit);
      if (i + 1 < n - j)
        detail::rasterize_micro_triangle(node[index(i + 1, j)], node[index(i + 1, j + 1)], node[index(i, j + 1)], width,
                                         height, visit);
    }
}

void render_bezier(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out);

}  // namespace tristream
