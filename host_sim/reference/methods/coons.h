/* SPDX-License-Identifier: MIT */
#pragma once
// Interpolation on the Coons patch of each triangle and its three edge neighbours (thesis
// §3.4, §4.2; docs/CONVENTIONS.md), averaged where patches overlap.
//
// Construction (the thesis leaves the orientation of the split open; this is the choice):
// the three parabolic boundary curves through (P200, P110, P020), (P020, P011, P002) and
// (P200, P101, P002), each curve(t) = a t^2 + b t + c through its ends at t = 0, 1 and its
// middle point at t = 1/2 (Eq. 3.8). The longest in the triangulation's units
// (|start - middle| + |middle - end|, first of equals in that order) is (A, M, B); C is the
// remaining corner. It is split at its middle M: the half A..M is the parabola through
// (A, T0.25, M) and the half M..B the one through (M, T0.75, B), with Tx = curve(x). These
// halves are exactly the two halves of the original curve (the thesis's text pairs T0.75 with
// A..M, which would bend the boundary back across M). With the other two curves A..C and
// C..B, the four boundaries form the quadrilateral A, M, B, C and
//   P(u, v) = (1-u) a1(v) + u a2(v) + (1-v) b1(u) + v b2(u)
//             - (1-u)(1-v) A - u(1-v) M - (1-u) v C - u v B            (Eq. 3.10)
// with b1 = A..M and b2 = C..B along u, a1 = A..C and a2 = M..B along v: the bilinearly
// blended Coons patch of these four boundaries, so P(u, 0) = b1(u), P(0, v) = a1(v) and so
// on. (Eq. 3.10's corner terms put M at (u, v) = (0, 1), which fits the layout of Eq. 3.9 but
// not the curve list of Eq. 3.11; renaming u and v gives the same surface.) It applies to x,
// y and every value channel alike.
//
// Variants as in bezier.h: "thesis" steps u and v by coons_thesis_step over [0, 1] and splats;
// the default rasterizes each patch exactly (methods/patch/raster.h).
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "reference/methods/patch/control.h"
#include "reference/methods/patch/raster.h"
#include "reference/render.h"

namespace tristream {

inline constexpr double coons_thesis_step = 0.007;

class CoonsPatch {
 public:
  explicit CoonsPatch(const PatchControl& control);

  // The split curve: 0 = (P200, P110, P020), 1 = (P020, P011, P002), 2 = (P200, P101, P002).
  int longest_curve() const { return longest_; }
  // Control-point indices (PatchPoint) of the corners A, M, B, C.
  std::array<int, 4> corners() const { return corner_; }

  // Position (output pixels) and its partial derivatives with respect to u and v.
  void position(double u, double v, double& x, double& y, double& x_u, double& x_v, double& y_u,
                double& y_v) const {
    detail::XY p, pu, pv;
    position(u, v, p, pu, pv);
    x = p[0], y = p[1], x_u = pu[0], x_v = pv[0], y_u = pu[1], y_v = pv[1];
  }
  // The same as (x, y) pairs.
  void position(double u, double v, detail::XY& p, detail::XY& pu, detail::XY& pv) const {
    const detail::XY* k = pos_;  // k, ku, kv, kuv, kuu, kvv, kuuv, kuvv
    // Horner in u over coefficients that are polynomials in v: P = c0 + u (c1 + u c2).
    const detail::XY c0 = k[0] + v * (k[2] + v * k[5]);
    const detail::XY c1 = k[1] + v * (k[3] + v * k[7]);
    const detail::XY c2 = k[4] + v * k[6];
    p = c0 + u * (c1 + u * c2);
    pu = c1 + 2 * u * c2;
    pv = (k[2] + 2 * v * k[5]) + u * ((k[3] + 2 * v * k[7]) + u * k[6]);
  }
  Point position(double u, double v) const { return {x_.at(u, v), y_.at(u, v)}; }
  // control.channels values at (u, v).
  void values(double u, double v, double* out) const {
    const Component* q = value_.data();
    for (std::size_t c = 0, n = value_.size(); c < n; ++c) out[c] = q[c].at(u, v);
  }
  // The same added to sum[0..channels).
  void add_values(double u, double v, double* sum) const {
    const Component* q = value_.data();
    for (std::size_t c = 0, n = value_.size(); c < n; ++c) sum[c] += q[c].at(u, v);
  }
  // Solves position(u, v) = (x, y) by Newton's method from (u, v) near the solution, until a
  // step is shorter than detail::newton_step (patch/raster.h). Returns false, leaving (u, v)
  // alone, when the Jacobian is singular, the iteration moves detail::newton_reach away or does not settle in
  // newton_iterations steps (beside a fold, see patch/raster.h).
  bool solve(double x, double y, double& u, double& v) const;
  // The closed parameter domain [0, 1]^2, widened by detail::domain_tolerance.
  static bool in_domain(double u, double v) {
    constexpr double e = detail::domain_tolerance;
    return u >= -e && v >= -e && u <= 1 + e && v <= 1 + e;
  }
  // How far (u, v) lies outside the domain (the largest violated constraint; <= 0 inside).
  static double outside_by(double u, double v) { return std::max({-u, -v, u - 1, v - 1}); }
  // A point inside the domain.
  static std::pair<double, double> centre() { return {0.5, 0.5}; }
  // The sides of the parameter domain for the exact variant's rows (patch/scan.h): side k
  // (v = 0, v = 1, u = 0, u = 1) at f in [0, 1] has parameters side(k, f).
  static constexpr int side_count = 4;
  static std::pair<double, double> side(int k, double f) {
    return k < 2 ? std::pair{f, double(k)} : std::pair{double(k - 2), f};
  }
  // For the exact variant (patch/raster.h): the squares of the domain, down to an eighth of
  // its side, where the Jacobian determinant may vanish, with boxes holding their images
  // (detail::find_fold_cells); none when the patch provably does not fold. Always true.
  bool fold_cells(std::vector<detail::FoldCell>& cells) const;

 private:
  // One coordinate (x, y or a value channel) of the patch: its corners and curves, and the
  // same surface in monomials 1, u, v, uv, u^2, v^2, u^2 v, u v^2.
  struct Component {
    double A = 0, M = 0, B = 0, C = 0;
    Parabola a1, a2, b1, b2;
    double k = 0, ku = 0, kv = 0, kuv = 0, kuu = 0, kvv = 0, kuuv = 0, kuvv = 0;

    void expand();
    double at(double u, double v) const {
      return k + u * (ku + u * kuu) + v * (kv + v * kvv) + u * v * (kuv + u * kuuv + v * kuvv);
    }
    void evaluate(double u, double v, double& value, double& d_u, double& d_v) const {
      const double uu = u * u, vv = v * v, uv = u * v;
      value = k + u * ku + v * kv + uv * kuv + uu * kuu + vv * kvv + uu * v * kuuv + u * vv * kuvv;
      d_u = ku + v * kuv + 2 * u * kuu + 2 * uv * kuuv + vv * kuvv;
      d_v = kv + u * kuv + 2 * v * kvv + uu * kuuv + 2 * uv * kuvv;
    }
  };
  int longest_ = 0;
  std::array<int, 4> corner_{};
  using XY = detail::XY;
  Component x_, y_;                // position
  XY pos_[8];                      // x_ and y_ monomial coefficients as pairs
  std::vector<Component> value_;  // one per value channel
};

void render_coons(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out);

}  // namespace tristream
