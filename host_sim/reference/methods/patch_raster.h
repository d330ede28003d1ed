#pragma once
// Private to the patch methods (bezier, coons). Both build, for each triangle with three edge
// neighbours, a parametric surface (x, y, values)(s, t) and average every surface that lands
// on a pixel, in sum and count buffers (thesis §3.3, §4.2). Two ways to land on pixels:
//
// - thesis: step s and t by a fixed step, round each sample's position to the nearest pixel,
//   add it there; the bilinear pre-fill counts as one more sample in every pixel.
// - exact (the default): tessellate the patch into micro-triangles whose edges are at most
//   kMicroEdge pixels, rasterize them with exact integer edge tests and a top-left tie rule
//   (each pixel is covered once per layer of the surface, a fold gives more layers), and
//   evaluate the surface at the pixel itself: the micro-triangle gives the parameters by
//   linear interpolation and Newton's method on the patch's position makes them exact. So the
//   value is that of the surface point above the pixel's sample point; only the decision
//   whether a pixel near the patch boundary is inside follows the tessellation (the boundary
//   curve replaced by its chords). A pixel no patch covers keeps the bilinear value.
//
// Pixels outside the triangulation's domain (NaN in the bilinear field) are never written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "common/errors.h"
#include "reference/render.h"

namespace tristream::detail {

// True for variant "thesis", false for "" (the exact default); throws UsageError otherwise.
inline bool is_thesis_variant(std::string_view method, const std::string& variant) {
  if (variant == "thesis") return true;
  if (variant.empty()) return false;
  throw UsageError(std::string(method) + ": unknown variant '" + variant +
                   "' (expected 'thesis', or none for the exact default)");
}

// Sum and count buffers over the output pixels, restricted to the domain of `prefill`
// (the bilinear field: NaN outside the triangulation).
class PatchCanvas {
 public:
  explicit PatchCanvas(const Field& prefill);

  int width() const { return prefill_.width; }
  int height() const { return prefill_.height; }
  int channels() const { return prefill_.channels; }
  bool in_domain(int i, int j) const { return inside_[std::size_t(j) * prefill_.width + i] != 0; }

  // Adds one sample (channels() values) to pixel (i, j); ignored outside the image or domain.
  void add(int i, int j, const double* values) {
    if (i < 0 || j < 0 || i >= prefill_.width || j >= prefill_.height) return;
    const std::size_t p = std::size_t(j) * prefill_.width + i;
    if (!inside_[p]) return;
    ++count_[p];
    double* s = &sum_[p * prefill_.channels];
    for (int c = 0; c < prefill_.channels; ++c) s[c] += values[c];
  }

  std::uint32_t count(int i, int j) const { return count_[std::size_t(j) * prefill_.width + i]; }

  // thesis: (pre-fill + sum) / (count + 1) in every domain pixel (§4.2).
  void resolve_thesis(Field& out) const;
  // exact: sum / count where some patch landed, the pre-fill elsewhere in the domain.
  void resolve_exact(Field& out) const;

 private:
  const Field& prefill_;
  std::vector<std::uint8_t> inside_;
  std::vector<std::uint32_t> count_;
  std::vector<double> sum_;
};

// Coverage decisions use positions snapped to 1/256 output pixel. Bit budget: a patch is
// skipped unless every node is within +-2^20 pixels, so fixed-point coordinates are below
// 2^28, differences below 2^29 and the edge functions (products of two differences, summed)
// below 2^59: int64 is exact.
inline constexpr int kSubpixelBits = 8;
inline constexpr double kSubpixelScale = 1 << kSubpixelBits;
inline constexpr double kMaxPatchCoordinate = 1 << 20;
// Upper bound on a micro-triangle edge, in output pixels, along the grid directions.
inline constexpr double kMicroEdge = 1.0;
// Subdivisions per patch side are capped (a micro-edge may then exceed kMicroEdge; coverage
// stays exact for the coarser tessellation and values stay exact).
inline constexpr int kMaxSubdivisions = 2048;

// A tessellation node: snapped output position and the patch parameters there.
struct MicroVertex {
  std::int64_t x = 0;
  std::int64_t y = 0;
  double s = 0;
  double t = 0;
};

// False when (x, y) is outside +-kMaxPatchCoordinate (or NaN): the caller skips the patch.
inline bool snap(double x, double y, double s, double t, MicroVertex& out) {
  if (!(std::fabs(x) <= kMaxPatchCoordinate && std::fabs(y) <= kMaxPatchCoordinate)) return false;
  out = {std::llround(x * kSubpixelScale), std::llround(y * kSubpixelScale), s, t};
  return true;
}

// Twice the signed area of (p, q, r) in fixed point; r is strictly left of p->q in the
// orient2d sense when positive.
inline std::int64_t edge_function(const MicroVertex& p, const MicroVertex& q, std::int64_t rx, std::int64_t ry) {
  return (q.x - p.x) * (ry - p.y) - (q.y - p.y) * (rx - p.x);
}

// Tie rule of reference/coverage.h applied to a micro-triangle with positive area: edge
// p->q owns the points on it when it goes down, or is horizontal and goes left. A shared
// edge is seen in opposite directions by its two triangles, so exactly one owns it.
inline std::int64_t edge_bias(const MicroVertex& p, const MicroVertex& q) {
  return (q.y > p.y || (q.y == p.y && q.x < p.x)) ? 0 : 1;
}

// Calls visit(i, j, s, t) for every pixel (i, j) of the width x height image whose sample
// point the micro-triangle (a, b, c) covers, either winding; (s, t) are the parameters
// interpolated linearly. Degenerate triangles cover nothing.
template <class Visit>
void rasterize_micro_triangle(const MicroVertex& a, const MicroVertex& b, const MicroVertex& c, int width, int height,
                              Visit&& visit) {
  const MicroVertex* v0 = &a;
  const MicroVertex* v1 = &b;
  const MicroVertex* v2 = &c;
  std::int64_t area = edge_function(a, b, c.x, c.y);
  if (area == 0) return;
  if (area < 0) {
    std::swap(v1, v2);
    area = -area;
  }
  // Pixel sample points are the integers: column i at fixed-point i << kSubpixelBits.
  const std::int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const std::int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  const std::int64_t one = std::int64_t(1) << kSubpixelBits;
  const std::int64_t i0 = std::max<std::int64_t>(0, (min_x + one - 1) >> kSubpixelBits);
  const std::int64_t i1 = std::min<std::int64_t>(width - 1, max_x >> kSubpixelBits);
  const std::int64_t j0 = std::max<std::int64_t>(0, (min_y + one - 1) >> kSubpixelBits);
  const std::int64_t j1 = std::min<std::int64_t>(height - 1, max_y >> kSubpixelBits);
  if (i0 > i1 || j0 > j1) return;
  const std::int64_t bias0 = edge_bias(*v1, *v2), bias1 = edge_bias(*v2, *v0), bias2 = edge_bias(*v0, *v1);
  const double inv_area = 1.0 / double(area);
  for (std::int64_t j = j0; j <= j1; ++j)
    for (std::int64_t i = i0; i <= i1; ++i) {
      const std::int64_t px = i << kSubpixelBits, py = j << kSubpixelBits;
      const std::int64_t w0 = edge_function(*v1, *v2, px, py);
      const std::int64_t w1 = edge_function(*v2, *v0, px, py);
      const std::int64_t w2 = edge_function(*v0, *v1, px, py);
      if (w0 < bias0 || w1 < bias1 || w2 < bias2) continue;
      const double l0 = double(w0) * inv_area, l1 = double(w1) * inv_area, l2 = 1.0 - l0 - l1;
      visit(int(i), int(j), l0 * v0->s + l1 * v1->s + l2 * v2->s, l0 * v0->t + l1 * v1->t + l2 * v2->t);
    }
}

// Refines (s, t) so that patch.position(s, t) is the point (x, y), by Newton's method from a
// close start (the micro-triangle's linear guess). Keeps the start when the Jacobian is
// singular or a step would leave the neighbourhood of the start (near a fold).
// Patch provides position(s, t, x, y, dx_ds, dx_dt, dy_ds, dy_dt).
template <class Patch>
void refine_parameters(const Patch& patch, double x, double y, double& s, double& t) {
  double cs = s, ct = t;
  for (int iteration = 0; iteration < 6; ++iteration) {
    double px, py, xs, xt, ys, yt;
    patch.position(cs, ct, px, py, xs, xt, ys, yt);
    const double det = xs * yt - xt * ys;
    if (!(std::fabs(det) > 1e-300)) return;
    const double ex = x - px, ey = y - py;
    const double ds = (yt * ex - xt * ey) / det;
    const double dt = (xs * ey - ys * ex) / det;
    cs += ds;
    ct += dt;
    if (!(std::fabs(cs - s) + std::fabs(ct - t) < 0.25)) return;  // diverging: keep the guess
    if (std::fabs(ds) + std::fabs(dt) < 1e-14) break;
  }
  s = cs;
  t = ct;
}

}  // namespace tristream::detail
