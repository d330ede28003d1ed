/* SPDX-License-Identifier: MIT */
#pragma once
// Private to the patch methods (bezier, coons): the candidates of the exact variant row by
// row between a patch's boundary curves, widened around its fold where it has one
// (patch/raster.h has the rest of the exact variant and the tessellation used for Bezier
// patches that may fold).
//
// Why rows suffice. Where the Jacobian keeps one sign the patch maps interior points to
// interior points, so the boundary of its image lies on its boundary curves. A pixel whose
// sample point the patch covers therefore has a boundary curve on its row to its left and
// to its right: it lies between the row's leftmost and rightmost crossing of the boundary.
// The boundary curves are parabolas (bezier: three, coons: four), so the crossings of row j
// are roots of quadratics, computed in floating point with a margin (row_tolerance in y,
// span_margin in x) that keeps a pixel on a curve among the candidates.
//
// Starts for Newton. Each crossing's parameters are known (a point of a side of the
// parameter domain); the first pixel after a crossing starts from them, moved to the pixel
// through the inverse Jacobian there; the next pixels extrapolate the last three solutions
// (two at a stretch's start). The starts are a pixel or less from the solutions and at least
// second-order accurate, so Newton mostly takes two or three steps. A pixel that none of
// these settles (SettleRule) tries the two nearest points of a 5 x 5 grid
// inside the domain, then, on a row that a straight side runs along, the side's point there.
//
// Where does it fold? one_sign below bounds the Jacobian determinant's sign by its Bernstein
// coefficients (the determinant lies in their convex hull): all of one sign prove that the
// patch does not fold. A Coons patch otherwise gets fold cells (find_fold_cells), squares of
// its domain that hold the fold, whose boxes join the rows' spans; a Bezier patch takes the
// tessellation.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "reference/render.h"

namespace tristream {

// curve(t) = (a t + b) t + c through s (t = 0), m (t = 1/2) and e (t = 1).
struct Parabola {
  double a = 0, b = 0, c = 0;

  static Parabola through(double s, double m, double e) { return {2 * s + 2 * e - 4 * m, 4 * m - 3 * s - e, s}; }
  double operator()(double t) const { return (a * t + b) * t + c; }
};

}  // namespace tristream

namespace tristream::detail {

// A patch is skipped unless its positions stay within +-max_patch_coordinate output pixels
// (the bit budget of patch/raster.h's fixed point).
inline constexpr double max_patch_coordinate = 1 << 20;

// A start for the pixels of a row: a boundary crossing (y is the row) or the middle of a
// fold cell: its position and its parameters.
struct RowCrossing {
  double x, y, s, t;
};

// The crossings of one row (the first max_row_crossings of them: enough for the guesses) and
// the span between the leftmost and rightmost of all.
struct RowCrossings {
  static constexpr int max_row_crossings = 20;
  int count = 0;
  double x_min = 1e300, x_max = -1e300;
  unsigned along = 0;  // bit k: side k of the patch runs along the row
  RowCrossing crossing[max_row_crossings];

  void clear() { count = 0, x_min = 1e300, x_max = -1e300, along = 0; }

  void add(double x, double y, double s, double t) {
    x_min = std::min(x_min, x), x_max = std::max(x_max, x);
    if (count < max_row_crossings) crossing[count++] = {x, y, s, t};
  }
};

// Scratch of scan_rows, reused from patch to patch.
struct ScanScratch {
  std::vector<RowCrossings> rows;
};

// Rows closer than this (output pixels) to a boundary curve's extreme or flat part count as
// crossing it there; crossings reach span_margin further out in x.
inline constexpr double row_tolerance = 1e-9;
inline constexpr double span_margin = 1e-7;

// A boundary curve: position (x(f), y(f)) for f in [0, 1], parameters (s, t) = (s0 + f ds,
// t0 + f dt).
struct BoundaryArc {
  Parabola x, y;
  double s0 = 0, t0 = 0, ds = 0, dt = 0;

  // The parameter f in (0, 1) where the curve turns back on itself (a cusp: its velocity
  // vanishes there; the side runs out along a segment and back), if it does.
  bool cusp(double& f) const {
    const double speed2 = x.a * x.a + y.a * y.a;
    if (speed2 == 0) return false;
    f = -(x.a * x.b + y.a * y.b) / (2 * speed2);  // the least velocity
    const double vx = 2 * x.a * f + x.b, vy = 2 * y.a * f + y.b;
    return f > 0 && f < 1 && vx * vx + vy * vy <= 1e-18 * speed2;
  }
};

// The sides of `patch` (Patch::side(k, f), k < Patch::side_count) as boundary curves: the
// position is quadratic along a side, the parabola through its ends and middle. False when
// one of those lies beyond max_patch_coordinate (the patch is skipped).
template <class Patch>
bool side_arcs(const Patch& patch, std::array<BoundaryArc, Patch::side_count>& arcs) {
  for (int k = 0; k < Patch::side_count; ++k) {
    BoundaryArc& arc = arcs[std::size_t(k)];
    const auto [s0, t0] = Patch::side(k, 0.0);
    const auto [s1, t1] = Patch::side(k, 1.0);
    const auto [sm, tm] = Patch::side(k, 0.5);
    const Point p0 = patch.position(s0, t0), pm = patch.position(sm, tm), p1 = patch.position(s1, t1);
    for (const Point& p : {p0, pm, p1})
      if (!(std::fabs(p.x) <= max_patch_coordinate && std::fabs(p.y) <= max_patch_coordinate)) return false;
    arc.x = Parabola::through(p0.x, pm.x, p1.x);
    arc.y = Parabola::through(p0.y, pm.y, p1.y);
    arc.s0 = s0, arc.t0 = t0, arc.ds = s1 - s0, arc.dt = t1 - t0;
  }
  return true;
}

// Calls f(r) for each root r in [0, 1] of a r^2 + b r + c = 0 (stable quadratic formula; a
// double root once; nothing where a = b = 0).
template <class F>
void unit_roots(double a, double b, double c, F&& f) {
  if (a == 0) {
    if (b != 0 && -c / b >= 0 && -c / b <= 1) f(-c / b);
    return;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  const double f1 = q / a, f2 = q != 0 ? c / q : f1;
  if (f1 >= 0 && f1 <= 1) f(f1);
  if (f2 >= 0 && f2 <= 1 && f2 != f1) f(f2);
}

// Adds the crossings of `arc` (side k of the patch) with rows j0..j1 to rows[j - j0], and
// marks k in the row's `along` where the arc runs along the row (a straight side on it).
inline void add_arc_crossings(const BoundaryArc& arc, int k, int j0, int j1, std::vector<RowCrossings>& rows) {
  const Parabola& y = arc.y;
  auto add = [&](int j, double f) {
    rows[std::size_t(j - j0)].add(arc.x(f), j, arc.s0 + f * arc.ds, arc.t0 + f * arc.dt);
  };
  // Extremes of y over [0, 1]: its ends and its vertex; of x: its vertex (for flat stretches).
  const double fy = y.a != 0 ? -y.b / (2 * y.a) : -1, fx = arc.x.a != 0 ? -arc.x.b / (2 * arc.x.a) : -1;
  const bool y_vertex = fy > 0 && fy < 1, x_vertex = fx > 0 && fx < 1;
  double lo = std::min(y.c, y(1)), hi = std::max(y.c, y(1));
  if (y_vertex) lo = std::min(lo, y(fy)), hi = std::max(hi, y(fy));
  const int first = std::max(j0, int(std::ceil(lo - row_tolerance)));
  const int last = std::min(j1, int(std::floor(hi + row_tolerance)));
  for (int j = first; j <= last; ++j) {
    // Roots of y(f) = j in [0, 1], and the points of the curve within row_tolerance of the
    // row among its ends and vertices (tangent or flat rows).
    const double a = y.a, b = y.b, c = y.c - j;
    if (std::fabs(c) <= row_tolerance) add(j, 0);
    if (std::fabs(a + b + c) <= row_tolerance) add(j, 1);
    if (y_vertex && std::fabs(y(fy) - j) <= row_tolerance) add(j, fy);
    if (x_vertex && std::fabs(y(fx) - j) <= row_tolerance) add(j, fx);
    unit_roots(a, b, c, [&](double f) { add(j, f); });
    if (a == 0 && b == 0 && c == 0) rows[std::size_t(j - j0)].along |= 1u << k;
  }
}

// What a start made of a pixel: Newton found no solution, one outside the patch's domain
// but within near_margin of it, one farther outside, or one inside (the pixel counted).
enum class Placed { none, outside, beyond, inside };
inline constexpr double near_margin = 0.25;

// Where a solution (s, t) of patch.solve lies.
template <class Patch>
Placed placed_at(const Patch& patch, double s, double t) {
  if (patch.in_domain(s, t)) return Placed::inside;
  return patch.outside_by(s, t) <= near_margin ? Placed::outside : Placed::beyond;
}

// The Jacobian determinant of the patch's position at (s, t).
template <class Patch>
double jacobian_determinant(const Patch& patch, double s, double t) {
  double x, y, xs, xt, ys, yt;
  patch.position(s, t, x, y, xs, xt, ys, yt);
  return xs * yt - xt * ys;
}

// A part of the parameter domain where a patch may fold: a box that holds its image, and
// its middle (position and parameters) as a start. The boundary of a folded patch's image
// lies on its boundary curves or on the image of its fold (where the Jacobian determinant
// vanishes), so the rows' spans take these boxes in too.
struct FoldCell {
  double x_lo, x_hi, y_lo, y_hi;
  RowCrossing middle;
};

// The rows j0..j1 that the patch's boundary curves and fold boxes reach, each with its
// crossings (rows[j - j0]); j0 > j1 when none.
template <class Patch>
std::pair<int, int> collect_row_crossings(const std::array<BoundaryArc, Patch::side_count>& arcs,
                                          const std::vector<FoldCell>& folds, int height,
                                          std::vector<RowCrossings>& rows) {
  double y_lo = 1e300, y_hi = -1e300;
  for (const BoundaryArc& arc : arcs) {
    // The curve lies in the triangle of its ends and control point y(0) + y'(0) / 2.
    const double y0 = arc.y.c, y1 = arc.y(1), cy = arc.y.c + 0.5 * arc.y.b;
    y_lo = std::min({y_lo, y0, y1, cy}), y_hi = std::max({y_hi, y0, y1, cy});
  }
  for (const FoldCell& cell : folds) y_lo = std::min(y_lo, cell.y_lo), y_hi = std::max(y_hi, cell.y_hi);
  const int j0 = std::max(0, int(std::ceil(y_lo - 1))), j1 = std::min(height - 1, int(std::floor(y_hi + 1)));
  if (j0 > j1) return {j0, j1};
  rows.resize(std::size_t(j1 - j0 + 1));
  for (RowCrossings& row : rows) row.clear();
  for (const FoldCell& cell : folds) {
    const int first = std::max(j0, int(std::ceil(cell.y_lo - row_tolerance)));
    const int last = std::min(j1, int(std::floor(cell.y_hi + row_tolerance)));
    for (int j = first; j <= last; ++j) {
      RowCrossings& row = rows[std::size_t(j - j0)];
      row.x_min = std::min(row.x_min, cell.x_lo), row.x_max = std::max(row.x_max, cell.x_hi);
      row.add(std::clamp(cell.middle.x, cell.x_lo, cell.x_hi), cell.middle.y, cell.middle.s, cell.middle.t);
    }
  }
  for (int k = 0; k < Patch::side_count; ++k) add_arc_crossings(arcs[std::size_t(k)], k, j0, j1, rows);
  return {j0, j1};
}

// The last resort, for a pixel no other start placed: the two nearest points of a grid over
// the domain (made once per patch, when first needed), nearer first. The points are the
// centres of a 5 x 5 split of the square, inside the domain: on its boundary the Jacobian may
// vanish (the Coons corner M, and sides of degenerate patches), where Newton fails.
template <class Patch>
class GridStarts {
 public:
  explicit GridStarts(const Patch& patch) : patch_(patch) {}

  void nearest(int i, int j, double (&gs)[2], double (&gt)[2]) {
    if (size_ == 0) build();
    double best[2] = {1e300, 1e300};
    int index[2] = {0, 0};
    for (int k = 0; k < size_; ++k) {
      const double d = std::fabs(grid_[k][0] - i) + std::fabs(grid_[k][1] - j);
      if (d < best[1]) {
        best[1] = d, index[1] = k;
        if (d < best[0]) std::swap(best[0], best[1]), std::swap(index[0], index[1]);
      }
    }
    for (int r = 0; r < 2; ++r) gs[r] = grid_[index[r]][2], gt[r] = grid_[index[r]][3];
  }

 private:
  static constexpr int grid_steps = 4;
  void build() {
    for (int a = 0; a <= grid_steps; ++a)
      for (int b = 0; b <= grid_steps; ++b) {
        const double gs = (a + 0.5) / (grid_steps + 1), gt = (b + 0.5) / (grid_steps + 1);
        if (patch_.in_domain(gs, gt)) {
          const Point p = patch_.position(gs, gt);
          grid_[size_++] = {p.x, p.y, gs, gt};
        }
      }
  }
  const Patch& patch_;
  std::array<double, 4> grid_[(grid_steps + 1) * (grid_steps + 1)];
  int size_ = 0;
};

// A start settles a pixel when the patch covers it from there or, for a patch that does not
// fold, when Newton finds a solution near the domain where the Jacobian determinant keeps the
// patch's sign: the pixel then lies beside the patch. The polynomial goes on beyond the domain
// and may fold back over the patch there, so a solution far outside (a start from a crossing
// near the Coons corner M, where the inverse Jacobian is large, can reach one) does not settle
// the pixel, nor does one where the determinant has turned: the continuation is folded there
// (beside the Coons corner M, where the determinant vanishes, it turns within near_margin of the
// domain). Where the patch folds (centre_det = 0) no solution outside the domain settles a
// pixel. The other starts are then tried too.
template <class Patch>
struct SettleRule {
  const Patch& patch;
  double centre_det;

  SettleRule(const Patch& p, bool folds) : patch(p), centre_det(0) {
    const auto [centre_s, centre_t] = Patch::centre();
    if (!folds) centre_det = jacobian_determinant(patch, centre_s, centre_t);
  }
  bool operator()(Placed placed, double s, double t) const {
    return placed == Placed::inside ||
           (placed == Placed::outside && centre_det != 0 && jacobian_determinant(patch, s, t) * centre_det > 0);
  }
};

// A start for pixel (i, j) from crossing c moved there through the inverse Jacobian at c;
// false where the Jacobian is singular (the Coons corner M) unless the pixel is on the
// crossing. (ds, dt) becomes J^-1 (1, 0) there: the step to the next pixel.
template <class Patch>
bool start_from_crossing(const Patch& patch, const RowCrossing& c, int i, int j, double& gs, double& gt, double& ds,
                         double& dt) {
  double px, py, xs, xt, ys, yt;
  patch.position(c.s, c.t, px, py, xs, xt, ys, yt);
  const double det = xs * yt - xt * ys;
  const bool regular = std::fabs(det) > 1e-9 * (std::fabs(xs * yt) + std::fabs(xt * ys));
  const double inverse = regular ? 1 / det : 0;
  ds = yt * inverse, dt = -ys * inverse;
  const double ex = -xt * inverse, et = xs * inverse;  // J^-1 (0, 1)
  gs = c.s + (i - c.x) * ds + (j - c.y) * ex, gt = c.t + (i - c.x) * dt + (j - c.y) * et;
  return regular || (i == c.x && j == c.y);
}

// On a row a straight side runs along (bits of `along`), the side's own points at the pixel,
// x(f) = i, as starts: the Jacobian may vanish all along such a side, so that Newton only
// creeps towards a pixel on it from anywhere else. True when one of them placed the pixel.
template <std::size_t Sides, class Visit>
bool start_along_sides(const std::array<BoundaryArc, Sides>& arcs, unsigned along, int i, int j, Visit& visit) {
  bool settled = false;
  for (; along != 0; along &= along - 1) {
    const BoundaryArc& arc = arcs[std::size_t(std::countr_zero(along))];
    unit_roots(arc.x.a, arc.x.b, arc.x.c - i, [&](double f) {
      double fs = arc.s0 + f * arc.ds, ft = arc.t0 + f * arc.dt;
      if (!settled && visit(i, j, fs, ft) == Placed::inside) settled = true;
    });
  }
  return settled;
}

// The pixels of row j between its leftmost and rightmost crossing, each visited from the
// last three solutions extrapolated while they settle it, else from the nearer crossing, the
// other, the grid and the sides along the row, in that order. Inlined into scan_rows: as a
// call it cost 0.3% more instructions on kodim23 (callgrind).
template <class Patch, class Visit>
[[gnu::always_inline]] inline void scan_row(const Patch& patch, const std::array<BoundaryArc, Patch::side_count>& arcs,
                                            RowCrossings& row, int j, int width, GridStarts<Patch>& grid,
                                            const SettleRule<Patch>& settles, Visit& visit) {
  RowCrossing* crossing = row.crossing;
  const int count = row.count;
  for (int k = 1; k < count; ++k)  // insertion sort by x: a row has a few crossings
    for (int m = k; m > 0 && crossing[m].x < crossing[m - 1].x; --m) std::swap(crossing[m], crossing[m - 1]);
  const int i0 = std::max(0, int(std::ceil(row.x_min - span_margin)));
  const int i1 = std::min(width - 1, int(std::floor(row.x_max + span_margin)));
  constexpr int grid_start = -2;  // and -3: the grid's two starts
  int next = 0;            // the first crossing right of the pixel
  bool continued = false;  // the last pixel was solved at (s, t), (ds, dt) apart from the one before
  double s = 0, t = 0, ds = 0, dt = 0, dds = 0, ddt = 0;  // and (dds, ddt) the difference of those steps
  for (int i = i0; i <= i1; ++i) {
    bool passed = false;
    while (next < count && crossing[next].x <= i + span_margin) ++next, passed = true;
    double ns, nt;
    if (continued && !passed) {
      // The common case: the last three solutions extrapolated (two at a stretch's start).
      ns = s + ds + dds, nt = t + dt + ddt;
      const Placed placed = visit(i, j, ns, nt);
      if (settles(placed, ns, nt)) {
        dds = ns - s - ds, ddt = nt - t - dt, ds = ns - s, dt = nt - t, s = ns, t = nt;
        continue;
      }
    }
    // A new stretch, or the extrapolation did not settle the pixel: the nearer crossing,
    // the other, the grid; the last solution found continues the row.
    dds = 0, ddt = 0;
    const int left = next - 1, right = next < count ? next : -1;
    const bool left_first = right < 0 || (left >= 0 && i - crossing[left].x <= crossing[right].x - i);
    const int order[4] = {left_first ? left : right, left_first ? right : left, grid_start, grid_start - 1};
    continued = false;
    bool settled = false;
    double grid_s[2], grid_t[2];
    for (int k : order) {
      double cds = 0, cdt = 0;
      if (k <= grid_start) {  // no crossing settled the pixel
        if (k == grid_start) grid.nearest(i, j, grid_s, grid_t);
        ns = grid_s[grid_start - k], nt = grid_t[grid_start - k];
      } else if (k < 0 || !start_from_crossing(patch, crossing[k], i, j, ns, nt, cds, cdt)) {
        continue;
      }
      const Placed placed = visit(i, j, ns, nt);
      if (placed == Placed::none) continue;
      continued = true, s = ns, t = nt, ds = cds, dt = cdt;
      if ((settled = settles(placed, ns, nt))) break;
    }
    if (!settled && row.along != 0) start_along_sides(arcs, row.along, i, j, visit);
  }
}

// Calls visit(i, j, s, t) for each pixel (i, j) of the width x height image between the
// leftmost and rightmost crossing of its row with the boundary of `patch` or with a box of
// `folds` (which must hold the patch's fold: none where it does not fold), with a start
// (s, t) for Newton passed by reference: visit returns what it made of the pixel (Placed),
// with (s, t) the solution unless none.
template <class Patch, class Visit>
void scan_rows(const Patch& patch, const std::vector<FoldCell>& folds, int width, int height, ScanScratch& scratch,
               Visit&& visit) {
  std::array<BoundaryArc, Patch::side_count> arcs;
  if (!side_arcs(patch, arcs)) return;
  std::vector<RowCrossings>& rows = scratch.rows;
  const auto [j0, j1] = collect_row_crossings<Patch>(arcs, folds, height, rows);
  if (j0 > j1) return;
  GridStarts<Patch> grid(patch);
  const SettleRule<Patch> settles(patch, !folds.empty());
  for (int j = j0; j <= j1; ++j) {
    RowCrossings& row = rows[std::size_t(j - j0)];
    if (row.count != 0) scan_row(patch, arcs, row, j, width, grid, settles, visit);
  }
}

// Sign of the Jacobian determinant of a patch over its domain from Bernstein coefficients.
// Bezier: the determinant is quadratic on the triangle: its six coefficients from the values
// at the corners and edge middles. Coons: it has degree 3 in u and in v: sixteen
// coefficients from its monomials (CoonsPatch::fold_cells). The coefficients at the domain's
// corners are the determinant there and may vanish (the Coons corner M always does): the
// others, all of one sign, keep the determinant away from 0 everywhere else. True for that.
inline bool one_sign(const double* b, int n, const bool* corner) {
  double scale = 0;
  for (int k = 0; k < n; ++k) scale = std::max(scale, std::fabs(b[k]));
  const double floor = 1e-9 * scale;
  bool positive = scale > 0, negative = scale > 0;
  for (int k = 0; k < n && (positive || negative); ++k) {
    positive = positive && (b[k] > floor || (corner[k] && b[k] >= -floor));
    negative = negative && (b[k] < -floor || (corner[k] && b[k] <= floor));
  }
  return positive || negative;
}

// Bernstein coefficients b[0..n] on [0, 1] split at 1/2 into those on [0, 1/2] (lo) and on
// [1/2, 1] (hi): de Casteljau's algorithm. `stride` steps from one coefficient to the next.
inline void halve_bernstein(const double* b, int n, int stride, double* lo, double* hi) {
  double work[4];
  for (int k = 0; k <= n; ++k) work[k] = b[k * stride];
  lo[0] = work[0], hi[n * stride] = work[n];
  for (int r = 1; r <= n; ++r) {
    for (int k = 0; k + r <= n; ++k) work[k] = 0.5 * (work[k] + work[k + 1]);
    lo[r * stride] = work[0], hi[(n - r) * stride] = work[n - r];
  }
}

// A square of a tensor-product patch's parameter domain with the Bernstein coefficients, on
// that square, of its Jacobian determinant (degree 3 x 3) and position (degree 2 x 2).
struct TensorCell {
  double det[4][4];
  double x[3][3], y[3][3];
  double u0 = 0, v0 = 0, size = 1;
};

// Appends to `out` the squares of `cell`, halved down to fold_depth times, on which the
// determinant may vanish (its coefficients are not all of one sign, see one_sign; the
// domain's corners may vanish), each with the box of its position's coefficients (the
// convex hull holds the image) and its middle. middle(u, v) gives the position there.
inline constexpr int fold_depth = 2;
template <class Middle>
void find_fold_cells(const TensorCell& cell, int depth, Middle&& middle, std::vector<FoldCell>& out) {
  auto domain_corner = [](double u, double v) { return (u == 0 || u == 1) && (v == 0 || v == 1); };
  const double u1 = cell.u0 + cell.size, v1 = cell.v0 + cell.size;
  bool corner[16] = {};
  corner[0] = domain_corner(cell.u0, cell.v0), corner[3] = domain_corner(cell.u0, v1);
  corner[12] = domain_corner(u1, cell.v0), corner[15] = domain_corner(u1, v1);
  if (one_sign(&cell.det[0][0], 16, corner)) return;
  if (depth == fold_depth) {
    FoldCell fold{1e300, -1e300, 1e300, -1e300, {}};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) {
        fold.x_lo = std::min(fold.x_lo, cell.x[i][k]), fold.x_hi = std::max(fold.x_hi, cell.x[i][k]);
        fold.y_lo = std::min(fold.y_lo, cell.y[i][k]), fold.y_hi = std::max(fold.y_hi, cell.y[i][k]);
      }
    const double u = cell.u0 + cell.size / 2, v = cell.v0 + cell.size / 2;
    const Point p = middle(u, v);
    fold.middle = {p.x, p.y, u, v};
    out.push_back(fold);
    return;
  }
  // Halve along u (the first index), then each half along v.
  TensorCell half[2], quarter[4];
  for (int k = 0; k < 4; ++k) halve_bernstein(&cell.det[0][k], 3, 4, &half[0].det[0][k], &half[1].det[0][k]);
  for (int k = 0; k < 3; ++k) {
    halve_bernstein(&cell.x[0][k], 2, 3, &half[0].x[0][k], &half[1].x[0][k]);
    halve_bernstein(&cell.y[0][k], 2, 3, &half[0].y[0][k], &half[1].y[0][k]);
  }
  for (int h = 0; h < 2; ++h) {
    TensorCell& lo = quarter[2 * h];
    TensorCell& hi = quarter[2 * h + 1];
    for (int i = 0; i < 4; ++i) halve_bernstein(half[h].det[i], 3, 1, lo.det[i], hi.det[i]);
    for (int i = 0; i < 3; ++i) {
      halve_bernstein(half[h].x[i], 2, 1, lo.x[i], hi.x[i]);
      halve_bernstein(half[h].y[i], 2, 1, lo.y[i], hi.y[i]);
    }
    lo.size = hi.size = cell.size / 2;
    lo.u0 = hi.u0 = cell.u0 + h * cell.size / 2;
    lo.v0 = cell.v0, hi.v0 = cell.v0 + cell.size / 2;
  }
  for (const TensorCell& q : quarter) find_fold_cells(q, depth + 1, middle, out);
}

}  // namespace tristream::detail
