// SPDX-License-Identifier: MIT
#include "geometry/predicates.h"

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

// This file must be compiled without floating-point contraction (-ffp-contract=off, set in
// CMakeLists.txt): a fused multiply-add would break the error-free transformations below.

namespace tristream {
namespace detail {
namespace {

// Half an ulp of 1: the unit roundoff of double.
constexpr double epsilon = 0x1p-53;
// Error bounds of the filters (Shewchuk 1997, section 4: ccwerrboundA and iccerrboundA).
constexpr double orient_bound = (3.0 + 16.0 * epsilon) * epsilon;
constexpr double incircle_bound = (10.0 + 96.0 * epsilon) * epsilon;
// Dekker's splitter 2^27 + 1: splits a double into two 26-bit halves.
constexpr double splitter = 134217729.0;

// An expansion: a sum of non-overlapping doubles, increasing magnitude, no zero components.
using Expansion = std::vector<double>;

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void fast_two_sum(double a, double b, double& x, double& y) {  // needs |a| >= |b|
  x = a + b;
  y = b - (x - a);
}

inline void split(double a, double& hi, double& lo) {
  const double c = splitter * a;
  hi = c - (c - a);
  lo = a - hi;
}

inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err = x - ahi * bhi - alo * bhi - ahi * blo;
  y = alo * blo - err;
}

// a - b exactly, as an expansion of at most two components.
Expansion difference(double a, double b) {
  const double x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  const double y = (a - av) + (bv - b);
  Expansion e;
  if (y != 0) e.push_back(y);
  if (x != 0) e.push_back(x);
  return e;
}

// e + b (Shewchuk's GROW-EXPANSION with zero elimination).
Expansion grow(const Expansion& e, double b) {
  Expansion h;
  h.reserve(e.size() + 1);
  double q = b;
  for (double component : e) {
    double sum, err;
    two_sum(q, component, sum, err);
    if (err != 0) h.push_back(err);
    q = sum;
  }
  if (q != 0) h.push_back(q);
  return h;
}

Expansion sum(const Expansion& e, const Expansion& f) {
  Expansion h = e;
  for (double component : f) h = grow(h, component);
  return h;
}

// e * b (Shewchuk's SCALE-EXPANSION with zero elimination).
Expansion scale(const Expansion& e, double b) {
  Expansion h;
  if (e.empty() || b == 0) return h;
  h.reserve(2 * e.size());
  double q, err;
  two_product(e[0], b, q, err);
  if (err != 0) h.push_back(err);
  for (std::size_t i = 1; i < e.size(); ++i) {
    double p1, p0, s;
    two_product(e[i], b, p1, p0);
    two_sum(q, p0, s, err);
    if (err != 0) h.push_back(err);
    fast_two_sum(p1, s, q, err);
    if (err != 0) h.push_back(err);
  }
  if (q != 0) h.push_back(q);
  return h;
}

Expansion product(const Expansion& e, const Expansion& f) {
  Expansion h;
  for (double component : f) h = sum(h, scale(e, component));
  return h;
}

Expansion negate(Expansion e) {
  for (double& component : e) component = -component;
  return e;
}

// The most significant component carries the sign; it approximates the value.
double estimate(const Expansion& e) { return e.empty() ? 0.0 : e.back(); }

double orient_exact(const Point& a, const Point& b, const Point& c) {
  const Expansion acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const Expansion bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  return estimate(sum(product(acx, bcy), negate(product(acy, bcx))));
}

double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Expansion adx = difference(a.x, d.x), ady = difference(a.y, d.y);
  const Expansion bdx = difference(b.x, d.x), bdy = difference(b.y, d.y);
  const Expansion cdx = difference(c.x, d.x), cdy = difference(c.y, d.y);
  const Expansion alift = sum(product(adx, adx), product(ady, ady));
  const Expansion blift = sum(product(bdx, bdx), product(bdy, bdy));
  const Expansion clift = sum(product(cdx, cdx), product(cdy, cdy));
  const Expansion bc = sum(product(bdx, cdy), negate(product(cdx, bdy)));
  const Expansion ca = sum(product(cdx, ady), negate(product(adx, cdy)));
  const Expansion ab = sum(product(adx, bdy), negate(product(bdx, ady)));
  return estimate(sum(sum(product(alift, bc), product(blift, ca)), product(clift, ab)));
}

// Integer inputs of magnitude <= 2^29 (every pixel position): differences fit 31 bits,
// the incircle determinant 3 * 2 * 2^61 * 2^61 < 2^126 fits a signed 128-bit integer.
constexpr double integer_limit = 0x1p29;

inline bool small_integer(double v) { return std::fabs(v) <= integer_limit && v == std::trunc(v); }

inline bool small_integers(std::initializer_list<double> values) {
  for (double v : values)
    if (!small_integer(v)) return false;
  return true;
}

double sign_of(__int128 v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

double orient_integer(const Point& a, const Point& b, const Point& c) {
  const std::int64_t acx = std::int64_t(a.x) - std::int64_t(c.x), acy = std::int64_t(a.y) - std::int64_t(c.y);
  const std::int64_t bcx = std::int64_t(b.x) - std::int64_t(c.x), bcy = std::int64_t(b.y) - std::int64_t(c.y);
  return sign_of(__int128(acx) * bcy - __int128(acy) * bcx);
}

double incircle_integer(const Point& a, const Point& b, const Point& c, const Point& d) {
  const std::int64_t adx = std::int64_t(a.x) - std::int64_t(d.x), ady = std::int64_t(a.y) - std::int64_t(d.y);
  const std::int64_t bdx = std::int64_t(b.x) - std::int64_t(d.x), bdy = std::int64_t(b.y) - std::int64_t(d.y);
  const std::int64_t cdx = std::int64_t(c.x) - std::int64_t(d.x), cdy = std::int64_t(c.y) - std::int64_t(d.y);
  const __int128 alift = __int128(adx * adx) + ady * ady;
  const __int128 blift = __int128(bdx * bdx) + bdy * bdy;
  const __int128 clift = __int128(cdx * cdx) + cdy * cdy;
  const __int128 bc = __int128(bdx * cdy) - bdy * cdx;
  const __int128 ca = __int128(cdx * ady) - cdy * adx;
  const __int128 ab = __int128(adx * bdy) - ady * bdx;
  return sign_of(alift * bc + blift * ca + clift * ab);
}

}  // namespace
}  // namespace detail

double orient2d(const Point& a, const Point& b, const Point& c) {
  const double left = (a.x - c.x) * (b.y - c.y);
  const double right = (a.y - c.y) * (b.x - c.x);
  const double det = left - right;
  const double bound = detail::orient_bound * (std::fabs(left) + std::fabs(right));
  if (det > bound || -det > bound) return det;
  if (detail::small_integers({a.x, a.y, b.x, b.y, c.x, c.y})) return detail::orient_integer(a, b, c);
  return detail::orient_exact(a, b, c);
}

double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = detail::incircle_bound * permanent;
  if (det > bound || -det > bound) return det;
  if (detail::small_integers({a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y}))
    return detail::incircle_integer(a, b, c, d);
  return detail::incircle_exact(a, b, c, d);
}

}  // namespace tristream
