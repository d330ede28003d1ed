// SPDX-License-Identifier: MIT
// Coverage of the exact variant of the patch methods (bezier, coons; patch/raster.h), checked
// patch by patch against an independent inversion of the patch: multi-start Newton in long
// double on the patch rebuilt from its control points (Bernstein form, Coons boundary curves),
// with numeric derivatives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "../support/random_mesh.h"
#include "io/tri_file.h"
#include "model/topology.h"
#include "reference/methods/bezier.h"
#include "reference/methods/coons.h"
#include "reference/methods/patch/raster.h"

using namespace tristream;

namespace {

using LPoint = std::array<long double, 2>;

// Independent position maps, in long double, from the control points.
struct BezierMap {
  std::array<LPoint, 6> p;
  explicit BezierMap(const PatchControl& c) {
    for (int k = 0; k < 6; ++k) p[k] = {c.pixel[k].x, c.pixel[k].y};
  }
  LPoint operator()(long double a, long double b) const {
    const long double c = 1 - a - b;
    LPoint r{};
    for (int d = 0; d < 2; ++d)
      r[d] = a * a * p[p200][d] + b * b * p[p020][d] + c * c * p[p002][d] + 2 * a * b * p[p110][d] +
             2 * b * c * p[p011][d] + 2 * a * c * p[p101][d];
    return r;
  }
  // Signed distance outside the domain a, b, c >= 0 (negative inside).
  static long double outside(long double a, long double b) { return std::max({-a, -b, a + b - 1}); }
  static constexpr long double lo = 0, hi = 1;
};

int middle_point(int p, int q) {
  const int lo = std::min(p, q), hi = std::max(p, q);
  return lo == p200 ? (hi == p020 ? p110 : p101) : p011;
}

struct CoonsMap {
  LPoint A, M, B, C, mac, mbc;
  CoonsMap(const PatchControl& c, const CoonsPatch& patch) {
    const auto k = patch.corners();
    auto at = [&](int i) { return LPoint{c.pixel[i].x, c.pixel[i].y}; };
    A = at(k[0]), M = at(k[1]), B = at(k[2]), C = at(k[3]);
    mac = at(middle_point(k[0], k[3])), mbc = at(middle_point(k[3], k[2]));
  }
  // The parabola through s, m, e at t = 0, 1/2, 1 (Lagrange form).
  static long double curve(long double s, long double m, long double e, long double t) {
    return s * 2 * (t - 0.5L) * (t - 1) - m * 4 * t * (t - 1) + e * 2 * t * (t - 0.5L);
  }
  LPoint operator()(long double u, long double v) const {
    LPoint r{};
    for (int d = 0; d < 2; ++d) {
      const long double b1 = curve(A[d], M[d], B[d], u / 2), a2 = curve(A[d], M[d], B[d], (1 + v) / 2);
      const long double a1 = curve(A[d], mac[d], C[d], v), b2 = curve(C[d], mbc[d], B[d], u);
      r[d] = (1 - u) * a1 + u * a2 + (1 - v) * b1 + v * b2 -
             ((1 - u) * (1 - v) * A[d] + u * (1 - v) * M[d] + (1 - u) * v * C[d] + u * v * B[d]);
    }
    return r;
  }
  static long double outside(long double u, long double v) { return std::max({-u, -v, u - 1, v - 1}); }
};

// Newton in long double with central-difference derivatives from (s, t), run until its steps
// vanish (where the Jacobian is singular it converges only linearly, and a small residual
// does not yet mean small parameter errors); true when it ends on a residual below 1e-10
// pixels.
template <class Map>
bool invert(const Map& map, long double x, long double y, long double& s, long double& t) {
  const long double h = 1e-7L;
  for (int it = 0; it < 120; ++it) {
    const LPoint p = map(s, t);
    const long double ex = x - p[0], ey = y - p[1];
    if (ex == 0 && ey == 0) return true;
    const LPoint ps = map(s + h, t), ms = map(s - h, t), pt = map(s, t + h), mt = map(s, t - h);
    const long double xs = (ps[0] - ms[0]) / (2 * h), ys = (ps[1] - ms[1]) / (2 * h);
    const long double xt = (pt[0] - mt[0]) / (2 * h), yt = (pt[1] - mt[1]) / (2 * h);
    const long double det = xs * yt - xt * ys;
    if (det == 0) break;
    const long double ds = (yt * ex - xt * ey) / det, dt = (xs * ey - ys * ex) / det;
    s += ds, t += dt;
    if (!(std::fabs(s) < 3 && std::fabs(t) < 3)) return false;
    if (std::fabs(ds) + std::fabs(dt) < 1e-17L) break;
  }
  const LPoint p = map(s, t);
  return std::fabs(x - p[0]) + std::fabs(y - p[1]) < 1e-10L;
}

// Preimages of (x, y) near the closed domain: their distances outside it (<= 0 inside).
template <class Map>
std::vector<long double> preimages(const Map& map, long double x, long double y) {
  std::vector<std::array<long double, 2>> roots;
  std::vector<long double> out;
  // The domain's corners first: where the Jacobian is singular (the Coons corner M) Newton
  // only creeps towards the root, so a start on it must find it exactly.
  std::vector<std::array<long double, 2>> starts = {{0, 0}, {1, 0}, {0, 1}};
  if (Map::outside(1, 1) <= 0) starts.push_back({1, 1});
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) starts.push_back({-0.1L + 1.2L * i / 4, -0.1L + 1.2L * j / 4});
  for (auto [s, t] : starts) {
    if (!invert(map, x, y, s, t) || Map::outside(s, t) > 0.05L) continue;
    bool seen = false;
    for (const auto& r : roots) seen = seen || (std::fabs(r[0] - s) + std::fabs(r[1] - t) < 1e-6L);
    if (seen) continue;
    roots.push_back({s, t});
    out.push_back(Map::outside(s, t));
  }
  return out;
}

// Jacobian of one sign over the domain (sampled): the patch does not fold.
template <class Patch>
bool folds(const Patch& patch, bool triangle) {
  int positive = 0, negative = 0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double s = i / 40.0, t = j / 40.0;
      if (triangle && s + t > 1) continue;
      double x, y, xs, xt, ys, yt;
      patch.position(s, t, x, y, xs, xt, ys, yt);
      const double det = xs * yt - xt * ys;
      positive += det > 0, negative += det < 0;
    }
  return positive && negative;
}

struct Tally {
  int patches = 0, folded = 0, by_rows = 0, folded_by_rows = 0, pixels = 0, on_boundary_counted = 0, ambiguous = 0;
  int fold_pixels = 0, fold_missed = 0, fold_missed_tessellated = 0;
};

// For every unfolded patch of `mesh`: the single patch's counts in a canvas against its
// independent preimages in the closed domain (within 1e-6 of it counts as on it), for each
// pixel of the patch's box: 1 where there is one (or more), else 0.
template <class Patch, class MakeMap>
Tally check_coverage(const Mesh& mesh, int width, int height, bool triangle, MakeMap&& make_map) {
  const Topology topo = build_topology(mesh);
  const PixelMapping map(width, height, width, height);
  Tally tally;
  Field prefill(width, height, mesh.value_count);
  std::fill(prefill.v.begin(), prefill.v.end(), 0.0);
  std::vector<detail::MicroVertex> nodes;
  detail::ScanScratch rows;
  std::vector<detail::FoldCell> fold_cells;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    PatchControl control;
    if (!patch_control(mesh, topo, t, map, control)) continue;
    const Patch patch(control);
    ++tally.patches;
    const bool folded = folds(patch, triangle);
    tally.folded += folded;
    const auto ref = make_map(control, patch);
    // Both ways of the exact variant, each against the truth: the renderer's choice (by rows
    // where the patch's fold is bounded, else by its tessellation), and the tessellation
    // (Bezier; a Coons patch has none and takes the rows again).
    Field by_rows_field = prefill, tessellated_field = prefill;
    detail::PatchCanvas canvas(by_rows_field), tessellated(tessellated_field);
    if (patch.fold_cells(fold_cells)) {
      ++tally.by_rows;
      tally.folded_by_rows += folded;
      detail::rasterize_rows(patch, fold_cells, canvas, rows);
    } else if constexpr (detail::is_tessellated<Patch>) {
      detail::rasterize_tessellated(patch, canvas, nodes);
    }
    // The tessellation too where the patch has one (Bezier); else the same as the renderer.
    if constexpr (detail::is_tessellated<Patch>)
      detail::rasterize_tessellated(patch, tessellated, nodes);
    else
      detail::rasterize_rows(patch, fold_cells, tessellated, rows);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (int i = 0; i <= 32; ++i)
      for (int j = 0; j <= 32; ++j) {
        if (triangle && i + j > 32) continue;
        const LPoint p = ref(i / 32.0L, j / 32.0L);
        x0 = std::min(x0, double(p[0])), x1 = std::max(x1, double(p[0]));
        y0 = std::min(y0, double(p[1])), y1 = std::max(y1, double(p[1]));
      }
    for (int y = std::max(0, int(std::floor(y0)) - 1); y <= std::min(height - 1, int(std::ceil(y1)) + 1); ++y)
      for (int x = std::max(0, int(std::floor(x0)) - 1); x <= std::min(width - 1, int(std::ceil(x1)) + 1); ++x) {
        const std::vector<long double> roots = preimages(ref, x, y);
        int truth = 0;
        bool on_boundary = false;
        for (long double d : roots) {
          // A preimage within 1e-6 of the domain's boundary is on it: these pixels are mesh
          // vertices or on straight boundary curves, and where the patch's Jacobian is singular
          // (the Coons corner M) even this long double inversion only gets within ~1e-9.
          on_boundary = on_boundary || std::fabs(d) < 1e-6L;
          truth += d < 1e-6L;
          // Off the boundary, preimages keep clear of domain_tolerance: the gap the band needs.
          tally.ambiguous += std::fabs(d) >= 1e-6L && std::fabs(d) < 1e-4L;
        }
        const int counted = int(canvas.count(x, y));
        ++tally.pixels;
        INFO("patch " << t << " pixel " << x << ", " << y << " truth " << truth << " counted " << counted
                      << " by tessellation " << tessellated.count(x, y));
        tally.on_boundary_counted += on_boundary && counted > 0;
        if (!folded) {
          // Once where the patch reaches the pixel, on its boundary too.
          REQUIRE(counted == std::min(truth, 1));
          REQUIRE(int(tessellated.count(x, y)) == std::min(truth, 1));
          continue;
        }
        // Where it folds: never where it does not reach, never twice; a pixel beside the
        // fold, where Newton finds no solution from any start, may be missed.
        REQUIRE(counted <= std::min(truth, 1));
        REQUIRE(int(tessellated.count(x, y)) <= std::min(truth, 1));
        tally.fold_pixels += truth > 0;
        tally.fold_missed += truth > 0 && counted == 0;
        tally.fold_missed_tessellated += truth > 0 && tessellated.count(x, y) == 0;
      }
  }
  return tally;
}

// check_coverage of each method, with its independent map (Bezier's domain is a triangle).
Tally bezier_coverage(const Mesh& mesh, int width, int height) {
  return check_coverage<BezierPatch>(mesh, width, height, true,
                                     [](const PatchControl& c, const BezierPatch&) { return BezierMap(c); });
}
Tally coons_coverage(const Mesh& mesh, int width, int height) {
  return check_coverage<CoonsPatch>(mesh, width, height, false,
                                    [](const PatchControl& c, const CoonsPatch& p) { return CoonsMap(c, p); });
}

}  // namespace

TEST_CASE("bezier exact coverage matches an independent inversion of each patch", "[bezier]") {
  for (std::uint32_t seed : {21u}) {
    INFO("seed " << seed);
    const Mesh mesh = testing::random_lattice_mesh(40, 30, 60, seed, 10);
    const Tally tally = bezier_coverage(mesh, 40, 30);
    CHECK(tally.ambiguous == 0);
    CHECK(tally.pixels > 1000);
    CHECK(tally.patches - tally.folded > 15);
    CHECK(tally.by_rows > (tally.patches - tally.folded) / 2);
    // Pixels on a patch's boundary (its corners are vertices, so pixel centres) are counted.
    CHECK(tally.on_boundary_counted > 20);
  }
}

TEST_CASE("coons exact coverage matches an independent inversion of each patch", "[coons]") {
  for (std::uint32_t seed : {26u}) {
    INFO("seed " << seed);
    const Mesh mesh = testing::random_lattice_mesh(40, 30, 60, seed, 10);
    const Tally tally = coons_coverage(mesh, 40, 30);
    CHECK(tally.ambiguous == 0);
    CHECK(tally.pixels > 1000);
    CHECK(tally.patches - tally.folded > 15);
    CHECK(tally.by_rows == tally.patches);  // folded ones too: their fold cells bound the fold
    CHECK(tally.folded_by_rows > 5);
    CHECK(tally.on_boundary_counted > 20);
    // Beside the folds: 0 of 3,706 missed. The seed is one whose lattice mesh (its Delaunay
    // diagonals) puts no pixel within the ambiguous band of a patch's boundary (ambiguous == 0),
    // where the independent inversion cannot decide.
    INFO("fold pixels " << tally.fold_pixels << " missed " << tally.fold_missed << " by tessellation "
                        << tally.fold_missed_tessellated);
    CHECK(tally.fold_missed * 700 < tally.fold_pixels);
  }
}

// Patches of the 13,000-vertex encoding of the boat photograph, moved next to the origin,
// that the lattice meshes above never made; each lost a pixel it covers.
// - Triangle 332 (moved 224 pixels left and 264 up): pixel (6, 6) lies 0.23 inside the domain
//   near the Coons corner M = (5, 6), but the start from the row's crossing reaches a
//   solution 0.246 outside it (within near_margin) where the continuation beyond M has folded back
//   over the patch (its Jacobian determinant there has the other sign). That solution must
//   not settle the pixel.
// - Triangle 2031 (moved 344 left, 196 up): at pixel (6, 12) the starts from the crossings
//   fail or land far outside, and so did the grid's nearest points on the domain's corner
//   (1, 1) and side u = 1, where the determinant vanishes: the grid's points lie inside.
// - Triangle 7233 (moved 40 left, 286 up): its side u = 1 runs straight along row 10, from
//   (10, 10) to (8, 10), and the determinant vanishes all along it, so Newton only creeps
//   towards pixel (9, 10) on it from any start but the side's own point there, now the last.
// The mesh of one such patch: its triangle (points 0, 1, 2) and its three edge neighbours,
// values 10, 20, ... at the points.
static Mesh photograph_patch_mesh(const std::vector<Point>& points,
                                  const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  Mesh mesh;
  mesh.points = points;
  for (std::size_t k = 0; k < points.size(); ++k) mesh.values.push_back(10.0 * double(k + 1));
  for (const auto& t : triangles) mesh.triangles.push_back({t});
  mesh.normalize_winding();
  return mesh;
}

TEST_CASE("coons: patches of a photograph's triangulation are covered exactly", "[coons]") {
  struct Case {
    const char* name;
    std::vector<Point> points;  // A, B, C (the triangle), then the apexes across CA, AB and BC
    int width, height;
  };
  const Case cases[] = {
      {"boat 332", {{10, 3}, {10, 7}, {5, 6}, {3, 3}, {12, 4}, {11, 10}}, 16, 14},
      {"boat 2031", {{10, 14}, {6, 10}, {12, 9}, {14, 12}, {5, 12}, {9, 4}}, 20, 20},
      {"boat 7233", {{10, 10}, {10, 9}, {12, 8}, {14, 10}, {8, 10}, {11, 6}}, 20, 16},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const Mesh mesh = photograph_patch_mesh(c.points, {{0, 1, 2}, {2, 3, 0}, {0, 4, 1}, {1, 5, 2}});
    const Tally tally = coons_coverage(mesh, c.width, c.height);
    REQUIRE(tally.patches == 1);
    CHECK(tally.folded == 0);
    CHECK(tally.pixels > 40);
    CHECK(tally.ambiguous == 0);
  }
}

// Bezier patches of the same boat encoding at vertices of degree 3: two corners of the patch
// are one vertex (the apex of two edge neighbours), so the side between them runs out and
// back along a segment, and its turning point (a cusp, where the Jacobian is singular) lands
// on a pixel. Newton does not converge there from any guess nearby; the boundary candidates
// of the tessellation (detail::visit_boundary_side) start that pixel on the cusp.
// Points: A, B, C, then the apexes across CA, AB and BC.
// - Triangle 9330 (moved 430 left, 150 up): apexes across CA and BC at (7, 4), the side
//   b = 0 turns back at pixel (7, 5).
// - Triangle 6779 (moved 3 right, 410 up): apexes across CA and AB at (4, 6), the side
//   c = 0 turns back at pixel (4, 9).
// Both tessellate with 2 subdivisions, so a node lies on the cusp, and that node's exact
// start is kept (BezierPatch::solve). Scaled by 3, triangle 9330 tessellates with 3: no node
// there, and only the start on the cusp itself places pixel (21, 15).
TEST_CASE("bezier: patches of a photograph's triangulation are covered exactly", "[bezier]") {
  struct Case {
    const char* name;
    std::vector<Point> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    int width, height;
    int subdivisions;  // of the tessellation: even puts a node on the cusp, odd does not
  };
  const Case cases[] = {
      {"boat 9330", {{8, 7}, {6, 6}, {7, 6}, {7, 4}, {5, 7}}, {{0, 1, 2}, {2, 3, 0}, {0, 4, 1}, {1, 3, 2}}, 14, 12, 2},
      {"boat 6779", {{4, 12}, {5, 13}, {3, 12}, {4, 6}, {4, 15}}, {{0, 1, 2}, {2, 3, 0}, {0, 3, 1}, {1, 4, 2}}, 10, 18,
       2},
      {"boat 9330 x 3",
       {{24, 21}, {18, 18}, {21, 18}, {21, 12}, {15, 21}},
       {{0, 1, 2}, {2, 3, 0}, {0, 4, 1}, {1, 3, 2}},
       42,
       36,
       3},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const Mesh mesh = photograph_patch_mesh(c.points, c.triangles);
    const Tally tally = bezier_coverage(mesh, c.width, c.height);
    PatchControl control;
    REQUIRE(patch_control(mesh, build_topology(mesh), 0, PixelMapping(c.width, c.height, c.width, c.height), control));
    CHECK(BezierPatch(control).subdivisions() == c.subdivisions);
    REQUIRE(tally.patches == 1);
    CHECK(tally.folded == 0);
    CHECK(tally.pixels > 30);
    CHECK(tally.ambiguous == 0);
  }
}

// Not run by ctest (about half an hour for 13,000 vertices): the same check on every patch
// of a triangulation file's first mesh, e.g.
//   PATCH_COVERAGE_TRI=boat.tri build/bin/test_patches "[.survey]"
// It stops at the first pixel of an unfolded patch counted wrongly and prints the tallies.
TEST_CASE("survey: coverage of every patch of a triangulation file", "[.survey]") {
  const char* file = std::getenv("PATCH_COVERAGE_TRI");
  if (!file) FAIL("set PATCH_COVERAGE_TRI to a .tri file");
  const Triangulation tri = read_tri_file(file);
  const Mesh& mesh = tri.layers.at(0);
  auto report = [](const char* method, const Tally& tally) {
    WARN(method << ": patches " << tally.patches << ", folded " << tally.folded << ", pixels " << tally.pixels
                << ", in folded patches " << tally.fold_pixels << " of which missed " << tally.fold_missed
                << ", ambiguous " << tally.ambiguous);
  };
  report("coons", coons_coverage(mesh, tri.width, tri.height));
  report("bezier", bezier_coverage(mesh, tri.width, tri.height));
}

// Patches the image cuts (the lattice mesh moved 13 pixels left and 7 up) are still covered
// exactly: a row's nearest crossing may then lie far from its first pixel, and where a start
// reaches a solution far outside the domain (patch/scan.h, near_margin) the other starts are tried
// (without that, a Coons patch here misses a pixel).
TEST_CASE("patches cut by the image's edge are covered exactly", "[bezier][coons]") {
  Mesh mesh = testing::random_lattice_mesh(40, 30, 60, 23, 10);
  for (Point& p : mesh.points) p.x -= 13, p.y -= 7;
  const Tally bezier = bezier_coverage(mesh, 27, 23);
  const Tally coons = coons_coverage(mesh, 27, 23);
  CHECK(bezier.pixels > 500);
  CHECK(coons.pixels > 500);
  INFO("coons fold pixels " << coons.fold_pixels << " missed " << coons.fold_missed);
  CHECK(coons.fold_missed * 700 < coons.fold_pixels);
}

// The trap of patch/raster.h: whether a pixel on a patch's boundary counts must not hang on
// the last bits of Newton's result. Starting each solve from a guess moved by up to 1e-3
// gives other last bits; the decisions must not change, and the parameters agree to a tenth
// of domain_tolerance. (A start may also lead to another preimage where a patch folds over
// itself: a different point, not different last bits; those are counted and must be rare.)
TEST_CASE("patch membership does not depend on the solver's start", "[bezier][coons]") {
  const Mesh mesh = testing::random_lattice_mesh(64, 48, 200, 31, 20);
  const Topology topo = build_topology(mesh);
  const PixelMapping map(64, 48, 64, 48);
  std::vector<detail::MicroVertex> nodes;
  std::vector<detail::FoldCell> folds;
  detail::ScanScratch scan;
  // Counts per patch and pixel (the tessellation may give a pixel more than one start).
  int boundary = 0, candidates = 0, singular = 0, other_root = 0, patch_number = 0;
  std::vector<int> seen(64 * 48, -1);
  // Pixel (x, y) with start (s, t) as the renderer gets it, solved from there and from starts
  // moved by up to 1e-3; false where the first solve fails, else (s, t) is its solution.
  auto examine = [&](const auto& patch, int x, int y, double& s, double& t) {
    double s0 = s, t0 = t;
    if (!patch.solve(x, y, s0, t0)) return false;
    const double start_s = s, start_t = t;
    s = s0, t = t0;
    const bool first = seen[y * 64 + x] != patch_number;
    seen[y * 64 + x] = patch_number;
    candidates += first;
    boundary += first && std::fabs(patch.outside_by(s0, t0)) < 1e-10;
    // Where the Jacobian is nearly singular (the Coons corner M) Newton converges slowly
    // from elsewhere; the renderer starts such a pixel on the node itself.
    double px, py, xs, xt, ys, yt;
    patch.position(s0, t0, px, py, xs, xt, ys, yt);
    if (!(std::fabs(xs * yt - xt * ys) >= 1e-2 * std::hypot(xs, ys) * std::hypot(xt, yt) && xs * yt - xt * ys != 0)) {
      // Apart from the patch's corners (the Coons corner M is on a pixel for every patch of
      // a lattice mesh, and always singular), such pixels must be rare.
      auto at_end = [](double k) { return std::fabs(k) < 1e-12 || std::fabs(k - 1) < 1e-12; };
      singular += first && !(at_end(s0) && at_end(t0));
      return true;
    }
    for (double ds : {-1e-3, 1e-3, 3.7e-4}) {
      double s1 = start_s + ds, t1 = start_t - ds / 2;
      if (!patch.solve(x, y, s1, t1)) continue;
      INFO("pixel " << x << ", " << y << " (" << s0 << ", " << t0 << ") vs (" << s1 << ", " << t1 << ") det "
                    << (xs * yt - xt * ys) / (std::hypot(xs, ys) * std::hypot(xt, yt)));
      if (std::fabs(s1 - s0) + std::fabs(t1 - t0) > 1e-3) {
        ++other_root;
        continue;
      }
      REQUIRE(patch.in_domain(s0, t0) == patch.in_domain(s1, t1));
      REQUIRE(std::fabs(s1 - s0) + std::fabs(t1 - t0) < detail::domain_tolerance / 10);
    }
    return true;
  };
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    PatchControl control;
    if (!patch_control(mesh, topo, t, map, control)) continue;
    // Bezier: the candidates and starts of the tessellation (Bezier patches that may fold).
    const BezierPatch bezier(control);
    ++patch_number;
    bezier.tessellate(64, 48, nodes, [&](int x, int y, double s, double t) { examine(bezier, x, y, s, t); });
    // Both: those of the rows (Bezier patches that do not fold, every Coons patch).
    auto by_rows = [&](const auto& patch) {
      if (!patch.fold_cells(folds)) return;
      ++patch_number;
      detail::scan_rows(patch, folds, 64, 48, scan, [&](int x, int y, double& s, double& t) {
        return examine(patch, x, y, s, t) ? detail::placed_at(patch, s, t) : detail::Placed::none;
      });
    };
    by_rows(bezier);
    by_rows(CoonsPatch(control));
  }
  CHECK(candidates > 10000);
  CHECK(boundary > 200);
  CHECK(singular < candidates / 100);
  CHECK(other_root < candidates / 1000);
}

// The fold cells of a Coons patch (patch/scan.h) must hold its fold: where the Jacobian
// determinant changes sign between neighbouring samples of a fine grid, the image there lies
// in some cell's box (widened by the image of a grid step), and a patch without cells has
// no sign change at all.
TEST_CASE("coons fold cells hold the fold", "[coons]") {
  const Mesh mesh = testing::random_lattice_mesh(64, 48, 200, 33, 20);
  const Topology topo = build_topology(mesh);
  const PixelMapping map(64, 48, 64, 48);
  std::vector<detail::FoldCell> cells;
  int folded = 0, crossings = 0;
  const int n = 48;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    PatchControl control;
    if (!patch_control(mesh, topo, t, map, control)) continue;
    const CoonsPatch patch(control);
    REQUIRE(patch.fold_cells(cells));
    folded += !cells.empty();
    auto det = [&](int i, int j) { return detail::jacobian_determinant(patch, double(i) / n, double(j) / n); };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
          if (i + di > n || j + dj > n) continue;
          if (!((det(i, j) > 0 && det(i + di, j + dj) < 0) || (det(i, j) < 0 && det(i + di, j + dj) > 0))) continue;
          ++crossings;
          INFO("patch " << t << " between (" << i << ", " << j << ") and (" << i + di << ", " << j + dj << ")");
          REQUIRE(!cells.empty());
          const Point a = patch.position(double(i) / n, double(j) / n);
          const Point b = patch.position(double(i + di) / n, double(j + dj) / n);
          const double reach = std::hypot(a.x - b.x, a.y - b.y);
          bool held = false;
          for (const detail::FoldCell& c : cells)
            held = held ||
                   (a.x >= c.x_lo - reach && a.x <= c.x_hi + reach && a.y >= c.y_lo - reach && a.y <= c.y_hi + reach);
          REQUIRE(held);
        }
  }
  CHECK(folded > 10);
  CHECK(crossings > 100);
}
