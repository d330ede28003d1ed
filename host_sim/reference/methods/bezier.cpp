#include "reference/methods/bezier.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/topology.h"
#include "reference/coverage.h"
#include "reference/methods/bilinear.h"
#include "reference/methods/patch_raster.h"

namespace tristream {
namespace {

// Bernstein weights of P200, P020, P002, P110, P011, P101 at (a, b, 1 - a - b).
std::array<double, 6> weights(double a, double b) {
  const double c = 1.0 - a - b;
  return {a * a, b * b, c * c, 2 * a * b, 2 * b * c, 2 * a * c};
}

void splat_thesis(const BezierPatch& patch, int channels, detail::PatchCanvas& canvas) {
  std::vector<double> value(channels);
  const int steps = int(std::floor(1.0 / kBezierThesisStep + 1e-9));
  for (int ia = 0; ia <= steps; ++ia) {
    const double a = ia * kBezierThesisStep;
    for (int ib = 0;; ++ib) {
      const double b = ib * kBezierThesisStep;
      if (b > 1.0 - a + 1e-12) break;
      const Point p = patch.position(a, b);
      if (!(std::fabs(p.x) <= detail::kMaxPatchCoordinate && std::fabs(p.y) <= detail::kMaxPatchCoordinate)) continue;
      patch.values(a, b, value.data());
      canvas.add(int(std::floor(p.x + 0.5)), int(std::floor(p.y + 0.5)), value.data());
    }
  }
}

void rasterize_exact(const BezierPatch& patch, int channels, detail::PatchCanvas& canvas,
                     std::vector<detail::MicroVertex>& node) {
  const int n = std::min(patch.subdivisions(detail::kMicroEdge), detail::kMaxSubdivisions);
  // Node (i, j) has a = i / n, b = j / n; row j holds n + 1 - j nodes.
  auto index = [n](int i, int j) { return std::size_t(j) * (n + 1) - std::size_t(j) * (j - 1) / 2 + i; };
  node.resize(index(0, n) + 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n - j; ++i) {
      const double a = double(i) / n, b = double(j) / n;
      const Point p = patch.position(a, b);
      if (!detail::snap(p.x, p.y, a, b, node[index(i, j)])) return;  // absurd coordinates: no patch
    }
  std::vector<double> value(channels);
  auto visit = [&](int x, int y, double a, double b) {
    if (!canvas.in_domain(x, y)) return;
    detail::refine_parameters(patch, x, y, a, b);
    patch.values(a, b, value.data());
    canvas.add(x, y, value.data());
  };
  const int w = canvas.width(), h = canvas.height();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n - j; ++i) {
      detail::rasterize_micro_triangle(node[index(i, j)], node[index(i + 1, j)], node[index(i, j + 1)], w, h, visit);
      if (i + 1 < n - j)
        detail::rasterize_micro_triangle(node[index(i + 1, j)], node[index(i + 1, j + 1)], node[index(i, j + 1)], w,
                                         h, visit);
    }
}

}  // namespace

void BezierPatch::position(double a, double b, double& x, double& y, double& x_a, double& x_b, double& y_a,
                           double& y_b) const {
  const auto& p = control_.pixel;
  const double c = 1.0 - a - b;
  const auto wt = weights(a, b);
  x = y = 0;
  for (int k = 0; k < 6; ++k) {
    x += wt[k] * p[k].x;
    y += wt[k] * p[k].y;
  }
  // dP/da = 2[a (P200 - P101) + b (P110 - P011) + c (P101 - P002)], dP/db likewise.
  x_a = 2 * (a * (p[p200].x - p[p101].x) + b * (p[p110].x - p[p011].x) + c * (p[p101].x - p[p002].x));
  y_a = 2 * (a * (p[p200].y - p[p101].y) + b * (p[p110].y - p[p011].y) + c * (p[p101].y - p[p002].y));
  x_b = 2 * (a * (p[p110].x - p[p101].x) + b * (p[p020].x - p[p011].x) + c * (p[p011].x - p[p002].x));
  y_b = 2 * (a * (p[p110].y - p[p101].y) + b * (p[p020].y - p[p011].y) + c * (p[p011].y - p[p002].y));
}

Point BezierPatch::position(double a, double b) const {
  const auto wt = weights(a, b);
  Point r;
  for (int k = 0; k < 6; ++k) {
    r.x += wt[k] * control_.pixel[k].x;
    r.y += wt[k] * control_.pixel[k].y;
  }
  return r;
}

void BezierPatch::values(double a, double b, double* out) const {
  const auto wt = weights(a, b);
  const int nc = control_.channels;
  for (int c = 0; c < nc; ++c) {
    double v = 0;
    for (int k = 0; k < 6; ++k) v += wt[k] * control_.value[k * nc + c];
    out[c] = v;
  }
}

int BezierPatch::subdivisions(double max_edge) const {
  static constexpr int net[9][2] = {{p200, p110}, {p110, p020}, {p020, p011}, {p011, p002}, {p002, p101},
                                    {p101, p200}, {p110, p011}, {p011, p101}, {p101, p110}};
  double longest = 0;
  for (const auto& e : net)
    longest = std::max(longest, std::hypot(control_.pixel[e[0]].x - control_.pixel[e[1]].x,
                                           control_.pixel[e[0]].y - control_.pixel[e[1]].y));
  const double n = std::ceil(2 * longest / max_edge);
  return n < 1 ? 1 : n > detail::kMaxSubdivisions ? detail::kMaxSubdivisions : int(n);
}

void render_bezier(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  const bool thesis = detail::is_thesis_variant("bezier", options.variant);
  const Topology topo = build_topology(mesh);
  const PixelMapping map(domain_width, domain_height, out.width, out.height);
  Field prefill(out.width, out.height, out.channels);
  render_bilinear(mesh, domain_width, domain_height, options, prefill);
  detail::PatchCanvas canvas(prefill);

  PatchControl control;
  std::vector<detail::MicroVertex> nodes;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!patch_control(mesh, topo, t, map, control)) continue;
    // The patch lies in the convex hull of its control points: skip it when that misses the image.
    double x0 = control.pixel[0].x, x1 = x0, y0 = control.pixel[0].y, y1 = y0;
    for (const Point& p : control.pixel) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    if (x1 < -1 || y1 < -1 || x0 > out.width || y0 > out.height) continue;
    const BezierPatch patch(control);
    if (thesis)
      splat_thesis(patch, control.channels, canvas);
    else
      rasterize_exact(patch, control.channels, canvas, nodes);
  }
  if (thesis)
    canvas.resolve_thesis(out);
  else
    canvas.resolve_exact(out);
}

}  // namespace tristream
