// SPDX-License-Identifier: MIT
// The exact integer helpers of the core's setup: the reciprocal divider must give the same
// quotients as plain division, bit for bit, over the whole range the setup uses.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "arith.h"
#include "bytes.h"

using namespace tristream::core::detail;

namespace {

__extension__ typedef unsigned __int128 u128;

// The references: plain division.
std::int64_t floor_div64(std::int64_t n, std::int64_t d) {
  const std::int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
std::int64_t round_div(std::int64_t n, std::int64_t d) { return floor_div64(2 * n + d, 2 * d); }
std::int64_t reference_floor(std::int64_t n, std::int64_t d) { return floor_div64(n, d); }

}  // namespace

TEST_CASE("mulhi_u64_portable equals the 128-bit product's high half") {
  std::mt19937_64 rng(7);
  const std::uint64_t edges[] = {0, 1, 2, 0xFFFFFFFFull, 0x100000000ull, ~0ull, ~0ull - 1, 1ull << 63};
  for (std::uint64_t a : edges)
    for (std::uint64_t b : edges) CHECK(mulhi_u64_portable(a, b) == std::uint64_t((u128(a) * b) >> 64));
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t a = rng() >> (rng() % 64), b = rng() >> (rng() % 64);
    REQUIRE(mulhi_u64_portable(a, b) == std::uint64_t((u128(a) * b) >> 64));
    REQUIRE(mulhi_u64(a, b) == mulhi_u64_portable(a, b));
  }
}

TEST_CASE("div_64_32 and reciprocal_portable equal 64-bit division") {
  std::mt19937_64 rng(5);
  // Divisors of every length, with edge values near powers of two and the corrections' worst cases.
  std::vector<std::uint64_t> divisors = {1, 2, 3, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u,
                                         0xFFFFFFFEu, 0xFFFFFFFFu, 0x100000000ull, 0x100000001ull, 1ull << 62};
  for (int i = 0; i < 200000; ++i) divisors.push_back((rng() >> (rng() % 64)) | 1u);
  for (std::uint64_t d : divisors) {
    REQUIRE(reciprocal_portable(d) == ~0ull / d);
    if (d >> 32) continue;
    const std::uint32_t v = std::uint32_t(d);
    for (int j = 0; j < 4; ++j) {
      const std::uint32_t u1 = std::uint32_t(rng() % v), u0 = std::uint32_t(j == 0 ? 0xFFFFFFFFu : j == 1 ? 0 : rng());
      const std::uint64_t u = (std::uint64_t(u1) << 32) | u0;
      REQUIRE(div_64_32(u1, u0, v) == u / v);
    }
    REQUIRE(div_64_32(v - 1, 0xFFFFFFFFu, v) == ((std::uint64_t(v - 1) << 32) | 0xFFFFFFFFu) / v);
  }
}

TEST_CASE("Divider and RoundingDivider equal floor_div64 and round_div") {
  std::mt19937_64 rng(11);
  // Divisors: small, powers of two and their neighbours, random up to 2^61 (doubled areas
  // are below 2^31; the divider is exact for any d below 2^62 and |n| below 2^62).
  std::vector<std::int64_t> divisors = {1, 2, 3, 5, 7, 255, 256, 257, 65535, 65536, 65537, (1ll << 31) - 1,
                                        1ll << 31, (1ll << 61) - 1, 1ll << 61, (1ll << 62) - 1};
  for (int i = 0; i < 300; ++i) divisors.push_back(std::int64_t(1 + (rng() >> (3 + rng() % 61))));
  for (std::int64_t d : divisors) {
    const Divider div(d);
    const RoundingDivider round(d);
    const std::int64_t specials[] = {0, 1, -1, d - 1, d, d + 1, -d + 1, -d, -d - 1, 2 * d, -2 * d,
                                     (1ll << 61) - 1, -(1ll << 61) + 1, (1ll << 62) - 1, -(1ll << 62) + 1};
    for (std::int64_t n : specials) {
      INFO("n " << n << " d " << d);
      REQUIRE(div.floor(n) == reference_floor(n, d));
      // RoundingDivider: 2 (n / 2) + d within the divider's |n| < 2^62.
      if (d < (1ll << 60) && n < (1ll << 61) && n > -(1ll << 61)) REQUIRE(round(n / 2) == round_div(n / 2, d));
    }
    for (int i = 0; i < 2000; ++i) {
      const std::int64_t n = std::int64_t(rng() >> (2 + rng() % 62)) * ((rng() & 1) ? 1 : -1);
      INFO("n " << n << " d " << d);
      REQUIRE(div.floor(n) == reference_floor(n, d));
      if (d < (1ll << 60) && n < (1ll << 61) && n > -(1ll << 61)) REQUIRE(round(n / 2) == round_div(n / 2, d));
    }
  }
}

TEST_CASE("ShortRoundingDivider equals round_div wherever |2n + d| 2d < 2^64") {
  std::mt19937_64 rng(12);
  std::vector<std::int64_t> divisors = {1, 2, 3, 5, 7, 255, 256, 257, 65535, 65536, 65537, (1ll << 20) - 1,
                                        1ll << 20, (1ll << 31) - 1, 1ll << 31};
  for (int i = 0; i < 300; ++i) divisors.push_back(std::int64_t(1 + (rng() >> (33 + rng() % 31))));
  for (std::int64_t d : divisors) {
    const ShortRoundingDivider round(d);
    // The largest |2n + d| allowed: below 2^64 / (2d) (and 2^62, to stay clear of int64 limits).
    u128 limit = (u128(1) << 64) / u128(2 * d);
    if (limit > (u128(1) << 62)) limit = u128(1) << 62;
    const std::int64_t x_max = std::int64_t(limit - 1);
    // n at the ends of the range (2n + d = +-x_max, or as near as integers allow) and around 0.
    const std::int64_t specials[] = {0, 1, -1, d, -d, d - 1, -d + 1, (x_max - d) / 2, (-x_max - d) / 2 + 1,
                                     (x_max - d) / 2 - 1, (-x_max - d) / 2 + 2};
    for (std::int64_t n : specials) {
      INFO("n " << n << " d " << d);
      REQUIRE(round(n) == round_div(n, d));
    }
    for (int i = 0; i < 2000; ++i) {
      const std::int64_t x = std::int64_t(u128(rng()) % u128(x_max));
      const std::int64_t n = (((rng() & 1) ? x : -x) - d) / 2;
      INFO("n " << n << " d " << d);
      REQUIRE(round(n) == round_div(n, d));
    }
  }
}

TEST_CASE("mulhi_u32, mul_u32_wide and their 16-bit forms are the 64-bit product and its high word") {
  std::mt19937_64 rng(32);
  std::vector<std::uint32_t> values = {0, 1, 2, 0xFFFFu, 0x10000u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (int i = 0; i < 2000; ++i) values.push_back(std::uint32_t(rng() >> (32 + rng() % 32)));
  for (std::uint32_t a : values) {
    for (std::uint32_t b : values) {
      const std::uint32_t want = std::uint32_t((std::uint64_t(a) * b) >> 32);
      INFO("a " << a << " b " << b);
      REQUIRE(mulhi_u32_portable(a, b) == want);
      REQUIRE(mul_u32_wide_portable(a, b) == std::uint64_t(a) * b);
      REQUIRE(mul_u32_wide(a, b) == std::uint64_t(a) * b);
      REQUIRE(mulhi_u32(a, b) == want);
    }
  }
}

TEST_CASE("mulhi_s32, mul_s32_wide and their 16-bit forms are the signed 64-bit product and its high word") {
  std::mt19937_64 rng(33);
  std::vector<std::int32_t> values = {0, 1, -1, 2, -2, 0xFFFF, -0xFFFF, 0x10000, -0x10000, 0x7FFF, -0x8000,
                                      0x7FFFFFFF, -0x7FFFFFFF - 1, -0x7FFFFFFF, 0x40000000, -0x40000000};
  for (int i = 0; i < 2000; ++i) values.push_back(std::int32_t(std::uint32_t(rng() >> (32 + rng() % 32))));
  for (int i = 0; i < 1000; ++i) values.push_back(-std::int32_t(std::uint32_t(rng() >> (33 + rng() % 31))));
  for (std::int32_t a : values) {
    for (std::int32_t b : values) {
      const std::int32_t want = std::int32_t((std::int64_t(a) * b) >> 32);
      INFO("a " << a << " b " << b);
      REQUIRE(mulhi_s32_portable(a, b) == want);
      REQUIRE(mulhi_s32(a, b) == want);
      REQUIRE(mul_s32_wide_portable(a, b) == std::int64_t(a) * b);
      REQUIRE(mul_s32_wide(a, b) == std::int64_t(a) * b);
    }
  }
}

TEST_CASE("load_u16_even reads load_u16's value; blobs at odd addresses only where halfword loads take them") {
  alignas(4) const std::uint8_t bytes[8] = {0x34, 0x12, 0xFF, 0x00, 0x01, 0x80, 0xCD, 0xAB};
  for (int at = 0; at < 8; at += 2) CHECK(load_u16_even(bytes + at) == load_u16(bytes + at));
  // open_blob's test: any address with unaligned halfword loads; else (ARMv6-M) even ones only,
  // since the tile path reads the blob's arrays with load_u16_even.
  for (std::uintptr_t address : {0x20000000u, 0x20000002u, 0x08001234u}) {
    CHECK(blob_address_fits(address, true));
    CHECK(blob_address_fits(address, false));
  }
  for (std::uintptr_t address : {0x20000001u, 0x08001233u}) {
    CHECK(blob_address_fits(address, true));
    CHECK_FALSE(blob_address_fits(address, false));
  }
  CHECK(blob_address_fits(0x20000001u, TS_UNALIGNED_STORES) == bool(TS_UNALIGNED_STORES));
}

TEST_CASE("divide_by_reciprocal is floor division for n below 2^31") {
  std::mt19937_64 rng(31);
  std::vector<std::uint32_t> divisors = {1, 2, 3, 4095, 4096, 65535, 65536, 131071, 131072, 0x7FFFFFFFu};
  for (int i = 0; i < 4000; ++i) divisors.push_back(1 + std::uint32_t(rng() % (1u << (1 + rng() % 31))));
  for (std::uint32_t d : divisors) {
    const std::uint32_t inv = 0xFFFFFFFFu / d;
    std::vector<std::uint32_t> ns = {0, 1, d - 1, d, d + 1, 0x7FFFFFFFu, 0x7FFFFFFFu - d, 0x7FFFFFFFu / d * d};
    for (int i = 0; i < 200; ++i) ns.push_back(std::uint32_t(rng() >> (33 + rng() % 31)));
    for (std::uint32_t n : ns) {
      if (n > 0x7FFFFFFFu) continue;
      std::uint32_t r = 0;
      INFO("n " << n << " d " << d);
      REQUIRE(divide_by_reciprocal(n, d, inv, &r) == n / d);
      REQUIRE(r == n % d);
    }
  }
}

TEMPLATE_TEST_CASE("Mod32RoundingDivider (by divisions and by reciprocal) equals round_div of m 2^8 modulo 2^32 "
                   "wherever 2d <= 2^17",
                   "", Mod32RoundingDividerOf<false>, Mod32RoundingDividerOf<true>) {
  using Mod32RoundingDivider = TestType;
  std::mt19937_64 rng(17);
  constexpr std::int64_t d_max = std::int64_t(Mod32RoundingDivider::max_divisor / 2);
  std::vector<std::int64_t> divisors = {1, 2, 3, 255, 256, 257, 32767, 32768, 32769, d_max - 1, d_max};
  for (int i = 0; i < 3000; ++i) divisors.push_back(1 + std::int64_t(rng() % std::uint64_t(d_max)));
  auto expected = [](std::int64_t m, std::int64_t d) { return std::uint32_t(round_div(m * 256, d)); };
  for (std::int64_t d : divisors) {
    const Mod32RoundingDivider round{std::int32_t(d)};
    // The ends of both ranges, around 0, multiples of 2d and their neighbours (remainders 0 and
    // 2d - 1 of either sign), and the ties: m 2^9 + d a multiple of 2d needs d a multiple of 2^9.
    std::vector<std::int64_t> specials = {0, 1, -1, 2 * d, -2 * d, 2 * d - 1, -2 * d + 1, 2 * d + 1, -2 * d - 1,
                                          INT32_MAX, INT32_MIN, INT32_MAX - 1, INT32_MIN + 1};
    if (d % 512 == 0)
      for (std::int64_t k = -3; k <= 3; ++k) specials.push_back((k * 2 * d - d) / 512);
    for (std::int64_t m : specials) {
      INFO("m " << m << " d " << d);
      REQUIRE(round.small(std::int32_t(m)) == expected(m, d));
    }
    for (int i = 0; i < 300; ++i) {
      const auto m32 = std::int32_t(std::uint32_t(rng() >> (32 + rng() % 32)) * ((rng() & 1) ? 1u : ~0u));
      INFO("m " << m32 << " d " << d);
      REQUIRE(round.small(m32) == expected(m32, d));
    }
  }
}

TEST_CASE("PreinvRoundingDivider equals round_div wherever 0 < 2d < 2^32 and |2n + d| < 2^62") {
  std::mt19937_64 rng(19);
  constexpr std::int64_t d_max = (std::int64_t(1) << 31) - 1;
  constexpr std::int64_t x_max = (std::int64_t(1) << 62) - 1;
  std::vector<std::int64_t> divisors = {1, 2, 3, 255, 256, 257, 65535, 65536, 65537, (1ll << 30) - 1, 1ll << 30,
                                        (1ll << 30) + 1, d_max - 1, d_max};
  for (int i = 0; i < 3000; ++i) divisors.push_back(1 + std::int64_t((rng() >> (rng() % 33)) % std::uint64_t(d_max)));
  REQUIRE(PreinvRoundingDivider::fits(d_max));
  REQUIRE(!PreinvRoundingDivider::fits(d_max + 1));
  REQUIRE(!PreinvRoundingDivider::fits(0));
  for (std::int64_t d : divisors) {
    const PreinvRoundingDivider round(d);
    // Around 0, the ties, the ends of the range, and on both sides of a quotient of 2^32 (x = +-D
    // 2^32, where the divider changes method; inside the range |x| < 2^62 only for D < 2^30).
    std::vector<std::int64_t> specials = {0, 1, -1, d, -d, d - 1, -d + 1, d / 2, -d / 2, (x_max - d) / 2,
                                          (-x_max - d) / 2 + 1};
    if (d < (std::int64_t(1) << 29)) {
      const std::int64_t big = 2 * d * (std::int64_t(1) << 32);
      for (std::int64_t n : {(big - d) / 2, (big - d) / 2 - 1, (big - d) / 2 + 1, (-big - d) / 2, (-big - d) / 2 + 1,
                             (-big - d) / 2 - 1})
        specials.push_back(n);
    }
    for (std::int64_t n : specials) {
      INFO("n " << n << " d " << d);
      REQUIRE(round(n) == round_div(n, d));
    }
    for (int i = 0; i < 400; ++i) {
      const std::int64_t x = std::int64_t(rng() >> (2 + rng() % 62)) % x_max;
      const std::int64_t n = (((rng() & 1) ? x : -x) - d) / 2;
      INFO("n " << n << " d " << d);
      REQUIRE(round(n) == round_div(n, d));
    }
    for (std::int64_t k = -3; k <= 3; ++k) {  // exact halves: 2n + d = k 2d
      const std::int64_t n = (k * 2 * d - d) / 2;
      if ((k * 2 * d - d) % 2 == 0) REQUIRE(round(n) == round_div(n, d));
    }
    // The corrections: x = q D + r with r at the ends of [0, D) for quotients across [0, 2^32)
    // (within |x| < 2^62), where an estimate one off is caught by the remainder tests (2n + d = x
    // needs x - d even).
    const std::int64_t q_max = (x_max - 2 * d) / (2 * d);
    for (int i = 0; i < 200; ++i) {
      const std::int64_t q = std::int64_t(rng() >> (32 + rng() % 32)) % (q_max + 1);
      for (std::int64_t r : {std::int64_t(0), std::int64_t(1), 2 * d - 2, 2 * d - 1}) {
        for (std::int64_t x : {q * (2 * d) + r, -(q * (2 * d) + r)}) {
          if ((x - d) % 2 != 0) continue;
          const std::int64_t n = (x - d) / 2;
          INFO("n " << n << " d " << d);
          REQUIRE(round(n) == round_div(n, d));
        }
      }
    }
  }
}
