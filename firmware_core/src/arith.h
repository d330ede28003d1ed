/* SPDX-License-Identifier: MIT */
#pragma once
// Exact integer helpers of the per-triangle setup (64-bit; never used per pixel).
#include <stdint.h>

#include "tristream/config.h"
#include "tuning.h"

namespace tristream::core::detail {

// T, or the 64-bit integer of T's signedness when Wide (the layouts of 64-bit hosts beside those
// of 32-bit targets).
template <bool Wide, typename T>
struct WiderIf {
  using type = T;
};
template <>
struct WiderIf<true, int32_t> {
  using type = int64_t;
};
template <>
struct WiderIf<true, uint32_t> {
  using type = uint64_t;
};
template <bool Wide, typename T>
using wider_if = typename WiderIf<Wide, T>::type;

// floor(n / d) for d > 0.
inline int64_t floor_div(int64_t n, int64_t d) {
  if (n == int64_t(int32_t(n)) && d == int64_t(int32_t(d))) {
    // 32-bit division when both fit (a hardware divide on Cortex-M4, faster on hosts too).
    const int32_t n32 = int32_t(n), d32 = int32_t(d);
    const int32_t q32 = n32 / d32;
    return int64_t(q32) - ((n32 % d32 != 0) & (n32 < 0));
  }
  int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// n = q d + r with 0 <= r < d, for d > 0 (one hardware divide on Cortex-M3 and later).
TS_INLINE inline void floor_divmod32(int32_t n, int32_t d, int32_t* q, int32_t* r) {
  int32_t qq = n / d, rr = n - qq * d;
  if (rr < 0) rr += d, --qq;
  *q = qq;
  *r = rr;
}

// High 64 bits of the 128-bit product a * b, from four 32 x 32 -> 64 products (targets without
// a 128-bit type, such as Cortex-M; the result is the same everywhere).
inline uint64_t mulhi_u64_portable(uint64_t a, uint64_t b) {
  const uint64_t a_lo = uint32_t(a), a_hi = a >> 32, b_lo = uint32_t(b), b_hi = b >> 32;
  const uint64_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi, hi_hi = a_hi * b_hi;
  const uint64_t mid = (lo_lo >> 32) + uint32_t(hi_lo) + uint32_t(lo_hi);  // below 3 * 2^32
  return hi_hi + (hi_lo >> 32) + (lo_hi >> 32) + (mid >> 32);
}

// The 64-bit product a * b, from four 16 x 16 -> 32 products (ARMv6-M, where a 64-bit product is
// a library call; the result is the same everywhere).
TS_INLINE inline uint64_t mul_u32_wide_portable(uint32_t a, uint32_t b) {
  const uint32_t a_lo = a & 0xFFFFu, a_hi = a >> 16, b_lo = b & 0xFFFFu, b_hi = b >> 16;
  const uint32_t lo_lo = a_lo * b_lo, hi_lo = a_hi * b_lo, lo_hi = a_lo * b_hi, hi_hi = a_hi * b_hi;
  const uint32_t mid = (lo_lo >> 16) + (hi_lo & 0xFFFFu) + (lo_hi & 0xFFFFu);  // below 3 * 2^16
  const uint32_t high = hi_hi + (hi_lo >> 16) + (lo_hi >> 16) + (mid >> 16);
  return (uint64_t(high) << 32) | (mid << 16) | (lo_lo & 0xFFFFu);
}

// Its high 32 bits (the low word's work is dropped).
TS_INLINE inline uint32_t mulhi_u32_portable(uint32_t a, uint32_t b) {
  return uint32_t(mul_u32_wide_portable(a, b) >> 32);
}

TS_INLINE inline uint64_t mul_u32_wide(uint32_t a, uint32_t b) {
  if constexpr (tuning::multiplies_wide) {
    return uint64_t(a) * b;  // one UMULL (Cortex-M3 and later), MUL and MULHU (RISC-V M)
  } else {
    return mul_u32_wide_portable(a, b);
  }
}

TS_INLINE inline uint32_t mulhi_u32(uint32_t a, uint32_t b) {
  if constexpr (tuning::multiplies_wide) {
    return uint32_t(uint64_t(a) * b >> 32);  // one UMULL (Cortex-M3 and later), MULHU (RISC-V M)
  } else {
    return mulhi_u32_portable(a, b);
  }
}

// floor(a b / 2^32), the high word of the signed 64-bit product, from four 16 x 16 -> 32 products
// (Hacker's Delight's mulhs; a = a_hi 2^16 + a_lo with a_hi signed, a_lo in [0, 2^16)): every
// partial product and sum below stays within int32. Written apart from mul_s32_wide_portable
// (unlike mulhi_u32_portable): as that one's high word, zienkiewicz on the Cortex-M0+ took 0.5 %
// more cycles at -O2 and 40 bytes more stack.
TS_INLINE inline int32_t mulhi_s32_portable(int32_t a, int32_t b) {
  const uint32_t a_lo = uint32_t(a) & 0xFFFFu, b_lo = uint32_t(b) & 0xFFFFu;
  const int32_t a_hi = a >> 16, b_hi = b >> 16;
  const int32_t t = a_hi * int32_t(b_lo) + int32_t((a_lo * b_lo) >> 16);
  const int32_t w = int32_t(a_lo) * b_hi + (t & 0xFFFF);
  return a_hi * b_hi + (t >> 16) + (w >> 16);
}

// a b, the signed 64-bit product, from the same four products (its low word from their low halves).
TS_INLINE inline int64_t mul_s32_wide_portable(int32_t a, int32_t b) {
  const uint32_t a_lo = uint32_t(a) & 0xFFFFu, b_lo = uint32_t(b) & 0xFFFFu;
  const int32_t a_hi = a >> 16, b_hi = b >> 16;
  const uint32_t lo_lo = a_lo * b_lo;
  const int32_t t = a_hi * int32_t(b_lo) + int32_t(lo_lo >> 16);
  const int32_t w = int32_t(a_lo) * b_hi + (t & 0xFFFF);
  const uint32_t high = uint32_t(a_hi * b_hi + (t >> 16) + (w >> 16));
  return int64_t((uint64_t(high) << 32) | (uint32_t(w) << 16) | (lo_lo & 0xFFFFu));
}

// The two above as calls, for builds optimized for size: about 20 instructions each, inlined at
// every product they would add kilobytes; a call still costs less than the library's 64 x 64
// product.
TS_NOINLINE inline int64_t mul_s32_wide_call(int32_t a, int32_t b) { return mul_s32_wide_portable(a, b); }
TS_NOINLINE inline int32_t mulhi_s32_call(int32_t a, int32_t b) { return mulhi_s32_portable(a, b); }

TS_INLINE inline int64_t mul_s32_wide(int32_t a, int32_t b) {
  if constexpr (tuning::multiplies_wide) {
    return int64_t(a) * b;  // one SMULL (Cortex-M3 and later), MUL and MULH (RISC-V M)
  } else if constexpr (TS_SIZE) {
    return mul_s32_wide_call(a, b);
  } else {
    return mul_s32_wide_portable(a, b);
  }
}

TS_INLINE inline int32_t mulhi_s32(int32_t a, int32_t b) {
  if constexpr (tuning::multiplies_wide) {
    return int32_t((int64_t(a) * b) >> 32);  // one SMULL (Cortex-M3 and later), MULH (RISC-V M)
  } else if constexpr (TS_SIZE) {
    return mulhi_s32_call(a, b);
  } else {
    return mulhi_s32_portable(a, b);
  }
}

// floor(n / d) and n mod d (*rem) for n < 2^31 and d >= 1, from inv = floor((2^32 - 1) / d): n inv /
// 2^32 is above n / d - n (d + 1) / (d 2^32) > n / d - 1, so the multiply-high is the quotient or
// one below, and one correction makes it exact.
TS_INLINE inline uint32_t divide_by_reciprocal(uint32_t n, uint32_t d, uint32_t inv, uint32_t* rem) {
  uint32_t q = mulhi_u32(n, inv);
  uint32_t r = n - q * d;
  if (r >= d) {
    ++q;
    r -= d;
  }
  *rem = r;
  return q;
}

inline uint64_t mulhi_u64(uint64_t a, uint64_t b) {
#if TS_USE_INT128
  __extension__ typedef unsigned __int128 u128;
  return uint64_t((u128(a) * b) >> 64);
#else
  return mulhi_u64_portable(a, b);
#endif
}

// floor((2^32 u1 + u0) / v) for u1 < v (the quotient fits 32 bits), by two 32-bit divisions of
// 16-bit digits (Hacker's Delight, divlu): a hardware divide on Cortex-M4, where a 64-bit division
// is a library call of about 430 instructions. Each digit's estimate is corrected at most twice.
inline uint32_t div_64_32(uint32_t u1, uint32_t u0, uint32_t v) {
  const int s = __builtin_clz(v);  // v > u1 >= 0
  v <<= s;
  const uint32_t vn1 = v >> 16, vn0 = v & 0xFFFFu;
  const uint32_t un32 = s ? (u1 << s) | (u0 >> (32 - s)) : u1;
  const uint32_t un10 = u0 << s;
  const uint32_t un1 = un10 >> 16, un0 = un10 & 0xFFFFu;
  uint32_t q1 = un32 / vn1, rhat = un32 - q1 * vn1;
  while (q1 > 0xFFFFu || q1 * vn0 > ((rhat << 16) | un1)) {
    --q1;
    rhat += vn1;
    if (rhat > 0xFFFFu) break;
  }
  const uint32_t un21 = (un32 << 16) + un1 - q1 * v;  // modulo 2^32: the true value is below v
  uint32_t q0 = un21 / vn1;
  rhat = un21 - q0 * vn1;
  while (q0 > 0xFFFFu || q0 * vn0 > ((rhat << 16) | un0)) {
    --q0;
    rhat += vn1;
    if (rhat > 0xFFFFu) break;
  }
  return (q1 << 16) | q0;
}

// floor((2^64 - 1) / d) for d > 0: the native division where it is one instruction (64-bit
// hosts), else two 32-bit steps when d < 2^32 (every divisor of the default configuration: twice
// the doubled area of a triangle of a 2048 x 2048 domain in 1/16 pixel is below 2^32).
inline uint64_t reciprocal_portable(uint64_t d) {
  if (d >> 32) return ~uint64_t(0) / d;
  const uint32_t d32 = uint32_t(d);
  const uint32_t hi = 0xFFFFFFFFu / d32;
  const uint32_t rem = 0xFFFFFFFFu - hi * d32;
  return (uint64_t(hi) << 32) | div_64_32(rem, 0xFFFFFFFFu, d32);
}

inline uint64_t reciprocal(uint64_t d) {
#if TS_USE_INT128
  return ~uint64_t(0) / d;
#else
  return reciprocal_portable(d);
#endif
}

// Exact division by one divisor d (0 < d < 2^62) used several times: the reciprocal
// m = floor((2^64 - 1) / d) is one division, then every quotient is a high multiply and at most
// one correction: 2^64 - m d <= d, so n / d - n m / 2^64 <= n / 2^64 < 1 and floor(n m / 2^64)
// is floor(n / d) or one less, for any n < 2^64. Same quotients as a division, bit for bit
// (tested against plain division).
class Divider {
 public:
  // k = 2^(62 - floor(log2 d)), so 2^62 <= k d < 2^63.
  explicit Divider(int64_t d)
      : d_(uint64_t(d)),
        m_(reciprocal(uint64_t(d))),
        k_(uint64_t(1) << (62 - (63 - __builtin_clzll(uint64_t(d))))),
        kd_(k_ * uint64_t(d)) {}

  // floor(n / d) for 0 <= n < 2^64.
  uint64_t floor_u(uint64_t n) const {
    const uint64_t q = mulhi_u64(n, m_);
    return q + (n - q * d_ >= d_);
  }
  // floor(n / d) for |n| < 2^62, as floor((n + k d) / d) - k: the numerator is then in
  // (0, 2^63 + 2^62), nonnegative and below 2^64, so no sign handling is needed.
  int64_t floor(int64_t n) const { return int64_t(floor_u(uint64_t(n) + kd_) - k_); }
  // floor((n + c) / d) for |n + c| < 2^62, with offset(c) = c + k d computed once for many n (the
  // same sums modulo 2^64 as floor).
  uint64_t offset(int64_t c) const { return uint64_t(c) + kd_; }
  int64_t floor_offset(int64_t n, uint64_t offset) const { return int64_t(floor_u(uint64_t(n) + offset) - k_); }

 private:
  uint64_t d_;
  uint64_t m_;
  uint64_t k_;
  uint64_t kd_;
};

// n / d rounded to nearest (halves up), for many n and one d: floor((2n + d) / (2d)), for
// |2n + d| < 2^62 (the setup's numerators stay below 2^61: docs/FIXED_POINT.md).
class RoundingDivider {
 public:
  explicit RoundingDivider(int64_t d) : div_(2 * d), offset_(div_.offset(d)) {}
  int64_t operator()(int64_t n) const { return div_.floor_offset(2 * n, offset_); }

 private:
  Divider div_;
  uint64_t offset_;  // the rounding offset d and the divider's k 2d, added once
};

// n / d rounded to nearest (halves up) like RoundingDivider, for numerators small against d:
// exact when |2n + d| * 2d < 2^64 (the caller proves it from its bit budget). With the reciprocal
// m = ceil(2^64 / D) (D = 2d >= 2), m D = 2^64 + e with 0 <= e < D, so for 0 <= x < 2^64 / D,
// x m / 2^64 = x / D + x e / (D 2^64) and x e < 2^64: the excess stays below 1 / D and cannot reach
// the next integer, so floor(x m / 2^64) = floor(x / D) without a correction. Negative x: with
// s = x >> 63 (all ones), floor(x / D) = ~floor(~x / D) (~x = -x - 1 >= 0), both as s ^ q(x ^ s).
class ShortRoundingDivider {
 public:
  explicit ShortRoundingDivider(int64_t d) : half_(d), m_(reciprocal(uint64_t(2 * d)) + 1) {}
  int64_t operator()(int64_t n) const {
    const int64_t x = 2 * n + half_;
    const int64_t s = x >> 63;
    return int64_t(mulhi_u64(uint64_t(x ^ s), m_)) ^ s;
  }

 private:
  int64_t half_;
  uint64_t m_;
};

// round(m 2^8 / d) modulo 2^32, halves up (RoundingDivider of n = m 2^8: q16_16 quotients of q8_8
// numerators, the bilinear set-up's), for any int32 m and 2 <= D = 2d <= 2^17, in 32-bit operations
// only: with m = q D + r, 0 <= r < D, floor((m 2^9 + d) / D) = q 2^9 + floor((r 2^9 + d) / D), and
// r 2^9 + d < 2^27. Only the quotient modulo 2^32 is computed: the bilinear set-up's every use is
// modulo 2^32 (BilinearChannel). Where a division is an instruction of a few cycles
// (tuning::divides_fast: Cortex-M3 and later) one signed division (floored) and one unsigned;
// elsewhere both quotients by D's 32-bit reciprocal, one division a triangle: a multiply-high and
// at most one correction each (quotient), no division per quotient (a library call on ARMv6-M, 3
// to 35 cycles on RISC-V cores).
// Both forms are compiled on every host (ByReciprocal), so that tests check both.
template <bool ByReciprocal>
class Mod32RoundingDividerOf {
 public:
  static constexpr uint32_t max_divisor = uint32_t(1) << 17;  // D = 2d at most this

  explicit Mod32RoundingDividerOf(int32_t d)
      : half_(uint32_t(d)), den_(uint32_t(2 * d)), inv_(ByReciprocal ? 0xFFFFFFFFu / uint32_t(2 * d) : 0u) {}
  TS_INLINE uint32_t small(int32_t m) const {
    if constexpr (!ByReciprocal) {
      int32_t q, r;
      floor_divmod32(m, int32_t(den_), &q, &r);  // D below 2^31
      return (uint32_t(q) << 9) + ((uint32_t(r) << 9) + half_) / den_;
    }
    // m = q D + r: for m < 0 from n = -(m + 1) >= 0, m = -(floor(n / D) + 1) D + (D - 1 - n mod D).
    uint32_t q, r;
    if (m >= 0) {
      q = quotient(uint32_t(m), &r);
    } else {
      uint32_t rn;
      q = ~quotient(uint32_t(-(m + 1)), &rn);
      r = den_ - 1 - rn;
    }
    uint32_t unused;
    return (q << 9) + quotient((r << 9) + half_, &unused);
  }

 private:
  TS_INLINE uint32_t quotient(uint32_t n, uint32_t* rem) const { return divide_by_reciprocal(n, den_, inv_, rem); }
  uint32_t half_;
  uint32_t den_;
  uint32_t inv_;
};
using Mod32RoundingDivider = Mod32RoundingDividerOf<!tuning::divides_fast>;

// n / d rounded to nearest (halves up) like RoundingDivider, for 0 < 2d < 2^32 and |2n + d| < 2^62,
// without a 64-bit division or a 64 x 64 product: the divisor's 32-bit reciprocal is computed once
// (one div_64_32), then each quotient below 2^32 takes one 32 x 32 -> 64 product and at most two
// corrections (Moller and Granlund, "Improved division by invariant integers", 2011, algorithm 4,
// which is exact for every u1:u0 with u1 < D normalized). x = 2n + d is divided by D = 2d as
// floor(x / D) = s ^ floor((x ^ s) / D) with s = x >> 63 (as ShortRoundingDivider); a quotient of
// 2^32 or more (|x| >= D 2^32: only where a value or gradient reaches 2^16 grey levels, i.e. slivers
// far thinner than a pixel) takes floor_div. The same quotients as a division, bit for bit (tested).
class PreinvRoundingDivider {
 public:
  // Whether d is in range: 0 < 2d < 2^32.
  static constexpr bool fits(int64_t d) { return d > 0 && d < (int64_t(1) << 31); }

  explicit PreinvRoundingDivider(int64_t d)
      : half_(d),
        den_(uint32_t(2 * d)),
        shift_(__builtin_clz(uint32_t(2 * d))),
        norm_(uint32_t(2 * d) << shift_),
        inv_(div_64_32(~norm_, 0xFFFFFFFFu, norm_)) {}  // floor((2^64 - 1) / norm) - 2^32

  TS_INLINE int64_t operator()(int64_t n) const {
    const int64_t x = 2 * n + half_;
    const int64_t s = x >> 63;
    const uint64_t u = uint64_t(x ^ s);
    uint32_t u1 = uint32_t(u >> 32), u0 = uint32_t(u);
    if (u1 >= den_) return floor_div(x, int64_t(den_));  // a quotient of 2^32 or more (rare)
    // Normalized: u1:u0 and D shifted left by shift_ (u1 < D keeps u1 < norm_). (u0 >> 1) >> (31 -
    // shift_) is u0 >> (32 - shift_) without a shift by 32 when shift_ is 0.
    u1 = (u1 << shift_) | ((u0 >> 1) >> (31 - shift_));
    u0 <<= shift_;
    const uint64_t p = mul_u32_wide(inv_, u1) + ((uint64_t(u1) << 32) | u0);
    uint32_t q = uint32_t(p >> 32) + 1;
    uint32_t r = u0 - q * norm_;
    if (r > uint32_t(p)) {
      --q;
      r += norm_;
    }
    if (r >= norm_) ++q;
    return int64_t(uint64_t(q) ^ uint64_t(s));
  }

 private:
  int64_t half_;
  uint32_t den_;
  int shift_;
  uint32_t norm_;
  uint32_t inv_;
};

// floor(x * y / 2^32) and floor(x * y / 2^30) for |x| < 2^61 and any int32 y (a q2_30 weight):
// the 96-bit product from two signed 32 x 32 -> 64 products, so no 128-bit type is needed (the
// same result everywhere; the native 128-bit product where there is one). x = xh 2^32 + xl with
// xl its low word read as signed (xh takes the borrow, |xh| <= 2^29): x y = (xh y + floor(xl y /
// 2^32)) 2^32 + u with 0 <= u < 2^32, the first a multiply-accumulate (SMULL, then SMLAL on
// Cortex-M4). Always inlined (-Os would call it for each product of a row's restart).
struct SplitProduct {
  int64_t high;  // floor(x y / 2^32)
  uint32_t low;  // x y mod 2^32
  TS_INLINE SplitProduct(int64_t x, int32_t y) {
    const int32_t xl = int32_t(uint32_t(x));
    const int32_t xh = int32_t(x >> 32) + int32_t(uint32_t(x) >> 31);
    const int64_t l = mul_s32_wide(xl, y);
    high = mul_s32_wide(xh, y) + (l >> 32);
    low = uint32_t(l);
  }
};
TS_INLINE inline int64_t mul_q30_portable(int64_t x, int32_t y) {
  const SplitProduct p(x, y);
  return int64_t(uint64_t(p.high) << 2) | int64_t(p.low >> 30);
}

TS_INLINE inline int64_t mul_q30(int64_t x, int32_t y) {
#if TS_USE_INT128
  __extension__ typedef __int128 i128;
  return int64_t((i128(x) * y) >> 30);
#else
  return mul_q30_portable(x, y);
#endif
}
TS_INLINE inline int64_t mul_q32(int64_t x, int32_t y) {
#if TS_USE_INT128
  __extension__ typedef __int128 i128;
  return int64_t((i128(x) * y) >> 32);
#else
  return SplitProduct(x, y).high;
#endif
}

// floor(x y / 2^64) for signed x, y: the high word of their 128-bit product (one multiply on
// 64-bit hosts; elsewhere mulhi_u64 with the sign corrections).
TS_INLINE inline int64_t mulhi_i64(int64_t x, int64_t y) {
#if TS_USE_INT128
  __extension__ typedef __int128 i128;
  return int64_t((i128(x) * y) >> 64);
#else
  return int64_t(mulhi_u64(uint64_t(x), uint64_t(y)) - (x < 0 ? uint64_t(y) : 0) - (y < 0 ? uint64_t(x) : 0));
#endif
}

// A signed 128-bit integer for exact sums of 64 x 64-bit products in per-triangle setup
// (two's complement in two words; only what the setup needs).
struct Wide {
  uint64_t lo = 0;
  uint64_t hi = 0;  // the high word, two's complement

  // Exact a * b.
  static Wide product(int64_t a, int64_t b) {
    const uint64_t ua = uint64_t(a), ub = uint64_t(b);
    Wide w;
    w.lo = ua * ub;
    w.hi = mulhi_u64(ua, ub) - (a < 0 ? ub : 0) - (b < 0 ? ua : 0);
    return w;
  }
  Wide operator+(const Wide& o) const {
    Wide w;
    w.lo = lo + o.lo;
    w.hi = hi + o.hi + (w.lo < lo ? 1 : 0);
    return w;
  }
  // round(value / 2^s), halves up, for 64 <= s < 127; the result must fit int64.
  int64_t round_shift(int s) const {
    const Wide half = s - 1 >= 64 ? Wide{0, uint64_t(1) << (s - 1 - 64)} : Wide{uint64_t(1) << (s - 1), 0};
    const Wide t = *this + half;
    return int64_t(t.hi) >> (s - 64);
  }
};

// Minimum and maximum in a form compilers turn into conditional moves: on triangle data the
// comparisons are unpredictable, and a mispredicted branch costs more than the whole test.
inline int32_t min2(int32_t a, int32_t b) { return b < a ? b : a; }
inline int32_t max2(int32_t a, int32_t b) { return b > a ? b : a; }
inline int32_t min3(int32_t a, int32_t b, int32_t c) { return min2(min2(a, b), c); }
inline int32_t max3(int32_t a, int32_t b, int32_t c) { return max2(max2(a, b), c); }

}  // namespace tristream::core::detail
