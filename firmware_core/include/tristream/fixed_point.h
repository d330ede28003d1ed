/* SPDX-License-Identifier: MIT */
#pragma once
// Fixed-point formats of the core, named by format: qI_F / fxI_F hold a value v as v * 2^F in an
// integer of I + F bits (plus sign). Bit budgets are in docs/FIXED_POINT.md.
#include <stdint.h>

#include "tristream/config.h"

namespace tristream::core {

template <typename Raw, int FracBits>
struct Fixed {
  using raw_type = Raw;
  static constexpr int frac_bits = FracBits;
  static constexpr Raw one = Raw(Raw(1) << FracBits);

  Raw raw = 0;

  static constexpr Fixed from_raw(Raw r) { return Fixed{r}; }
  static constexpr Fixed from_int(int32_t i) { return Fixed{Raw(Raw(i) * one)}; }
  // Largest integer <= value.
  constexpr int32_t floor_to_int() const { return int32_t(raw >> FracBits); }
  // Smallest integer >= value.
  constexpr int32_t ceil_to_int() const { return int32_t((raw + (one - 1)) >> FracBits); }
  // Nearest integer, halves rounded up.
  constexpr int32_t round_to_int() const { return int32_t((raw + (one >> 1)) >> FracBits); }
  constexpr bool is_integer() const { return (raw & (one - 1)) == 0; }
};

// Vertex positions in pixels with TS_SUBPIXEL_BITS fraction bits: fx28_4 with the default 4.
using position_fx = Fixed<int32_t, config::subpixel_bits>;
// Vertex values as stored in blobs: 0..255 with 8 fraction bits (unsigned 16-bit on the wire).
using q8_8 = Fixed<int32_t, 8>;
// Interpolated channel values handed to pixel writers: unclamped, 8 fraction bits.
using q24_8 = Fixed<int32_t, 8>;
// Bilinear values stepped along a span: |v| < 2^9 with 16 fraction bits.
using q16_16 = Fixed<int32_t, 16>;
// Barycentric coordinates stepped along a span: 0..1 with 30 fraction bits.
using q2_30 = Fixed<int32_t, 30>;
// Per-vertex gradients of zienkiewicz, value units per domain pixel.
using q19_12 = Fixed<int32_t, config::gradient_frac_bits>;

namespace detail {

constexpr int bits_for(int32_t n) {
  int b = 0;
  while ((int64_t(1) << b) < n) ++b;
  return b;
}

}  // namespace detail

// Budget: a coordinate is below D * 2^S (D = max dimension, S = sub-pixel bits), so a coordinate
// difference fits bits_for(D) + S + 1 signed bits, an edge function value (sum of two products of
// differences) fits 2 * (bits_for(D) + S) + 1 bits, and a span bound (edge value over a nonzero x
// coefficient, which is at least 2^S) fits 2 * bits_for(D) + S + 1 bits: it must fit int32.
inline constexpr int coordinate_bits = detail::bits_for(config::max_dimension) + config::subpixel_bits;
static_assert(coordinate_bits + 1 <= 16 + 1, "coordinate differences must fit 17 bits (int32 products)");
static_assert(2 * coordinate_bits + 1 <= 62, "edge functions must fit int64");
static_assert(2 * detail::bits_for(config::max_dimension) + config::subpixel_bits + 1 <= 30,
              "span bounds must fit int32 with headroom for stepping");
static_assert(position_fx::frac_bits == config::subpixel_bits, "position format follows the config");

}  // namespace tristream::core
