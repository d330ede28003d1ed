// SPDX-License-Identifier: MIT
#include "reference/methods/bezier.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/methods/patch/raster.h"

namespace tristream {
namespace {

void splat_thesis(const BezierPatch& patch, int channels, detail::PatchCanvas& canvas) {
  std::vector<double> value(channels);
  const int steps = int(std::floor(1.0 / bezier_thesis_step + 1e-9));
  for (int ia = 0; ia <= steps; ++ia) {
    const double a = ia * bezier_thesis_step;
    for (int ib = 0;; ++ib) {
      const double b = ib * bezier_thesis_step;
      if (b > 1.0 - a + 1e-12) break;
      const Point p = patch.position(a, b);
      if (!(std::fabs(p.x) <= detail::max_patch_coordinate && std::fabs(p.y) <= detail::max_patch_coordinate)) continue;
      patch.values(a, b, value.data());
      canvas.add(int(std::floor(p.x + 0.5)), int(std::floor(p.y + 0.5)), value.data());
    }
  }
}

}  // namespace

BezierPatch::BezierPatch(const PatchControl& control) {
  value_.resize(std::size_t(control.channels));
  for (std::size_t d = 0; d < value_.size() + 2; ++d) {
    auto q = [&](int k) {
      if (d == 0) return control.pixel[k].x;
      if (d == 1) return control.pixel[k].y;
      return control.value[k * control.channels + int(d - 2)];
    };
    // The Bernstein form expanded in monomials of a and b (c = 1 - a - b).
    (d == 0 ? x_ : d == 1 ? y_ : value_[d - 2]) = {q(p002),
                     2 * (q(p101) - q(p002)),
                     2 * (q(p011) - q(p002)),
                     q(p200) + q(p002) - 2 * q(p101),
                     2 * (q(p002) + q(p110) - q(p011) - q(p101)),
                     q(p020) + q(p002) - 2 * q(p011)};
  }
  pos_[0] = XY{x_.k, y_.k}, pos_[1] = XY{x_.ks, y_.ks}, pos_[2] = XY{x_.kt, y_.kt};
  pos_[3] = XY{x_.kss, y_.kss}, pos_[4] = XY{x_.kst, y_.kst}, pos_[5] = XY{x_.ktt, y_.ktt};
}

bool BezierPatch::unfolded() const {
  // The determinant is quadratic: Bernstein coefficients from the corners and edge middles.
  const double d1 = detail::jacobian_determinant(*this, 1, 0), d2 = detail::jacobian_determinant(*this, 0, 1);
  const double d3 = detail::jacobian_determinant(*this, 0, 0);
  const double b[6] = {d1, d2, d3, 2 * detail::jacobian_determinant(*this, 0.5, 0.5) - (d1 + d2) / 2,
                       2 * detail::jacobian_determinant(*this, 0, 0.5) - (d2 + d3) / 2,
                       2 * detail::jacobian_determinant(*this, 0.5, 0) - (d1 + d3) / 2};
  constexpr bool corner[6] = {true, true, true, false, false, false};
  return detail::one_sign(b, 6, corner);
}

bool BezierPatch::exact_start(double x, double y, double a, double b) const {
  const Point p = position(a, b);
  return std::fabs(x - p.x) + std::fabs(y - p.y) < detail::exact_residual;
}

int BezierPatch::subdivisions() const {
  // In monomials: P200 - 2 P101 + P002 = kss, P020 - 2 P011 + P002 = ktt and
  // P200 - 2 P110 + P020 = kss - kst + ktt.
  auto norm = [](const XY& v) { return std::hypot(v[0], v[1]); };
  const double largest = std::max({norm(pos_[3]), norm(pos_[5]), norm(pos_[3] - pos_[4] + pos_[5])});
  return detail::subdivisions_for(2 * largest);
}

void render_bezier(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  // The patch lies in the convex hull of its control points: skip it when that misses the image.
  auto meets_image = [&out](const PatchControl& control) {
    double x0 = control.pixel[0].x, x1 = x0, y0 = control.pixel[0].y, y1 = y0;
    for (const Point& p : control.pixel) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    return !(x1 < -1 || y1 < -1 || x0 > out.width || y0 > out.height);
  };
  detail::render_patches<BezierPatch>("bezier", mesh, domain_width, domain_height, options, out, meets_image,
                                      splat_thesis, detail::rasterize_exact<BezierPatch>);
}

}  // namespace tristream
