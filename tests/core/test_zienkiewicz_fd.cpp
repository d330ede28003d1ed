// SPDX-License-Identifier: MIT
// Forward differencing of the zienkiewicz cubic along rows (detail/interpolate.h): the helpers
// against 128-bit arithmetic, every forward-differenced value against the exact value of the same
// cubic (within the bound of docs/FIXED_POINT.md), and values independent of where a span starts.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "tristream/detail/arith.h"
#include "tristream/detail/edge.h"
#include "tristream/detail/interpolate.h"

using namespace tristream::core;
using namespace tristream::core::detail;

namespace {

__extension__ typedef __int128 i128;

constexpr int vf = ZienkiewiczChannel::value_frac_bits;

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

// The documented bound, in units of 2^-32 grey, at m steps after a restart.
double fd_bound(int32_t m) {
  const double c2 = m * (m - 1.0) / 2, c3 = c2 * (m - 2.0) / 3;
  return 9.01 + 8.2 * m + 4.1 * c2 + 0.876 * c3;
}

struct RowCase {
  ZienkiewiczChannel ch[3];
  uint32_t a = 0, b = 0, da = 0, db = 0;  // q2_30 at the row's first covered pixel, and steps
  int32_t length = 0;                      // covered pixels
};

// A random triangle of the given size (pixels) with random values and gradients; its longest
// covered row. False when no row has two pixels.
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
  std::uniform_int_distribution<int32_t> value(0, 255 * 256), gradient(-max_gradient << 12, max_gradient << 12);
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

// Values of pixels n0..n1 of the row (2^-32 grey, no bias), channel c.
std::vector<int64_t> row_values(const RowCase& rc, int c, int32_t n0, int32_t n1) {
  std::vector<int64_t> out;
  zienkiewicz_row<3>(rc.ch, rc.a, rc.b, rc.da, rc.db, n0, n1, 0, [&](int32_t n, const CubicSteps* s) {
    REQUIRE(n == n0 + int32_t(out.size()));
    out.push_back(int64_t(s[c].v));
  });
  return out;
}

}  // namespace

TEST_CASE("mul_q30 and Wide equal 128-bit arithmetic") {
  std::mt19937_64 rng(3);
  const int64_t xs[] = {0, 1, -1, (int64_t(1) << 61) - 1, -(int64_t(1) << 61) + 1, 0x123456789abcdefll >> 4};
  const int32_t ys[] = {0, 1, -1, INT32_MAX, INT32_MIN, 1 << 30, -(1 << 30)};
  for (int64_t x : xs)
    for (int32_t y : ys) {
      CHECK(mul_q30_portable(x, y) == int64_t((i128(x) * y) >> 30));
      CHECK(mul_q30(x, y) == mul_q30_portable(x, y));
    }
  for (int i = 0; i < 200000; ++i) {
    const int64_t x = int64_t(rng()) >> (3 + rng() % 60);
    const int32_t y = int32_t(uint32_t(rng())) >> (rng() % 31);
    REQUIRE(mul_q30_portable(x, y) == int64_t((i128(x) * y) >> 30));
    REQUIRE(mul_q30(x, y) == mul_q30_portable(x, y));
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
  for (int i = 0; i < 2000; ++i) {
    CubicSteps s{rng(), rng(), rng(), rng()};
    const uint32_t k = uint32_t(rng() % 200);
    CubicSteps t = s;
    for (uint32_t j = 0; j < k; ++j) t.step();
    s.skip(k);
    REQUIRE(s.v == t.v);
    REQUIRE(s.d1 == t.d1);
    REQUIRE(s.d2 == t.d2);
    REQUIRE(s.d3 == t.d3);
  }
}

TEST_CASE("CubicSteps::high_bytes equals clamped high words of repeated steps") {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    // Values near the [0, 255] range in the high word, and anywhere.
    const uint64_t v = i % 2 ? rng() : (uint64_t(rng() % 300) << 32) - (uint64_t(20) << 32) + (rng() >> 32);
    CubicSteps s{v, rng() >> (i % 3 ? 24 : 0), rng() >> (i % 5 ? 30 : 0), rng() >> (i % 7 ? 36 : 0)};
    if (i % 4 == 0) s.d1 = ~s.d1;  // negative differences
    const int32_t count = int32_t(rng() % 40);
    CubicSteps t = s;
    uint8_t out[40];
    s.high_bytes(out, count);
    for (int32_t k = 0; k < count; ++k) {
      const int32_t h = int32_t(int64_t(t.v) >> 32);
      REQUIRE(int(out[k]) == (h < 0 ? 0 : (h > 255 ? 255 : h)));
      t.step();
    }
    REQUIRE(s.v == t.v);
    REQUIRE(s.d1 == t.d1);
    REQUIRE(s.d2 == t.d2);
    REQUIRE(s.d3 == t.d3);
  }
}

TEST_CASE("eval_narrow equals eval_wide within its coefficient budget") {
  std::mt19937_64 rng(11);
  constexpr int64_t max = ZienkiewiczChannel::max_narrow_coefficient;
  ZienkiewiczChannel z{};
  Coefficients p{};
  // Weights as the shader forms them (int32 q2_30 >> 15: |w| <= 2^16), the extremes included.
  const int32_t extremes[] = {-(1 << 16), (1 << 16) - 1, 1 << 15, -1, 0, 1};
  for (int i = 0; i < 200000; ++i) {
    for (int64_t& q : p) {
      const uint64_t r = rng();
      q = r % 3 == 0 ? (r & 8 ? max : -max) : int64_t(r % uint64_t(2 * max + 1)) - max;
    }
    set_coefficients(z, p);
    REQUIRE(z.fits_narrow());
    const int32_t a = i % 3 ? int32_t(uint32_t(rng())) >> 15 : extremes[rng() % 6];
    const int32_t b = i % 5 ? int32_t(uint32_t(rng())) >> 15 : extremes[rng() % 6];
    REQUIRE(int64_t(z.eval_narrow(a, b)) == z.eval_wide(a, b));
  }
  // All coefficients at the limit with the same sign: the largest partial sums.
  for (int64_t sign : {1, -1})
    for (int32_t w : {-(1 << 16), 1 << 15, (1 << 16) - 1}) {
      for (int64_t& q : p) q = sign * max;
      set_coefficients(z, p);
      REQUIRE(z.fits_narrow());
      REQUIRE(int64_t(z.eval_narrow(w, w)) == z.eval_wide(w, w));
    }
  for (int64_t& q : p) {
    const int64_t keep = q;
    q = max + 1;
    set_coefficients(z, p);
    CHECK_FALSE(z.fits_narrow());
    q = -max - 1;
    set_coefficients(z, p);
    CHECK_FALSE(z.fits_narrow());
    q = keep;
  }
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
    CHECK_FALSE(z64.setup<false>(dx, dy, v3, g));
    REQUIRE(narrow == z.fits_narrow());
    narrow_cases += narrow;
    // The same coefficients from the derivatives in 64 bits.
    constexpr int down = config::subpixel_bits + config::gradient_frac_bits - q24_8::frac_bits;
    auto dot = [&](int e, int v) {
      return (int64_t(dx[e]) * g[2 * v] + int64_t(dy[e]) * g[2 * v + 1] + (int64_t(1) << (down - 1))) >> down;
    };
    ZienkiewiczChannel w{};
    w.expand<int64_t>(v3[0], dot(0, 0), dot(0, 1), v3[1], dot(1, 1), dot(1, 2), v3[2], dot(2, 2), dot(2, 0));
    REQUIRE(coefficients(z) == coefficients(w));
    REQUIRE(coefficients(z64) == coefficients(w));
    // Coefficients beyond int32 (kept apart where the coefficients are int32: TS_USE_INT128=0)
    // are outside both 32-bit budgets, and eval_wide is the int64 Horner scheme in either layout.
    const Coefficients pw = coefficients(w);
    bool beyond_int32 = false;
    for (const int64_t q : pw) beyond_int32 |= q < INT32_MIN || q > INT32_MAX;
    beyond_int32_cases += beyond_int32;
    if (beyond_int32) {
      CHECK_FALSE(z.fits_rows());
      CHECK_FALSE(z.fits_narrow());
    }
    const ZienkiewiczChannel::WideCoefficients c = w.coefficients();
    for (int j = 0; j < 4; ++j) {
      const int64_t a = int64_t(rng() % (2u << 16)) - (1 << 16), b = int64_t(rng() % (2u << 16)) - (1 << 16);
      REQUIRE(z.eval_wide(a, b) == ZienkiewiczChannel::horner(c, a, b));
      REQUIRE(z64.eval_wide(a, b) == ZienkiewiczChannel::horner(c, a, b));
    }
  }
  // Narrow and wide triangles both occur, and coefficients beyond int32.
  CHECK(narrow_cases > 2000);
  CHECK(narrow_cases < 18000);
  CHECK(beyond_int32_cases > 100);
}

TEST_CASE("steps_at equals the polynomials of 2^-32 coefficients evaluated in 128-bit arithmetic") {
  // The value's Horner steps on p 2^24 with floor(x w / 2^30), as the documentation states them.
  std::mt19937_64 rng(13);
  auto m = [](i128 x, int32_t w) { return int64_t((x * w) >> 30); };
  for (int i = 0; i < 20000; ++i) {
    ZienkiewiczChannel z{};
    Coefficients p;
    const int64_t max = ZienkiewiczChannel::max_fd_coefficient - 1;
    for (int64_t& q : p) q = int64_t(rng() % uint64_t(2 * max + 1)) - max;
    set_coefficients(z, p);
    const int32_t da = int32_t(rng() % (2u << 20)) - (1 << 20), db = int32_t(rng() % (2u << 20)) - (1 << 20);
    REQUIRE(z.setup_rows(da, db));
    const int32_t a = int32_t(rng() % (1u << 30)), b = int32_t(rng() % (1u << 30));
    const CubicSteps s = z.steps_at(a, b, 3);
    auto f = [](int64_t c) { return i128(c) << 24; };
    const int64_t pb = int64_t(f(p[0]) + m(f(p[1]) + m(f(p[2]) + m(f(p[3]), b), b), b));
    const int64_t pa = int64_t(f(p[4]) + m(f(p[5]) + m(f(p[6]), b), b) + m(f(p[7]) + m(f(p[8]), b) + m(f(p[9]), a), a));
    REQUIRE(s.v == uint64_t(pb + m(pa, a)));
  }
}

TEST_CASE("forward-differenced rows equal the exact cubic within the documented bound") {
  std::mt19937 rng(17);
  double worst = 0;  // largest error over the bound
  double worst_units = 0;
  int rows = 0;
  for (int32_t size : {40, 300, 1200, 2047}) {
    for (int32_t max_gradient : {8, 60, 400}) {
      for (int t = 0; t < (size > 1000 ? 6 : 30); ++t) {
        RowCase rc;
        if (!random_row(rng, size, max_gradient, &rc)) continue;
        ++rows;
        for (int c = 0; c < 3; ++c) {
          const std::vector<int64_t> v = row_values(rc, c, 0, rc.length - 1);
          for (int32_t n = 0; n < rc.length; ++n) {
            const int32_t an = int32_t(rc.a + rc.da * uint32_t(n)), bn = int32_t(rc.b + rc.db * uint32_t(n));
            const i128 diff = i128(v[n]) * (i128(1) << 66) - exact_p(rc.ch[c], an, bn);
            const double units = double(diff) / 0x1p66;  // units of 2^-32 grey
            const double ratio = std::abs(units) / fd_bound(n % zienkiewicz_fd_restart);
            worst = std::max(worst, ratio);
            worst_units = std::max(worst_units, std::abs(units));
            REQUIRE(ratio <= 1.0);
          }
        }
      }
    }
  }
  INFO("rows " << rows << ", largest error " << worst_units << " units of 2^-32, " << worst << " of the bound");
  CHECK(rows > 100);
  WARN("largest forward-difference error " << worst_units << " x 2^-32 grey (" << worst << " of the bound)");
}

TEST_CASE("coefficients and steps at the bit budget: no overflow, still within the bound") {
  std::mt19937 rng(23);
  const int64_t big = ZienkiewiczChannel::max_fd_coefficient - 1;
  for (int t = 0; t < 200; ++t) {
    RowCase rc;
    for (auto& ch : rc.ch) {
      Coefficients p;
      for (int64_t& q : p) q = (rng() % 2 ? big : -big) >> (rng() % 4 == 0 ? 10 : 0);
      set_coefficients(ch, p);
      REQUIRE(ch.fits_rows());
    }
    ZienkiewiczChannel too_big = rc.ch[0];
    Coefficients over_budget = coefficients(too_big);
    over_budget[8] = ZienkiewiczChannel::max_fd_coefficient;  // p21
    set_coefficients(too_big, over_budget);
    CHECK_FALSE(too_big.setup_rows(0, 0));
    // Steps at the budget's limit (a two-pixel row from vertex 0 to vertex 1) or those of a row
    // of `length` pixels with weights from 1 to 0.
    const bool extreme = t % 4 == 0;
    const int32_t length = extreme ? 2 : 3 + int32_t(rng() % 300);
    const int32_t step = extreme ? int32_t(1) << 30 : int32_t((1 << 30) / (length - 1));
    for (auto& ch : rc.ch) {
      REQUIRE(ch.setup_rows(-step, step));
      ZienkiewiczChannel over = ch;
      CHECK_FALSE(over.setup_rows(-step - (extreme ? 1 : 0x7fffffff - step), step));
    }
    rc.a = 1u << 30;
    rc.b = 0;
    rc.da = uint32_t(-step);
    rc.db = uint32_t(step);
    rc.length = length;
    for (int c = 0; c < 3; ++c) {
      const std::vector<int64_t> v = row_values(rc, c, 0, rc.length - 1);
      for (int32_t n = 0; n < rc.length; ++n) {
        const int32_t an = int32_t(rc.a + rc.da * uint32_t(n)), bn = int32_t(rc.b + rc.db * uint32_t(n));
        const i128 diff = i128(v[n]) * (i128(1) << 66) - exact_p(rc.ch[c], an, bn);
        REQUIRE(std::abs(double(diff) / 0x1p66) <= fd_bound(n % zienkiewicz_fd_restart));
      }
    }
  }
}

TEST_CASE("a pixel's value does not depend on where its span starts") {
  std::mt19937 rng(29);
  int rows = 0;
  for (int t = 0; t < 60; ++t) {
    RowCase rc;
    if (!random_row(rng, t % 2 ? 400 : 1500, 50, &rc)) continue;
    ++rows;
    for (int c = 0; c < 3; ++c) {
      const std::vector<int64_t> full = row_values(rc, c, 0, rc.length - 1);
      for (int k = 0; k < 40; ++k) {
        const int32_t n0 = int32_t(rng() % uint32_t(rc.length));
        const int32_t n1 = n0 + int32_t(rng() % uint32_t(rc.length - n0));
        const std::vector<int64_t> part = row_values(rc, c, n0, n1);
        for (int32_t n = n0; n <= n1; ++n) REQUIRE(part[n - n0] == full[n]);
      }
      // Tiles of every width from 1 to 70 pixels, in order along the row.
      for (int32_t w = 1; w <= 70; ++w)
        for (int32_t n0 = 0; n0 < rc.length; n0 += w) {
          const int32_t n1 = std::min(rc.length - 1, n0 + w - 1);
          const std::vector<int64_t> part = row_values(rc, c, n0, n1);
          for (int32_t n = n0; n <= n1; ++n) REQUIRE(part[n - n0] == full[n]);
        }
    }
  }
  CHECK(rows > 20);
}
