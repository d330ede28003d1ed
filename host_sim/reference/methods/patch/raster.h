/* SPDX-License-Identifier: MIT */
#pragma once
// Private to the patch methods (bezier, coons). Both build, for each triangle with three edge
// neighbours, a parametric surface (x, y, values)(s, t) and average every surface that lands
// on a pixel, in sum and count buffers (thesis §3.3, §4.2). Two ways to land on pixels:
//
// - thesis: s and t stepped by a fixed step, each sample rounded to the nearest pixel and
//   added there unless it is off the image or outside the domain; the bilinear pre-fill
//   counts as one more sample in every pixel.
// - exact (the default): every pixel whose sample point is the image of a point of the
//   patch's closed parameter domain (widened by domain_tolerance) counts once for the patch,
//   with the surface's value there, placed by Newton's method (until its step is below
//   newton_step) from a start. Candidates and starts come by rows (patch/scan.h) for every
//   Coons patch and every Bezier patch that provably does not fold, and from a coarse
//   tessellation (rasterize_tessellated, with the pixels between each boundary chord and its
//   curve) for a Bezier patch that may fold; a stamp per pixel (PatchCanvas::claim) keeps a
//   pixel from counting twice for one patch. A pixel beside a fold where Newton converges
//   from no start is not counted; a domain pixel no patch covers keeps the bilinear value.
//
// docs/PATCHES.md has the design, why the boundary band and the step limit are what they
// are, and the history of the coverage fixes. tests/methods/test_patch_coverage.cpp checks
// each patch's counts against an independent long double inversion.
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
#include "reference/methods/patch/control.h"
#include "reference/methods/patch/scan.h"
#include "reference/render.h"

namespace tristream::detail {

// True for variant "thesis", false for "" (the exact default); throws UsageError otherwise.
inline bool is_thesis_variant(std::string_view method, const std::string& variant) {
  if (variant == "thesis") return true;
  if (variant.empty()) return false;
  throw UsageError(std::string(method) + ": unknown variant '" + variant +
                   "' (expected 'thesis', or none for the exact default)");
}

// Sums and counts over the output pixels, in place in `field`, which holds the bilinear
// pre-fill (NaN outside the triangulation: those pixels are never written). The exact
// variant overwrites a pixel's pre-fill with the first patch value it gets and adds the rest;
// the thesis variant adds every sample to the pre-fill. resolve_*() then divides.
class PatchCanvas {
 public:
  explicit PatchCanvas(Field& field);

  int width() const { return field_.width; }
  int height() const { return field_.height; }
  int channels() const { return field_.channels; }
  bool in_domain(int i, int j) const { return inside_[std::size_t(j) * field_.width + i] != 0; }

  // thesis: adds one sample (channels() values) to pixel (i, j); ignored outside the image or
  // domain.
  void add(int i, int j, const double* values) {
    if (i < 0 || j < 0 || i >= field_.width || j >= field_.height) return;
    const std::size_t p = std::size_t(j) * field_.width + i;
    if (!inside_[p]) return;
    ++count_[p];
    double* s = &field_.v[p * field_.channels];
    for (int c = 0; c < field_.channels; ++c) s[c] += values[c];
  }

  // Pixel (i, j) of the image by index; inside(p) is in_domain for that pixel.
  std::size_t index(int i, int j) const { return std::size_t(j) * field_.width + i; }
  bool inside(std::size_t p) const { return inside_[p] != 0; }
  // exact: the values of `patch` at (s, t) (Patch::values, add_values) for a pixel index p
  // already known to be in the image and the domain.
  template <class Patch>
  void add_inside(std::size_t p, const Patch& patch, double s, double t) {
    double* sum = field_.v.data() + p * field_.channels;
    if (count_[p]++ == 0)
      patch.values(s, t, sum);
    else
      patch.add_values(s, t, sum);
  }

  std::uint32_t count(int i, int j) const { return count_[std::size_t(j) * field_.width + i]; }

  // The exact variant's stamps: begin_patch() starts a patch, claim(p) marks pixel p as
  // counted for it, claimed(p) asks. (2^32 patches before a stamp repeats.) Made with the
  // first patch that needs them (one taking the tessellation).
  void begin_patch() {
    if (claim_.empty()) claim_.assign(inside_.size(), 0);
    ++patch_;
  }
  bool claimed(std::size_t p) const { return claim_[p] == patch_; }
  void claim(std::size_t p) { claim_[p] = patch_; }

  // thesis: (pre-fill + sum) / (count + 1) in every domain pixel (§4.2).
  void resolve_thesis();
  // exact: sum / count where some patch landed; the pre-fill stays elsewhere in the domain.
  void resolve_exact();

 private:
  Field& field_;
  std::vector<std::uint8_t> inside_;
  std::vector<std::uint32_t> count_;
  std::vector<std::uint32_t> claim_;
  std::uint32_t patch_ = 0;
};

// Coverage decisions use positions snapped to 1/256 output pixel. Bit budget: a patch is
// skipped unless every node is within +-2^20 pixels (max_patch_coordinate), so fixed-point coordinates are below
// 2^28, differences below 2^29 and the edge functions (products of two differences, summed)
// below 2^59, also when stepped across a bounding box: int64 is exact.
inline constexpr int patch_subpixel_bits = 8;
inline constexpr double patch_subpixel_scale = 1 << patch_subpixel_bits;
// Distance in output pixels between a patch and its tessellation, which bounds the error of
// Newton's start: the linear interpolant of a quadratic map over a triangle with edge
// vectors d_k (parameter space) deviates by at most max_k |d_k' H d_k| / 6 (H the second
// derivative).
inline constexpr double guess_tolerance = 1.0;
// Candidates of a boundary arc (visit_boundary_arc) reach this far, in output pixels,
// beyond the triangle that holds the arc: a pixel on the curve is then a candidate whatever
// the rounding of the triangle's corners.
inline constexpr double arc_margin = 1.0 / 256;
// Newton's method (BezierPatch::solve, CoonsPatch::solve) stops after a step shorter than
// newton_step in the parameters (sum of both): where it converges quadratically the error
// left is then about |P''| / |P'| newton_step^2, 1e-12 times that ratio. A stop on the residual instead
// would end early where the Jacobian is nearly singular (a small residual there still allows
// parameter errors of about its square root), so the step rules; it may take up to
// newton_iterations steps.
inline constexpr double newton_step = 1e-6;
// Newton gives up when it moves farther than newton_reach (sum of both parameters) from its
// start: the domain's size, since a start may be a pixel from a thin patch's solution.
inline constexpr double newton_reach = 1.0;
inline constexpr int newton_iterations = 12;
// A start whose residual is below exact_residual pixels is taken as the solution as it is.
inline constexpr double exact_residual = 1e-12;
// A solution counts as in the patch's closed parameter domain when no domain constraint is
// violated by more than domain_tolerance (see the header comment: coverage on the boundary).
inline constexpr double domain_tolerance = 1e-8;
// Subdivisions per patch side are capped (the tessellation may then deviate more).
inline constexpr int max_subdivisions = 1024;

// Subdivisions n of a parameter side for the second-derivative bound `interior` (max
// |d' H d| over the micro-triangle edge directions d scaled to the whole side):
// n^2 >= interior / (6 guess_tolerance), at least 1.
inline int subdivisions_for(double interior) {
  const double n = std::ceil(std::sqrt(interior / (6 * guess_tolerance)));
  return n < 1 ? 1 : n > max_subdivisions ? max_subdivisions : int(n);
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

// False when (x, y) is outside +-max_patch_coordinate (or NaN): the caller skips the patch.
inline bool snap(double x, double y, double s, double t, MicroVertex& out) {
  if (!(std::fabs(x) <= max_patch_coordinate && std::fabs(y) <= max_patch_coordinate)) return false;
  // floor without a library call: exact here, the values are below 2^29 in magnitude.
  auto floor64 = [](double v) {
    const std::int64_t k = std::int64_t(v);
    return k - (double(k) > v);
  };
  out = {floor64(x * patch_subpixel_scale + 0.5), floor64(y * patch_subpixel_scale + 0.5), s, t};
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
  // Pixel sample points are the integers: column i at fixed-point i << patch_subpixel_bits. The box
  // first: most micro-triangles of a fine tessellation hold no sample point.
  const std::int64_t min_x = std::min(std::min(a.x, b.x), c.x), max_x = std::max(std::max(a.x, b.x), c.x);
  const std::int64_t min_y = std::min(std::min(a.y, b.y), c.y), max_y = std::max(std::max(a.y, b.y), c.y);
  const std::int64_t one = std::int64_t(1) << patch_subpixel_bits;
  const std::int64_t i0 = std::max<std::int64_t>(0, (min_x + one - 1) >> patch_subpixel_bits);
  const std::int64_t i1 = std::min<std::int64_t>(width - 1, max_x >> patch_subpixel_bits);
  const std::int64_t j0 = std::max<std::int64_t>(0, (min_y + one - 1) >> patch_subpixel_bits);
  const std::int64_t j1 = std::min<std::int64_t>(height - 1, max_y >> patch_subpixel_bits);
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
  const std::int64_t px0 = i0 << patch_subpixel_bits, py0 = j0 << patch_subpixel_bits;
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

// Calls visit(i, j, s, t) for every pixel (i, j) of the width x height image whose sample
// point lies within arc_margin of the triangle (p, c, q), c = 2 m - (p + q) / 2: the control
// point of the parabola with ends p, q and middle point m. The arc lies in that triangle, so
// every pixel between the arc and its chord p-q, or on either, is visited (some more near
// them too). (s, t) is a guess of the pixel's parameters: those of p, (ps, pt), and of q,
// (qs, qt), interpolated at the pixel's projection on the chord. Rows are cut from the
// triangle in floating point; the margin absorbs its rounding.
template <class Visit>
void visit_boundary_arc(Point p, Point m, Point q, double ps, double pt, double qs, double qt, int width, int height,
                        Visit&& visit) {
  const double vx[3] = {p.x, 2 * m.x - 0.5 * (p.x + q.x), q.x};
  const double vy[3] = {p.y, 2 * m.y - 0.5 * (p.y + q.y), q.y};
  for (int k = 0; k < 3; ++k)
    if (!(std::fabs(vx[k]) <= 4 * max_patch_coordinate && std::fabs(vy[k]) <= 4 * max_patch_coordinate)) return;
  const double e = arc_margin;
  const double y_lo = std::min({vy[0], vy[1], vy[2]}) - e, y_hi = std::max({vy[0], vy[1], vy[2]}) + e;
  const int j0 = std::max(0, int(std::ceil(y_lo))), j1 = std::min(height - 1, int(std::floor(y_hi)));
  const double dx = q.x - p.x, dy = q.y - p.y, chord2 = dx * dx + dy * dy;
  for (int j = j0; j <= j1; ++j) {
    // x range of the triangle within the slab j - e <= y <= j + e: that of its edges' parts there.
    double x_lo = 1e300, x_hi = -1e300;
    for (int k = 0; k < 3; ++k) {
      const double ax = vx[k], ay = vy[k], bx = vx[(k + 1) % 3], by = vy[(k + 1) % 3];
      if (std::max(ay, by) < j - e || std::min(ay, by) > j + e) continue;
      double f0 = 0, f1 = 1;
      if (by != ay) {
        double fa = (j - e - ay) / (by - ay), fb = (j + e - ay) / (by - ay);
        if (fa > fb) std::swap(fa, fb);
        f0 = std::max(f0, fa), f1 = std::min(f1, fb);
        if (f0 > f1) continue;
      }
      const double x0 = ax + f0 * (bx - ax), x1 = ax + f1 * (bx - ax);
      x_lo = std::min({x_lo, x0, x1}), x_hi = std::max({x_hi, x0, x1});
    }
    if (x_lo > x_hi) continue;
    const int i0 = std::max(0, int(std::ceil(x_lo - e))), i1 = std::min(width - 1, int(std::floor(x_hi + e)));
    for (int i = i0; i <= i1; ++i) {
      const double f = chord2 > 0 ? std::clamp(((i - p.x) * dx + (j - p.y) * dy) / chord2, 0.0, 1.0) : 0.0;
      visit(i, j, ps + f * (qs - ps), pt + f * (qt - pt));
    }
  }
}

// The boundary candidates of side k of a patch's parameter domain (Patch::side(k, f), f in
// [0, 1]; its curve `arc` from side_arcs), in n chords: chord c runs from side(c / n) to
// side((c + 1) / n), its arc's middle is side((c + 1/2) / n), and each goes to
// visit_boundary_arc. Where the side turns back on
// itself (BoundaryArc::cusp: two patch corners at one vertex, the apex of both edge
// neighbours, a vertex of degree 3) the Jacobian vanishes with its velocity and Newton
// converges to no pixel there from a guess nearby, so the pixel nearest the cusp also gets
// the cusp as its start (kept when the cusp is its sample point: the solvers keep a start
// that solves the equation exactly).
template <class Patch, class Visit>
void visit_boundary_side(const Patch& patch, int n, int k, const BoundaryArc& arc, int width, int height,
                         Visit&& visit) {
  auto [s0, t0] = Patch::side(k, 0.0);
  Point p0 = patch.position(s0, t0);
  for (int c = 0; c < n; ++c) {
    const auto [s1, t1] = Patch::side(k, double(c + 1) / n);
    const auto [sm, tm] = Patch::side(k, (c + 0.5) / n);
    const Point p1 = patch.position(s1, t1);
    visit_boundary_arc(p0, patch.position(sm, tm), p1, s0, t0, s1, t1, width, height, visit);
    p0 = p1, s0 = s1, t0 = t1;
  }
  double f;
  if (!arc.cusp(f)) return;
  const double i = std::floor(arc.x(f) + 0.5), j = std::floor(arc.y(f) + 0.5);
  if (i >= 0 && j >= 0 && i < width && j < height) visit(int(i), int(j), arc.s0 + f * arc.ds, arc.t0 + f * arc.dt);
}

// The triangles of `mesh` cell by cell (16 x 16 domain units, cells row by row) by their
// first vertex: neighbouring triangles, and so their patches, come one after another, so the
// pixels they write stay in cache (in file order they are scattered over the image). A
// counting sort: linear in the triangle count.
std::vector<std::uint32_t> triangles_by_cell(const Mesh& mesh);

// The bilinear field of `mesh` at the output size of `out`, as render_bilinear gives it (same
// coverage: domain boundary inclusive, top-left ties; same values up to rounding): the
// patches' pre-fill and domain. Fast path with exact integer edge tests when the output size
// equals the domain's and every vertex lies on the 1/256-pixel grid (pixel positions do),
// where they decide exactly as the exact predicates of reference/coverage.h; otherwise it
// calls render_bilinear. `order` lists the triangles (triangles_by_cell).
void bilinear_prefill(const Mesh& mesh, const Topology& topo, const std::vector<std::uint32_t>& order,
                      int domain_width, int domain_height, const RenderOptions& options, Field& out);

// The exact variant for a patch with a tessellation (is_tessellated below: Bezier): each
// candidate pixel of patch.tessellate, placed by patch.solve from its guess and kept when in
// the closed domain (patch.in_domain), adds the patch's values there to `canvas`, once per
// pixel (the canvas's stamps).
template <class Patch>
void rasterize_tessellated(const Patch& patch, PatchCanvas& canvas, std::vector<MicroVertex>& node) {
  canvas.begin_patch();
  patch.tessellate(canvas.width(), canvas.height(), node, [&](int x, int y, double s, double t) {
    const std::size_t p = canvas.index(x, y);
    if (!canvas.inside(p) || canvas.claimed(p)) return;
    if (!patch.solve(x, y, s, t)) return;
    if (!patch.in_domain(s, t)) return;  // outside the patch: between a chord and its arc, or a margin
    canvas.claim(p);
    canvas.add_inside(p, patch, s, t);
  });
}

// The same by rows (patch/scan.h), each candidate once, for a patch whose fold, if any,
// `folds` holds.
template <class Patch>
void rasterize_rows(const Patch& patch, const std::vector<FoldCell>& folds, PatchCanvas& canvas, ScanScratch& scan) {
  scan_rows(patch, folds, canvas.width(), canvas.height(), scan, [&](int x, int y, double& s, double& t) {
    if (!patch.solve(x, y, s, t)) return Placed::none;
    const Placed placed = placed_at(patch, s, t);
    if (placed != Placed::inside) return placed;
    const std::size_t p = canvas.index(x, y);
    if (canvas.inside(p)) canvas.add_inside(p, patch, s, t);
    return placed;
  });
}

// Scratch of the exact variant, reused from patch to patch.
struct PatchScratch {
  std::vector<MicroVertex> node;
  ScanScratch scan;
  std::vector<FoldCell> folds;
};

// Patches with a tessellation (Bezier: for those that may fold).
template <class Patch>
inline constexpr bool is_tessellated = requires(const Patch& patch) { patch.subdivisions(); };

// The exact variant for one patch: by rows where its fold is bounded (patch.fold_cells: a
// Coons patch always, a Bezier patch when it provably does not fold), else by its
// tessellation.
template <class Patch>
void rasterize_exact(const Patch& patch, PatchCanvas& canvas, PatchScratch& scratch) {
  if (patch.fold_cells(scratch.folds))
    rasterize_rows(patch, scratch.folds, canvas, scratch.scan);
  else if constexpr (is_tessellated<Patch>)
    rasterize_tessellated(patch, canvas, scratch.node);
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
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const std::vector<std::uint32_t> order = triangles_by_cell(mesh);
  bilinear_prefill(mesh, topo, order, domain_width, domain_height, options, out);
  PatchCanvas canvas(out);

  PatchControl control;
  PatchScratch scratch;
  for (std::uint32_t t : order) {
    if (!patch_control(mesh, topo, t, map, control) || !accept(control)) continue;
    const Patch patch(control);
    if (thesis)
      splat(patch, control.channels, canvas);
    else
      rasterize(patch, canvas, scratch);
  }
  if (thesis)
    canvas.resolve_thesis();
  else
    canvas.resolve_exact();
}

}  // namespace tristream::detail
