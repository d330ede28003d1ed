#pragma once
// Exact integer helpers of the per-triangle setup (64-bit; never used per pixel).
#include <stdint.h>

namespace tristream::core::detail {

// floor(n / d) for d > 0, always in 64 bits (for dividends that rarely fit 32 bits).
inline int64_t floor_div64(int64_t n, int64_t d) {
  int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// floor(n / d) for d > 0.
inline int64_t floor_div(int64_t n, int64_t d) {
  if (n == int64_t(int32_t(n)) && d == int64_t(int32_t(d))) {
    // 32-bit division when both fit (a hardware divide on Cortex-M4, faster on hosts too).
    const int32_t n32 = int32_t(n), d32 = int32_t(d);
    const int32_t q32 = n32 / d32;
    return (n32 % d32 != 0 && n32 < 0) ? int64_t(q32) - 1 : int64_t(q32);
  }
  int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// n / d rounded to nearest (halves up) for d > 0; |n| < 2^62.
// Its dividends (gradients and weights scaled by 2^8 or 2^30) hardly ever fit 32 bits.
inline int64_t round_div(int64_t n, int64_t d) { return floor_div64(2 * n + d, 2 * d); }

inline int32_t min3(int32_t a, int32_t b, int32_t c) { return a < b ? (a < c ? a : c) : (b < c ? b : c); }
inline int32_t max3(int32_t a, int32_t b, int32_t c) { return a > b ? (a > c ? a : c) : (b > c ? b : c); }

}  // namespace tristream::core::detail
