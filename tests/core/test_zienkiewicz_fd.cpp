// SPDX-License-Identifier: MIT
// Forward differencing of the zienkiewicz cubic along rows (detail/interpolate.h): the helpers
// against 128-bit arithmetic, every forward-differenced value against the restart's value plus the
// exact change of the same cubic (within the bound of docs/FIXED_POINT.md), and values
// independent of where a span starts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "arith.h"
#include "edge.h"
#include "interpolate.h"

using namespace tristream::core;
using namespace tristream::core::detail;

namespace {

__extension__ typedef __int128 i128;

constexpr int32_t R = zienkiewicz_fd_restart;

// The ten coefficients p00, p01, p02, p03, p10, p11, p12, p20, p21, p30, whatever the layout of
// ZienkiewiczChannel (int64 fields, or with TS_USE_INT128=0 int32 ones and a wide fallback).
using Coefficients = std::array<int64_t, 10>;
Coefficients coefficients(const ZienkiewiczChannel& z) {
  const ZienkiewiczChannel::WideCoefficients c = z.coefficients();
  return {c.p00, c.p01, c.p02, c.p03, c.p10, c.p11, c.p12, c.p20, c.p21, c.p30};
}
void set_coefficients(ZienkiewiczChannel& z, const Coefficients& p) {
  z.set_coefficients({p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], p[9]});
}

// Exact P(a, b) * 2^98 (p in 2^-8, a and b in 2^-30 grey units): every term below 2^122.
i128 exact_p(const ZienkiewiczChannel& z, int32_t a, int32_t b) {
  const Coefficients c = coefficients(z);
  const int64_t p[4][4] = {{c[0], c[1], c[2], c[3]}, {c[4], c[5], c[6], 0}, {c[7], c[8], 0, 0}, {c[9], 0, 0, 0}};
  i128 sum = 0;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j) {
      i128 t = p[i][j];
      for (int k = 0; k < i; ++k) t *= a;
      for (int k = 0; k < j; ++k) t *= b;
      for (int k = 0; k < 3 - i - j; ++k) t *= i128(1) << 30;
      sum += t;
    }
  return sum;
}

// The documented bound, in units of 2^-18 grey, at m steps after a restart.
double fd_bound(int32_t m) { return double(zienkiewicz_fd_bound_tenths(m)) / 10; }

struct RowCase {
  ZienkiewiczChannel ch[3];
  uint32_t a = 0, b = 0, da = 0, db = 0;  // q2_30 at the row's first covered pixel, and steps
  int32_t length = 0;                     // covered pixels
};

// A random triangle of the given size (pixels) with random values and gradients (q19_12, up to
// max_gradient in magnitude); its longest covered row. False when no row has two pixels or the
// triangle is outside the forward-difference budget.
bool random_row(std::mt19937& rng, int32_t size, int32_t max_gradient, RowCase* rc) {
  constexpr int S = config::subpixel_bits;
  std::uniform_int_distribution<int32_t> pos(0, size << S);
  int32_t x[3], y[3];
  for (int k = 0; k < 3; ++k) x[k] = pos(rng), y[k] = pos(rng);
  int64_t area2 = (int64_t(x[1]) - x[0]) * (int64_t(y[2]) - y[0]) - (int64_t(y[1]) - y[0]) * (int64_t(x[2]) - x[0]);
  if (area2 == 0) return false;
  if (area2 < 0) std::swap(x[1], x[2]), std::swap(y[1], y[2]), area2 = -area2;
  Edge e[3];
  for (int k = 0; k < 3; ++k) e[k] = make_edge(x[k], y[k], x[(k + 1) % 3], y[(k + 1) % 3], true);
  const RoundingDivider by_area2(area2);
  BarycentricStepper steps;
  steps.setup(e, by_area2, x[0] >> S, y[0] >> S);
  int32_t best_y = 0, best_xs = 0, best_len = 0;
  for (int32_t row = 0; row <= size; ++row) {
    int32_t xs = -1, len = 0;
    for (int32_t px = 0; px <= size; ++px) {
      bool in = true;
      for (int k = 0; k < 3; ++k) in = in && e[k].exact_at(px, row) >= 0;
      if (in && xs < 0) xs = px;
      if (in) len = px - xs + 1;
    }
    if (len > best_len) best_len = len, best_xs = xs, best_y = row;
  }
  if (best_len < 2) return false;
  int32_t dx[3], dy[3], grads[6];
  for (int k = 0; k < 3; ++k) dx[k] = x[(k + 1) % 3] - x[k], dy[k] = y[(k + 1) % 3] - y[k];
  std::uniform_int_distribution<int32_t> value(0, 255 * 256), gradient(-max_gradient, max_gradient);
  if (!ZienkiewiczChannel::steps_fit_rows(int32_t(steps.dadx), int32_t(steps.dbdx))) return false;
  for (auto& ch : rc->ch) {
    const int32_t v3[3] = {value(rng), value(rng), value(rng)};
    for (int32_t& g : grads) g = gradient(rng);
    ch.setup(dx, dy, v3, grads);
    if (!ch.setup_rows(int32_t(steps.dadx), int32_t(steps.dbdx))) return false;
  }
  steps.at(best_xs, best_y, &rc->a, &rc->b);
  rc->da = steps.dadx;
  rc->db = steps.dbdx;
  rc->length = best_len;
  return true;
}

// Values of pixels n0..n1 of the row (2^-18 grey, no bias, read as int32), channel c.
std::vector<int32_t> row_values(const RowCase& rc, int c, int32_t n0, int32_t n1) {
  std::vector<int32_t> out;
  zienkiewicz_row_chunks<3>(rc.ch, rc.a, rc.b, rc.da, rc.db, n0, n1, 0, [&](int32_t n, int32_t end, CubicSteps* s) {
    for (; n <= end; ++n) {
      REQUIRE(n == n0 + int32_t(out.size()));
      out.push_back(int32_t(s[c].v));
      for (int k = 0; k < 3; ++k) s[k].step();
    }
  });
  return out;
}

// A restart's value is within this many units of 2^-18 grey of the cubic at its weights (nine
// floors of units of 2^-14: docs/FIXED_POINT.md).
constexpr double restart_bound = double(zienkiewicz_fd_value_bound_tenths) / 10;

// Every pixel of the row against its restart's value plus the exact change of the cubic from the
// restart, and each restart's value against the cubic; returns the largest error in units of
// 2^-18 grey, and checks the bounds.
double check_row(const RowCase& rc, double* worst_ratio) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    const std::vector<int32_t> v = row_values(rc, c, 0, rc.length - 1);
    for (int32_t n = 0; n < rc.length; ++n) {
      const int32_t start = n & ~(R - 1);
      auto at = [&](int32_t k, int32_t* a, int32_t* b) {
        *a = int32_t(rc.a + rc.da * uint32_t(k)), *b = int32_t(rc.b + rc.db * uint32_t(k));
      };
      int32_t an, bn, as, bs;
      at(n, &an, &bn);
      at(start, &as, &bs);
      // exact_p is P * 2^98 in grey: 2^80 of it a unit of 2^-18.
      REQUIRE(std::abs(double(i128(v[start]) * (i128(1) << 80) - exact_p(rc.ch[c], as, bs)) / 0x1p80) <= restart_bound);
      const i128 change = exact_p(rc.ch[c], an, bn) - exact_p(rc.ch[c], as, bs);
      const i128 diff = (i128(v[n]) - v[start]) * (i128(1) << 80) - change;
      const double units = std::abs(double(diff) / 0x1p80);
      worst = std::max(worst, units);
      if (worst_ratio) *worst_ratio = std::max(*worst_ratio, units / fd_bound(n - start));
      REQUIRE(units <= fd_bound(n - start));
    }
  }
  return worst;
}

}  // namespace

TEST_CASE("mul_q30, mul_q32 and Wide equal 128-bit arithmetic") {
  std::mt19937_64 rng(3);
  const int64_t xs[] = {0, 1, -1, (int64_t(1) << 61) - 1, -(int64_t(1) << 61) + 1, 0x123456789abcdefll >> 4};
  const int32_t ys[] = {0, 1, -1, INT32_MAX, INT32_MIN, 1 << 30, -(1 << 30)};
  for (int64_t x : xs)
    for (int32_t y : ys) {
      CHECK(mul_q30_portable(x, y) == int64_t((i128(x) * y) >> 30));
      CHECK(mul_q30(x, y) == mul_q30_portable(x, y));
      CHECK(SplitProduct(x, y).high == int64_t((i128(x) * y) >> 32));
      CHECK(mul_q32(x, y) == SplitProduct(x, y).high);
    }
  for (int i = 0; i < 200000; ++i) {
    const int64_t x = int64_t(rng()) >> (3 + rng() % 60);
    const int32_t y = int32_t(uint32_t(rng())) >> (rng() % 31);
    REQUIRE(mul_q30_portable(x, y) == int64_t((i128(x) * y) >> 30));
    REQUIRE(mul_q30(x, y) == mul_q30_portable(x, y));
    REQUIRE(SplitProduct(x, y).high == int64_t((i128(x) * y) >> 32));
    REQUIRE(mul_q32(x, y) == SplitProduct(x, y).high);
    const int64_t a = int64_t(rng()) >> (rng() % 63), b = int64_t(rng()) >> (rng() % 63);
    const int64_t c = int64_t(rng()) >> (2 + rng() % 61), d = int64_t(rng()) >> (2 + rng() % 61);
    const Wide w = Wide::product(a, b) + Wide::product(c, d);
    const i128 exact = i128(a) * b + i128(c) * d;
    REQUIRE(w.lo == uint64_t(exact));
    REQUIRE(w.hi == uint64_t(exact >> 64));
    const int s = 64 + int(rng() % 62);
    const i128 rounded = (exact + (i128(1) << (s - 1))) >> s;
    REQUIRE(w.round_shift(s) == int64_t(rounded));
  }
}

TEST_CASE("CubicSteps::skip equals repeated steps") {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 4000; ++i) {
    CubicSteps s{uint32_t(rng()), uint32_t(rng()), uint32_t(rng()), uint32_t(rng())};
    const uint32_t k = uint32_t(rng() % CubicSteps::max_skip);
    CubicSteps t = s;
    for (uint32_t j = 0; j < k; ++j) t.step();
    s.skip(k);
    REQUIRE(s.v == t.v);
    REQUIRE(s.d1 == t.d1);
    REQUIRE(s.d2 == t.d2);
    REQUIRE(s.d3 == t.d3);
  }
}

// The degree of coefficient k of Coefficients (p00, p01, p02, p03, p10, p11, p12, p20, p21, p30).
constexpr int degree[10] = {0, 1, 2, 3, 1, 2, 3, 2, 3, 3};

TEST_CASE("eval_narrow equals eval_wide within its coefficient budget") {
  std::mt19937_64 rng(11);
  // The budget is on the scaled coefficients s = p 4^degree (s00 with the rounding bias): each in
  // [-S, S).
  constexpr int64_t max = ZienkiewiczChannel::max_narrow_coefficient, bias = ZienkiewiczChannel::rounding_bias;
  auto lo = [](int k) { return -(max >> (2 * degree[k])) - (k == 0 ? bias : 0); };
  auto hi = [](int k) { return (max >> (2 * degree[k])) - 1 - (k == 0 ? bias : 0); };
  ZienkiewiczChannel z{};
  Coefficients p{};
  // Any int32 q2_30 weights (the shader's modular sums read as int32), the extremes included.
  const int32_t extremes[] = {INT32_MIN, INT32_MAX, 1 << 30, -(1 << 30), -1, 0, 1};
  for (int i = 0; i < 200000; ++i) {
    for (int k = 0; k < 10; ++k) {
      const uint64_t r = rng();
      p[k] = r % 3 == 0 ? (r & 8 ? hi(k) : lo(k)) : lo(k) + int64_t(r % uint64_t(hi(k) - lo(k) + 1));
    }
    set_coefficients(z, p);
    REQUIRE(z.fits_narrow());
    const int32_t a = i % 3 ? int32_t(uint32_t(rng())) : extremes[rng() % 7];
    const int32_t b = i % 5 ? int32_t(uint32_t(rng())) : extremes[rng() % 7];
    REQUIRE(int64_t(z.eval32(a, b)) == z.eval_wide(a, b));
    REQUIRE(int64_t(z.eval_narrow(ZienkiewiczChannel::Weights::of(uint32_t(a), uint32_t(b)))) == z.eval_wide(a, b));
  }
  // All coefficients at a limit with the same sign: the largest partial sums.
  for (const bool top : {true, false})
    for (int32_t w : extremes) {
      for (int k = 0; k < 10; ++k) p[k] = top ? hi(k) : lo(k);
      set_coefficients(z, p);
      REQUIRE(z.fits_narrow());
      const int32_t v = int32_t(0u - uint32_t(w));  // -w, modulo 2^32
      INFO("weights " << w << ", " << v);
      REQUIRE(int64_t(z.eval32(w, w)) == z.eval_wide(w, w));
      REQUIRE(int64_t(z.eval32(w, v)) == z.eval_wide(w, v));
    }
  for (int k = 0; k < 10; ++k) {
    const int64_t keep = p[k];
    p[k] = hi(k) + 1;
    set_coefficients(z, p);
    CHECK_FALSE(z.fits_narrow());
    p[k] = lo(k) - 1;
    set_coefficients(z, p);
    CHECK_FALSE(z.fits_narrow());
    p[k] = keep;
  }
}

TEST_CASE("eval_wide equals the portable Horner steps (mul_q32) for coefficients of any size") {
  // Where a 128-bit product exists eval_wide (and eval_narrow, for every triangle) takes the high
  // word of (w 2^32) t; Cortex-M takes mul_q32's two 32 x 32 -> 64 products: the same integers.
  std::mt19937_64 rng(17);
  ZienkiewiczChannel z{};
  Coefficients p{};
  for (int i = 0; i < 200000; ++i) {
    for (int64_t& q : p) q = int64_t(rng()) >> (12 + rng() % 52);  // |p| < 2^52
    set_coefficients(z, p);
    REQUIRE(coefficients(z) == p);  // stored (scaled, in int32 or int64) without loss
    const int32_t a = int32_t(uint32_t(rng())), b = int32_t(uint32_t(rng()));
    const ZienkiewiczChannel::ScaledCoefficients c = z.scaled();
    auto h = [](int32_t w, int64_t t, int64_t s) { return s + SplitProduct(t, w).high; };
    const int64_t pb = h(b, h(b, h(b, c.s03, c.s02), c.s01), c.s00);
    const int64_t pa = h(a, h(a, c.s30, h(b, c.s21, c.s20)), h(b, h(b, c.s12, c.s11), c.s10));
    REQUIRE(z.eval_wide(a, b) == h(a, pa, pb));
    if (ZienkiewiczChannel::narrow_always) REQUIRE(int64_t(z.eval_narrow(a, b)) == z.eval_wide(a, b));
  }
}

TEST_CASE("eval_wide is within 3 units of 2^-8 grey below the exact cubic for weights in [0, 1]") {
  // docs/FIXED_POINT.md: each step's floor is below one unit of its scale, the scales 4^degree
  // times the value's; for |a|, |b| <= 1 the errors sum to below 3 units of the value, all downward.
  std::mt19937_64 rng(13);
  ZienkiewiczChannel z{};
  Coefficients p{};
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const int bits = 8 + int(rng() % 22);  // exact_p within i128
    for (int64_t& q : p) q = int64_t(rng() % (uint64_t(2) << bits)) - (int64_t(1) << bits);
    set_coefficients(z, p);
    const int32_t one = 1 << 30;
    int32_t a = int32_t(rng() % (uint32_t(one) + 1)), b = int32_t(rng() % (uint32_t(one) + 1));
    if (i % 7 == 0) a = i % 2 ? one : 0;
    if (i % 11 == 0) b = i % 3 ? one : 0;
    // Exact P 2^90 (value in 2^-8 grey) against eval_wide (less the rounding bias) 2^90.
    const i128 diff = exact_p(z, a, b) - (i128(z.eval_wide(a, b) - ZienkiewiczChannel::rounding_bias) << 90);
    REQUIRE(diff >= 0);
    REQUIRE(diff < i128(3) << 90);
    worst = std::max(worst, double(diff) / double(i128(1) << 90));
  }
  CHECK(worst > 2);  // the bound is not loose by much
}

TEST_CASE("the coefficients in 32 bits equal those in 64 bits within max_narrow_derivative") {
  std::mt19937_64 rng(19);
  constexpr int32_t max = ZienkiewiczChannel::max_narrow_derivative;
  for (int i = 0; i < 200000; ++i) {
    int32_t u[9];
    for (int k = 0; k < 9; ++k) {
      const bool value = k % 3 == 0;  // u1, u4, u7: q8_8 vertex values
      const uint64_t r = rng();
      u[k] = value ? int32_t(r % 65536) : (r % 4 == 0 ? (r & 16 ? max : -max) : int32_t(r % (2u * max + 1)) - max);
    }
    ZienkiewiczChannel n{}, w{};
    n.expand<int32_t>(u[0], u[1], u[2], u[3], u[4], u[5], u[6], u[7], u[8]);
    w.expand<int64_t>(u[0], u[1], u[2], u[3], u[4], u[5], u[6], u[7], u[8]);
    REQUIRE(n.fits_narrow());
    REQUIRE(coefficients(n) == coefficients(w));
  }
}

TEST_CASE("setup_narrow takes exactly the triangles whose edge derivatives are in [-2^18, 2^18)") {
  // Its test on the words of the lifted rounding sums against the derivatives themselves, with
  // gradients at the budget's edges (u = +-2^18 and one step inside) in every slot.
  std::mt19937_64 rng(41);
  constexpr int down = config::subpixel_bits + config::gradient_frac_bits - q24_8::frac_bits;
  constexpr int64_t max = ZienkiewiczChannel::max_narrow_derivative;
  int taken = 0, refused = 0;
  for (int i = 0; i < 100000; ++i) {
    int32_t dx[3], dy[3], v3[3], g[6];
    for (int k = 0; k < 3; ++k) {
      dx[k] = int32_t(rng() % 64) - 32;
      dy[k] = int32_t(rng() % 64) - 32;
      v3[k] = int32_t(rng() % 65536);
    }
    for (int32_t& gk : g) gk = (int32_t(rng() % (1u << 28)) - (1 << 27)) >> int(8 + rng() % 12);
    if (i % 2) {
      // One derivative at the budget's edge, the others 0: edge e = (1, 0), the other edges
      // (0, 0), its vertex's gx chosen so that the rounded derivative is -max - 1, -max, max - 1
      // or max.
      const int slot = int(rng() % 6), e = slot / 2 == 0 ? 0 : (slot / 2 == 1 ? 1 : 2);
      const int v = slot == 0 ? 0 : slot == 1 ? 1 : slot == 2 ? 1 : slot == 3 ? 2 : slot == 4 ? 2 : 0;
      const int64_t targets[4] = {-max - 1, -max, max - 1, max};
      const int64_t u = targets[rng() % 4];
      for (int k = 0; k < 3; ++k) dx[k] = dy[k] = 0;
      dx[e] = 1;
      g[2 * v] = int32_t(u << down), g[2 * v + 1] = int32_t(rng() % 7) - 3;
    }
    auto dot = [&](int e, int v) {
      return (int64_t(dx[e]) * g[2 * v] + int64_t(dy[e]) * g[2 * v + 1] + (int64_t(1) << (down - 1))) >> down;
    };
    const bool small =
        ZienkiewiczChannel::narrow_derivatives(dot(0, 0), dot(0, 1), dot(1, 1), dot(1, 2), dot(2, 2), dot(2, 0));
    ZienkiewiczChannel z{};
    INFO("case " << i);
    REQUIRE(z.setup_narrow(dx, dy, v3, g) == small);
    if (small) {
      ZienkiewiczChannel w{};
      w.expand<int64_t>(v3[0], dot(0, 0), dot(0, 1), v3[1], dot(1, 1), dot(1, 2), v3[2], dot(2, 2), dot(2, 0));
      REQUIRE(coefficients(z) == coefficients(w));
    }
    (small ? taken : refused) += 1;
  }
  CHECK(taken > 20000);
  CHECK(refused > 20000);
}

TEST_CASE("setup takes the 32-bit coefficients only for small edge derivatives, with the same result") {
  std::mt19937_64 rng(37);
  int narrow_cases = 0, beyond_int32_cases = 0;
  for (int i = 0; i < 20000; ++i) {
    // Edges up to 2^15 (fx), gradients up to 2^27 (q19_12): derivatives from tiny to 2^35.
    const int shift = int(rng() % 16);
    int32_t dx[3], dy[3], v3[3], g[6];
    for (int k = 0; k < 3; ++k) {
      dx[k] = (int32_t(rng() % 65536) - 32768) >> shift;
      dy[k] = (int32_t(rng() % 65536) - 32768) >> shift;
      v3[k] = int32_t(rng() % 65536);
    }
    for (int32_t& gk : g) gk = (int32_t(rng() % (1u << 28)) - (1 << 27)) >> int(rng() % 20);
    ZienkiewiczChannel z{};
    const bool narrow = z.setup<true>(dx, dy, v3, g);
    ZienkiewiczChannel z64{};
    // setup's result: whether eval_narrow evaluates the triangle (every one where it is exact for
    // any coefficients, else within fits_narrow), the same from either expansion.
    REQUIRE(z64.setup<false>(dx, dy, v3, g) == narrow);
    REQUIRE(narrow == (ZienkiewiczChannel::narrow_always || z.fits_narrow()));
    narrow_cases += z.fits_narrow();
    // The same coefficients from the derivatives in 64 bits.
    constexpr int down = config::subpixel_bits + config::gradient_frac_bits - q24_8::frac_bits;
    auto dot = [&](int e, int v) {
      return (int64_t(dx[e]) * g[2 * v] + int64_t(dy[e]) * g[2 * v + 1] + (int64_t(1) << (down - 1))) >> down;
    };
    ZienkiewiczChannel w{};
    w.expand<int64_t>(v3[0], dot(0, 0), dot(0, 1), v3[1], dot(1, 1), dot(1, 2), v3[2], dot(2, 2), dot(2, 0));
    REQUIRE(coefficients(z) == coefficients(w));
    REQUIRE(coefficients(z64) == coefficients(w));
    // Coefficients beyond int32 (whose scaled ones are kept apart where the fields are int32:
    // TS_USE_INT128=0) are outside both 32-bit budgets, and eval_wide is the same Horner scheme
    // in either layout.
    const Coefficients pw = coefficients(w);
    bool beyond_int32 = false;
    for (const int64_t q : pw) beyond_int32 |= q < INT32_MIN || q > INT32_MAX;
    beyond_int32_cases += beyond_int32;
    if (beyond_int32) {
      CHECK_FALSE(z.setup_rows(1 << 20, 1 << 20));
      CHECK_FALSE(z.fits_narrow());
    }
    const ZienkiewiczChannel::ScaledCoefficients c = w.scaled();
    for (int j = 0; j < 4; ++j) {
      const int32_t a = int32_t(uint32_t(rng())), b = int32_t(uint32_t(rng()));
      REQUIRE(z.eval_wide(a, b) == ZienkiewiczChannel::horner(c, a, b));
      REQUIRE(z64.eval_wide(a, b) == ZienkiewiczChannel::horner(c, a, b));
    }
  }
  // Narrow and wide triangles both occur, and coefficients beyond int32.
  CHECK(narrow_cases > 2000);
  CHECK(narrow_cases < 18000);
  CHECK(beyond_int32_cases > 100);
}

TEST_CASE("setup_rows and steps_at equal their definitions in 128-bit arithmetic") {
  // docs/FIXED_POINT.md: c2 and c3 by floor(x w / 2^30) products of exact sums, each coefficient
  // the sum rounded once to 2^-18; the value (from p 2^6, in 2^-14 grey), D1 and D2 by Horner's
  // rule with floor(w t / 2^30).
  std::mt19937_64 rng(13);
  constexpr int64_t max_sum = ZienkiewiczChannel::max_fd_sum;
  constexpr int64_t step_limit = (int64_t(1) << 28) + (int64_t(1) << 26);
  auto floor30 = [](i128 x, int64_t w) { return int64_t((x * w) >> 30); };
  auto round20 = [](i128 x) { return int64_t((x + (i128(1) << 19)) >> 20); };
  int in_budget = 0, out_of_budget = 0, out_of_sum = 0;
  for (int i = 0; i < 40000; ++i) {
    ZienkiewiczChannel z{};
    Coefficients p;
    // Magnitudes whose sum is around the budget (sometimes one coefficient carries it all).
    const int64_t scale = max_sum / (i % 4 == 0 ? 1 : 5) >> int(rng() % 6);
    int64_t sum = 0;
    for (int64_t& q : p) {
      q = int64_t(rng() % uint64_t(2 * scale + 1)) - scale;
      sum += q < 0 ? -q : q;
    }
    set_coefficients(z, p);
    // Steps from those of long rows to the budget's limit.
    auto step = [&] {
      const uint64_t r = rng();
      return r % 7 == 0 ? (r & 16 ? step_limit : -step_limit)
                        : (int64_t(r % uint64_t(2 * step_limit + 1)) - step_limit) >> int(rng() % 12);
    };
    const int64_t da = step(), db = step();
    REQUIRE(ZienkiewiczChannel::steps_fit_rows(int32_t(da), int32_t(db)));
    const int64_t p01 = p[1], p02 = p[2], p03 = p[3], p10 = p[4], p11 = p[5], p12 = p[6], p20 = p[7], p21 = p[8],
                  p30 = p[9];
    const int64_t s00 = floor30(i128(p20) * da + i128(p11) * db, da) + floor30(i128(p02) * db, db);
    const int64_t s10 = floor30(i128(3 * p30) * da + i128(2 * p21) * db, da) + floor30(i128(p12) * db, db);
    const int64_t s01 = floor30(i128(p21) * da + i128(2 * p12) * db, da) + floor30(i128(3 * p03) * db, db);
    const int64_t c3 = floor30(floor30(i128(p30) * da + i128(p21) * db, da), da) +
                       floor30(floor30(i128(p12) * da + i128(p03) * db, db), db);
    const int64_t g00 = round20(i128(p10) * da + i128(p01) * db + s00 + c3);
    const int64_t g10 = round20(i128(2 * p20) * da + i128(p11) * db + s10);
    const int64_t g01 = round20(i128(p11) * da + i128(2 * p02) * db + s01);
    const int64_t g20 = round20(i128(3 * p30) * da + i128(p21) * db);
    const int64_t g11 = round20(i128(2 * p21) * da + i128(2 * p12) * db);
    const int64_t g02 = round20(i128(p12) * da + i128(3 * p03) * db);
    const int64_t h00 = round20(i128(2) * s00 + i128(6) * c3);
    const int64_t h10 = round20(i128(2) * s10);
    const int64_t h01 = round20(i128(2) * s01);
    const int64_t d3 = round20(i128(6) * c3);
    auto within = [](int64_t v, int bits) { return v >= -(int64_t(1) << bits) && v < (int64_t(1) << bits); };
    const bool g_budget =
        within(g00, 26) && within(g10, 26) && within(g01, 26) && within(g20, 26) && within(g11, 26) && within(g02, 26);
    const bool h_budget = within(h00, 28) && within(h10, 28) && within(h01, 28);
    const bool budget = sum < max_sum && g_budget && h_budget;
    REQUIRE(z.setup_rows(int32_t(da), int32_t(db)) == budget);
    if (sum >= max_sum) {
      ++out_of_sum;
      continue;
    }
    // With the steps' budget the g budget implies the h budget (interpolate.h).
    if (g_budget) REQUIRE(h_budget);
    if (!budget) {
      ++out_of_budget;
      continue;
    }
    ++in_budget;
    const ZienkiewiczChannel::RowCoefficients& f = z.fd;
    REQUIRE(f.g00 == g00);
    REQUIRE(f.g10 == g10);
    REQUIRE(f.g01 == g01);
    REQUIRE(f.g20x4 == 4 * g20);
    REQUIRE(f.g11x4 == 4 * g11);
    REQUIRE(f.g02x4 == 4 * g02);
    REQUIRE(f.h00 == h00);
    REQUIRE(f.h10x4 == 4 * h10);
    REQUIRE(f.h01x4 == 4 * h01);
    REQUIRE(f.d3 == d3);
    for (int j = 0; j < 4; ++j) {
      // Weights of covered pixels: [0, 1] up to a little rounding.
      const int32_t a = int32_t(rng() % ((1u << 30) + 32)) - 16, b = int32_t(rng() % ((1u << 30) + 32)) - 16;
      auto m = [](int64_t w, int64_t t, int64_t q) { return q + int64_t((i128(w) * t) >> 30); };
      const int64_t e1 = m(a, m(a, g20, m(b, g11, g10)), m(b, m(b, g02, g01), g00));
      const int64_t e2 = m(a, h10, m(b, h01, h00));
      const CubicSteps s = z.steps_at(a, b);
      REQUIRE(int32_t(s.d1) == e1);
      REQUIRE(int32_t(s.d2) == e2);
      REQUIRE(int32_t(s.d3) == d3);
      auto e = [&](int k) { return p[k] << 6; };
      const int64_t vb = m(b, m(b, m(b, e(3), e(2)), e(1)), e(0));
      const int64_t va = m(a, m(a, e(9), m(b, e(8), e(7))), m(b, m(b, e(6), e(5)), e(4)));
      REQUIRE(int32_t(s.v) == int32_t(uint32_t(m(a, va, vb)) << 4));
    }
  }
  CHECK(in_budget > 10000);
  CHECK(out_of_budget > 100);
  CHECK(out_of_sum > 100);
  // Steps beyond their budget, whatever the coefficients.
  {
    ZienkiewiczChannel z{};
    set_coefficients(z, Coefficients{});
    CHECK(z.setup_rows(int32_t(step_limit), 0));
    CHECK_FALSE(z.setup_rows(int32_t(step_limit + 1), 0));
    CHECK_FALSE(z.setup_rows(0, int32_t(-step_limit - 1)));
  }
  // At and beyond the coefficients' budget (either sign, one coefficient or spread) and the steps'.
  for (int k = 0; k < 10; ++k)
    for (int64_t sign : {1, -1}) {
      Coefficients p{};
      p[k] = sign * (max_sum - 1);
      ZienkiewiczChannel z{};
      set_coefficients(z, p);
      CHECK(z.setup_rows(1 << 20, 1 << 20));
      p[k] = sign * max_sum;
      set_coefficients(z, p);
      CHECK_FALSE(z.setup_rows(1 << 20, 1 << 20));
      p[k] = sign * (max_sum - 1);
      p[(k + 3) % 10] = -sign;
      set_coefficients(z, p);
      CHECK_FALSE(z.setup_rows(1 << 20, 1 << 20));
    }
  CHECK(ZienkiewiczChannel::steps_fit_rows(int32_t(step_limit), int32_t(-step_limit)));
  CHECK_FALSE(ZienkiewiczChannel::steps_fit_rows(int32_t(step_limit + 1), 0));
  CHECK_FALSE(ZienkiewiczChannel::steps_fit_rows(0, int32_t(-step_limit - 1)));
}

TEST_CASE("forward-differenced rows stay within the documented bound of the cubic") {
  std::mt19937 rng(17);
  double worst_ratio = 0, worst_units = 0;
  int rows = 0;
  // (size in pixels, largest gradient in q19_12)
  const std::pair<int32_t, int32_t> cases[] = {{40, 8 << 12},  {40, 1 << 12},   {300, 1 << 12},
                                               {300, 1 << 10}, {1200, 1 << 10}, {2047, 1 << 9}};
  for (const auto& [size, max_gradient] : cases) {
    for (int t = 0; t < (size > 1000 ? 60 : 150); ++t) {
      RowCase rc;
      if (!random_row(rng, size, max_gradient, &rc)) continue;
      ++rows;
      worst_units = std::max(worst_units, check_row(rc, &worst_ratio));
    }
  }
  INFO("rows " << rows);
  CHECK(rows > 100);
  WARN("largest forward-difference error " << worst_units << " x 2^-18 grey (" << worst_ratio << " of the bound)");
}

TEST_CASE("coefficients and steps at the budget: no overflow, still within the bound") {
  std::mt19937 rng(23);
  int rows = 0, shortest = 0;
  for (int t = 0; t < 800; ++t) {
    RowCase rc;
    // The sum of magnitudes at the budget (or, for the short rows' steps to pass the differences'
    // budget, a power of two below), spread over the ten or in one coefficient.
    const int64_t sum = (ZienkiewiczChannel::max_fd_sum - 1) >> (t % 2 ? 0 : int(rng() % 8));
    for (auto& ch : rc.ch) {
      Coefficients p{};
      if (rng() % 3 == 0) {
        p[rng() % 10] = rng() % 2 ? sum : -sum;
      } else {
        for (int k = 0; k < 10; ++k) p[k] = (rng() % 2 ? 1 : -1) * (sum / 10 + (k < sum % 10 ? 1 : 0));
      }
      set_coefficients(ch, p);
    }
    // The steps of a row of `length` pixels with weights from 1 to 0 (5 pixels: the steps'
    // limit).
    const int32_t length = t % 4 == 0 ? 5 : 5 + int32_t(rng() % 300);
    const int32_t step = int32_t((1 << 30) / (length - 1));
    bool fits = true;
    for (auto& ch : rc.ch) fits &= ch.setup_rows(-step, step);
    if (!fits) continue;  // the differences' budget (tested above against its definition)
    ++rows;
    shortest += length == 5;
    rc.a = 1u << 30;
    rc.b = 0;
    rc.da = uint32_t(-step);
    rc.db = uint32_t(step);
    rc.length = length;
    check_row(rc, nullptr);
  }
  CHECK(rows > 100);
  CHECK(shortest > 10);  // rows at the steps' limit
}

TEST_CASE("a pixel's value does not depend on where its span starts") {
  std::mt19937 rng(29);
  int rows = 0;
  for (int t = 0; t < 80; ++t) {
    RowCase rc;
    if (!random_row(rng, t % 2 ? 400 : 1500, 1 << 10, &rc)) continue;
    ++rows;
    for (int c = 0; c < 3; ++c) {
      const std::vector<int32_t> full = row_values(rc, c, 0, rc.length - 1);
      for (int k = 0; k < 40; ++k) {
        const int32_t n0 = int32_t(rng() % uint32_t(rc.length));
        const int32_t n1 = n0 + int32_t(rng() % uint32_t(rc.length - n0));
        const std::vector<int32_t> part = row_values(rc, c, n0, n1);
        for (int32_t n = n0; n <= n1; ++n) REQUIRE(part[n - n0] == full[n]);
      }
      // Tiles of every width from 1 to 70 pixels, in order along the row.
      for (int32_t w = 1; w <= 70; ++w)
        for (int32_t n0 = 0; n0 < rc.length; n0 += w) {
          const int32_t n1 = std::min(rc.length - 1, n0 + w - 1);
          const std::vector<int32_t> part = row_values(rc, c, n0, n1);
          for (int32_t n = n0; n <= n1; ++n) REQUIRE(part[n - n0] == full[n]);
        }
    }
  }
  CHECK(rows > 20);
}
