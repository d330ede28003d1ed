// SPDX-License-Identifier: MIT
// The bilinear set-up of scan-path triangles on targets without a 128-bit type
// (BilinearChannel::setup_from_vertex0, Mod32RoundingDivider): v_ref taken from vertex 0's value
// must be the same quotient, modulo 2^32, as the rounded division of 2^8 sum v E(xr, yr) by the
// doubled area, and the gradients those of 2^8 sum v a and 2^8 sum v b, for every triangle the
// scan path of such a target takes (pixel box below 15 x 15, values q8_8 below 2^16).
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>

#include "arith.h"
#include "interpolate.h"

using namespace tristream::core::detail;

namespace {

constexpr int S = 4;                        // config::subpixel_bits of the default configuration
constexpr std::int32_t spread = (15 + 1) << S;  // vertex coordinates of a box below 15 pixels differ by less

std::int64_t floor_div64(std::int64_t n, std::int64_t d) {
  const std::int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
std::uint32_t rounded(std::int64_t n, std::int64_t d) { return std::uint32_t(floor_div64(2 * n + d, 2 * d)); }

struct Case {
  std::int32_t x[3], y[3];
  std::int32_t v[3];
};

// Compares setup_from_vertex0 with the exact roundings; false (and nothing checked) for a triangle
// that is not counter-clockwise. wide: any triangle of the coordinate budget, with the divider of
// 64-bit numerators the span path takes (PreinvRoundingDivider, RoundingDivider past 2^31).
bool check(const Case& t, bool wide = false) {
  const std::int64_t area2 = std::int64_t(t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) -
                             std::int64_t(t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
  if (area2 <= 0) return false;
  if (!wide) REQUIRE(2 * area2 <= std::int64_t(Mod32RoundingDivider::max_divisor));
  const std::int32_t xr = t.x[0] >> S, yr = t.y[0] >> S;  // floor: coordinates are nonnegative
  std::int32_t a[3], b[3];
  std::int64_t e_ref[3];
  for (int k = 0; k < 3; ++k) {
    const int n = (k + 1) % 3;
    const std::int32_t dx = t.x[n] - t.x[k], dy = t.y[n] - t.y[k];
    a[k] = -dy * (1 << S);
    b[k] = dx * (1 << S);
    e_ref[k] = std::int64_t(-dy) * ((xr << S) - t.x[k]) + std::int64_t(dx) * ((yr << S) - t.y[k]);
  }
  BilinearChannel ch;
  const auto edges = BilinearChannel::VertexZeroEdges::of<S>(a, b, (xr << S) - t.x[0], (yr << S) - t.y[0]);
  if (!wide) {
    ch.setup_from_vertex0(edges, Mod32RoundingDivider(std::int32_t(area2)), t.v);
  } else if (PreinvRoundingDivider::fits(area2)) {
    ch.setup_from_vertex0(edges, PreinvRoundingDivider(area2), t.v);
  } else {
    ch.setup_from_vertex0(edges, RoundingDivider(area2), t.v);
  }
  // E_k / area2 weighs vertex k + 2.
  std::int64_t nx = 0, ny = 0, nv = 0;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t w = t.v[(k + 2) % 3];
    nx += w * a[k];
    ny += w * b[k];
    nv += w * e_ref[k];
  }
  INFO("vertices (" << t.x[0] << "," << t.y[0] << ") (" << t.x[1] << "," << t.y[1] << ") (" << t.x[2] << ","
                    << t.y[2] << ") values " << t.v[0] << " " << t.v[1] << " " << t.v[2]);
  REQUIRE(ch.dvdx == rounded(nx * 256, area2));
  REQUIRE(ch.dvdy == rounded(ny * 256, area2));
  REQUIRE(ch.v_ref == rounded(nv * 256, area2));
  return true;
}

// check in the given vertex order, or else with vertices 1 and 2 swapped; 1 if either was checked.
int check_either_order(Case t, bool wide = false) {
  if (check(t, wide)) return 1;
  std::swap(t.x[1], t.x[2]);
  std::swap(t.y[1], t.y[2]);
  return check(t, wide) ? 1 : 0;
}

}  // namespace

TEST_CASE("setup_from_vertex0 equals the rounded divisions of the edge values at the reference pixel") {
  std::mt19937 rng(23);
  int checked = 0;
  SECTION("random triangles anywhere in the box's spread, with any values") {
    for (int i = 0; i < 200000; ++i) {
      Case t;
      const std::int32_t bx = std::int32_t(rng() % 4096), by = std::int32_t(rng() % 4096);
      for (int k = 0; k < 3; ++k) {
        t.x[k] = bx + std::int32_t(rng() % spread);
        t.y[k] = by + std::int32_t(rng() % spread);
        t.v[k] = std::int32_t(rng() % 65536);
      }
      checked += check_either_order(t);
    }
    CHECK(checked > 190000);
  }
  SECTION("any triangle of the coordinate budget, with the span path's dividers") {
    constexpr std::int32_t budget = 4096 << S;  // drawing positions below max_dimension 2^S
    for (int i = 0; i < 200000; ++i) {
      Case t;
      const std::int32_t reach = std::int32_t(1) << (1 + rng() % 16);  // slivers to the whole budget
      const std::int32_t bx = std::int32_t(rng() % std::uint32_t(budget - reach + 1));
      const std::int32_t by = std::int32_t(rng() % std::uint32_t(budget - reach + 1));
      for (int k = 0; k < 3; ++k) {
        t.x[k] = bx + std::int32_t(rng() % std::uint32_t(reach));
        t.y[k] = by + std::int32_t(rng() % std::uint32_t(reach));
        t.v[k] = (rng() & 7) ? std::int32_t(rng() % 65536) : std::int32_t((rng() & 1) * 65535);
      }
      checked += check_either_order(t, true);
    }
    CHECK(checked > 150000);
    // The largest triangles (doubled areas past 2^31: RoundingDivider).
    for (int mask = 0; mask < 8; ++mask) {
      const std::int32_t v[2] = {0, 65535};
      Case t{{0, budget - 1, 0}, {0, 0, budget - 1}, {v[mask & 1], v[(mask >> 1) & 1], v[(mask >> 2) & 1]}};
      REQUIRE(check(t, true));
    }
  }
  SECTION("the extremes: vertices at the corners of the spread, values 0 and 65535, slivers") {
    const std::int32_t ends[] = {0, 1, spread / 2, spread - 2, spread - 1};
    const std::int32_t values[] = {0, 65535};
    for (std::int32_t x1 : ends)
      for (std::int32_t y1 : ends)
        for (std::int32_t x2 : ends)
          for (std::int32_t y2 : ends)
            for (int mask = 0; mask < 8; ++mask)
              for (std::int32_t offset : {0, 7, 15}) {
                Case t{{offset, offset + x1, offset + x2},
                       {offset, offset + y1, offset + y2},
                       {values[mask & 1], values[(mask >> 1) & 1], values[(mask >> 2) & 1]}};
                checked += check_either_order(t);
              }
    CHECK(checked > 1000);
  }
}
