#pragma once
// Private to the patch methods (bezier, coons). Both build, for each triangle with three edge
// neighbours, a parametric surface (x, y, values)(s, t) and average every surface that lands
// on a pixel, in sum and count buffers (thesis §3.3, §4.2). Two ways to land on pixels:
//
// - thesis: step s and t by a fixed step, round each sample's position to the nearest pixel
//   (pixel (i, j) samples the point (i, j), so its cell is centred there; the thesis's integer
//   truncation assumed pixels at their corners), add it there unless it is off the image or
//   outside the domain; the bilinear pre-fill counts as one more sample in every pixel.
// - exact (the default): tessellate the patch's parameter domain uniformly, rasterize the
//   micro-triangles with exact integer edge tests and a top-left tie rule (each pixel is
//   covered once per layer of the surface; a fold gives more layers), and evaluate the
//   surface at the pixel itself: the micro-triangle gives the parameters by linear
//   interpolation, Newton's method on the patch's position makes them exact. So a pixel's
//   value is that of the surface point above its sample point. A pixel whose parameters fall
//   outside the patch's closed parameter domain, or which Newton cannot place (beside a fold
//   of the patch, where the tessellation's fold line is off), is not counted; so the
//   tessellation only decides the coverage of pixels between a boundary curve and its chord,
//   which stays within kBoundaryTolerance of the curve, and of pixels on the boundary curve
//   (its tie rule). Its interior stays within about kGuessTolerance
//   of the patch (Newton's start). Both follow from bounds on the position's second
//   derivatives, so a nearly affine patch is one or two micro-triangles. Work per covered
//   pixel and patch: one Newton solve (bezier: one position evaluation and closed-form
//   steps; coons: two to four evaluations); per patch: the micro-triangles, a few per
//   pixel at most. A domain pixel no patch covers keeps the bilinear value.
//
// Coverage on the boundary. Pixels whose preimage lies on a patch's parameter boundary are
// common (the patch corners are mesh vertices, so pixel centres on a mesh of integer
// vertices; straight boundary curves run through pixel centres). Their membership used to
// be decided by the last bits of Newton's result against a 1e-12 domain test, so any change
// of the solver's arithmetic flipped pixels (the Horner form of the Coons position flipped
// 120 of 262,144 by up to 31 levels), and about 6,400 of the ~20,000 on-boundary samples of
// a 13,000-vertex grey image were dropped at random. Now the domain is closed and widened by
// kDomainTolerance (1e-8 in the parameters), and Newton runs until its step is below
// kNewtonStep, leaving errors below 1e-12 where it converges quadratically; measured on
// the 13,000-vertex boat, peppers and kodim23 encodings, solutions on the boundary lie
// within 1e-11 of it and all others at least 1e-7 away, so the band decides nothing but the
// boundary itself. Where the Jacobian is singular on the boundary Newton converges only
// linearly (the Coons corner M, where the split curve runs straight through, is always
// such a point; it is a tessellation node, and a start that already solves the equation
// to kExactResidual is kept as it is, so a pixel on it is placed exactly). A pixel on the
// boundary counts when the tessellation's tie rule gives it to one of the patch's
// micro-triangles: a deterministic integer decision. tests/methods/test_patches.cpp checks
// each patch's counts against an independent long double inversion, and that moving
// Newton's start does not change any decision.
//
// The bilinear field (pre-fill and domain) comes from bilinear_prefill below.
// Pixels outside the triangulation's domain (NaN in the bilinear field) are never written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/errors.h"
#include "model/topology.h"
#include "reference/methods/patch_control.h"
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

  // Pixel (i, j) of the image by index; inside(p) is in_domain for that pixel.
  std::size_t index(int i, int j) const { return std::size_t(j) * prefill_.width + i; }
  bool inside(std::size_t p) const { return inside_[p] != 0; }
  // add() for a pixel index p already known to be in the image and the domain.
  void add_inside(std::size_t p, const double* values) {
    ++count_[p];
    double* s = sum_.data() + p * prefill_.channels;
    for (int c = 0, n = prefill_.channels; c < n; ++c) s[c] += values[c];
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
// below 2^59, also when stepped across a bounding box: int64 is exact.
inline constexpr int kSubpixelBits = 8;
inline constexpr double kSubpixelScale = 1 << kSubpixelBits;
inline constexpr double kMaxPatchCoordinate = 1 << 20;
// Distances in output pixels between a patch and its tessellation. A chord of a quadratic
// curve with second derivative K and parameter step h deviates by at most K h^2 / 8; the
// linear interpolant of a quadratic map over a triangle with edge vectors d_k (parameter
// space) deviates by at most max_k |d_k' H d_k| / 6 (H the second derivative).
inline constexpr double kBoundaryTolerance = 1.0 / 8;
inline constexpr double kGuessTolerance = 1.0;
// Newton's method (BezierPatch::solve, CoonsPatch::solve) stops after a step shorter than
// kNewtonStep in the parameters (sum of both): where it converges quadratically the error
// left is then about |P''| / |P'| kNewtonStep^2, below 1e-12. A stop on the residual instead
// would end early where the Jacobian is nearly singular (a small residual there still allows
// parameter errors of about its square root), so the step rules; it may take up to
// kNewtonIterations steps.
inline constexpr double kNewtonStep = 1e-7;
inline constexpr int kNewtonIterations = 12;
// A start whose residual is below kExactResidual pixels is taken as the solution as it is.
inline constexpr double kExactResidual = 1e-12;
// A solution counts as in the patch's closed parameter domain when no domain constraint is
// violated by more than kDomainTolerance (see the header comment: coverage on the boundary).
inline constexpr double kDomainTolerance = 1e-8;
// Subdivisions per patch side are capped (the tessellation may then deviate more).
inline constexpr int kMaxSubdivisions = 1024;

// Subdivisions n of a parameter side for second-derivative bounds `boundary` (along the
// boundary curves) and `interior` (max |d' H d| over the micro-triangle edge directions d
// scaled to the whole side): n^2 >= boundary / (8 kBoundaryTolerance) and
// n^2 >= interior / (6 kGuessTolerance), at least 1.
inline int subdivisions_for(double boundary, double interior) {
  const double n = std::ceil(std::sqrt(std::max(boundary / (8 * kBoundaryTolerance), interior / (6 * kGuessTolerance))));
  return n < 1 ? 1 : n > kMaxSubdivisions ? kMaxSubdivisions : int(n);
}

// A quadratic polynomial in two parameters (s, t) with its first derivatives.
struct Quadratic2 {
  double k = 0, ks = 0, kt = 0, kss = 0, kst = 0, ktt = 0;

  double operator()(double s, double t) const { return k + s * (ks + s * kss + t * kst) + t * (kt + t * ktt); }
  double ds(double s, double t) const { return ks + 2 * s * kss + t * kst; }
  double dt(double s, double t) const { return kt + s * kst + 2 * t * ktt; }
};

// A position (x, y) as one SIMD pair (GCC/Clang vector extension), so that both coordinates
// of a patch are evaluated together in the per-pixel Newton iteration.
using XY = double __attribute__((vector_size(16)));

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
  // floor without a library call: exact here, the values are below 2^29 in magnitude.
  auto floor64 = [](double v) {
    const std::int64_t k = std::int64_t(v);
    return k - (double(k) > v);
  };
  out = {floor64(x * kSubpixelScale + 0.5), floor64(y * kSubpixelScale + 0.5), s, t};
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
// interpolated linearly. Degenerate triangles cover nothing. Bit e of `inclusive_edges`
// makes edge e (a-b, b-c, c-a) own all its points (a domain boundary edge).
template <class Visit>
void rasterize_micro_triangle(const MicroVertex& a, const MicroVertex& b, const MicroVertex& c, int width, int height,
                              Visit&& visit, unsigned inclusive_edges = 0) {
  const MicroVertex* v0 = &a;
  const MicroVertex* v1 = &b;
  const MicroVertex* v2 = &c;
  // Edges opposite v0, v1, v2 as edge indices of (a, b, c).
  int opposite0 = 1, opposite1 = 2, opposite2 = 0;
  // Pixel sample points are the integers: column i at fixed-point i << kSubpixelBits. The box
  // first: most micro-triangles of a fine tessellation hold no sample point.
  const std::int64_t min_x = std::min(std::min(a.x, b.x), c.x), max_x = std::max(std::max(a.x, b.x), c.x);
  const std::int64_t min_y = std::min(std::min(a.y, b.y), c.y), max_y = std::max(std::max(a.y, b.y), c.y);
  const std::int64_t one = std::int64_t(1) << kSubpixelBits;
  const std::int64_t i0 = std::max<std::int64_t>(0, (min_x + one - 1) >> kSubpixelBits);
  const std::int64_t i1 = std::min<std::int64_t>(width - 1, max_x >> kSubpixelBits);
  const std::int64_t j0 = std::max<std::int64_t>(0, (min_y + one - 1) >> kSubpixelBits);
  const std::int64_t j1 = std::min<std::int64_t>(height - 1, max_y >> kSubpixelBits);
  if (i0 > i1 || j0 > j1) return;
  std::int64_t area = edge_function(a, b, c.x, c.y);
  if (area == 0) return;
  if (area < 0) {
    std::swap(v1, v2);
    std::swap(opposite1, opposite2);
    area = -area;
  }
  const std::int64_t bias0 = (inclusive_edges >> opposite0 & 1) ? 0 : edge_bias(*v1, *v2);
  const std::int64_t bias1 = (inclusive_edges >> opposite1 & 1) ? 0 : edge_bias(*v2, *v0);
  const std::int64_t bias2 = (inclusive_edges >> opposite2 & 1) ? 0 : edge_bias(*v0, *v1);
  // Edge functions at the first pixel of the box, stepped by whole pixels: w(p + (1, 0)) =
  // w(p) - dy * one, w(p + (0, 1)) = w(p) + dx * one, for edge (p -> q), dx = q.x - p.x.
  const std::int64_t px0 = i0 << kSubpixelBits, py0 = j0 << kSubpixelBits;
  std::int64_t r0 = edge_function(*v1, *v2, px0, py0);
  std::int64_t r1 = edge_function(*v2, *v0, px0, py0);
  std::int64_t r2 = edge_function(*v0, *v1, px0, py0);
  const std::int64_t sx0 = -(v2->y - v1->y) * one, sy0 = (v2->x - v1->x) * one;
  const std::int64_t sx1 = -(v0->y - v2->y) * one, sy1 = (v0->x - v2->x) * one;
  const std::int64_t sx2 = -(v1->y - v0->y) * one, sy2 = (v1->x - v0->x) * one;
  const double inv_area = 1.0 / double(area);
  for (std::int64_t j = j0; j <= j1; ++j, r0 += sy0, r1 += sy1, r2 += sy2) {
    std::int64_t w0 = r0, w1 = r1, w2 = r2;
    for (std::int64_t i = i0; i <= i1; ++i, w0 += sx0, w1 += sx1, w2 += sx2) {
      if (w0 < bias0 || w1 < bias1 || w2 < bias2) continue;
      const double l0 = double(w0) * inv_area, l1 = double(w1) * inv_area, l2 = 1.0 - l0 - l1;
      visit(int(i), int(j), l0 * v0->s + l1 * v1->s + l2 * v2->s, l0 * v0->t + l1 * v1->t + l2 * v2->t);
    }
  }
}

// The bilinear field of `mesh` at the output size of `out`, as render_bilinear gives it (same
// coverage: domain boundary inclusive, top-left ties; same values up to rounding): the
// patches' pre-fill and domain. Fast path with exact integer edge tests when the output size
// equals the domain's and every vertex lies on the 1/256-pixel grid (pixel positions do),
// where they decide exactly as the exact predicates of reference/coverage.h; otherwise it
// calls render_bilinear.
void bilinear_prefill(const Mesh& mesh, const Topology& topo, int domain_width, int domain_height,
                      const RenderOptions& options, Field& out);

// The exact variant for one patch: every pixel its tessellation covers (patch.tessellate),
// placed by patch.solve and kept when in the closed domain (patch.in_domain), adds the
// patch's values there to `canvas`. `value` holds one double per channel.
template <class Patch>
void rasterize_exact(const Patch& patch, std::vector<double>& value, PatchCanvas& canvas,
                     std::vector<MicroVertex>& node) {
  double* out = value.data();
  patch.tessellate(canvas.width(), canvas.height(), node, [&](int x, int y, double s, double t) {
    const std::size_t p = canvas.index(x, y);
    if (!canvas.inside(p)) return;
    if (!patch.solve(x, y, s, t)) return;
    if (!patch.in_domain(s, t)) return;  // outside the patch, inside a boundary chord
    patch.values(s, t, out);
    canvas.add_inside(p, out);
  });
}

// The render loop of the patch methods: the bilinear pre-fill, then for each triangle with
// three neighbours whose control points `accept(control)` takes, the patch built by
// Patch(control), splatted as the thesis does (`splat`) or rasterized exactly
// (`rasterize`), then the averages written to `out`.
template <class Patch, class Accept, class Splat, class Rasterize>
void render_patches(std::string_view method, const Mesh& mesh, int domain_width, int domain_height,
                    const RenderOptions& options, Field& out, Accept&& accept, Splat&& splat,
                    Rasterize&& rasterize) {
  const bool thesis = is_thesis_variant(method, options.variant);
  const Topology topo = build_topology(mesh);
  const PixelMapping map(domain_width, domain_height, out.width, out.height);
  Field prefill(out.width, out.height, out.channels);
  bilinear_prefill(mesh, topo, domain_width, domain_height, options, prefill);
  PatchCanvas canvas(prefill);

  PatchControl control;
  std::vector<MicroVertex> nodes;
  std::vector<double> value(std::size_t(std::max(mesh.value_count, 1)));
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!patch_control(mesh, topo, t, map, control) || !accept(control)) continue;
    const Patch patch(control);
    if (thesis)
      splat(patch, control.channels, canvas);
    else
      rasterize(patch, value, canvas, nodes);
  }
  if (thesis)
    canvas.resolve_thesis(out);
  else
    canvas.resolve_exact(out);
}

}  // namespace tristream::detail
