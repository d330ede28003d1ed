/* SPDX-License-Identifier: MIT */
#pragma once
// The adaptive binary range decoder of compressed blobs and its integer binarizations
// (docs/COMPRESSED_BLOB.md). One multiply and one shift per coded bit, no division, no table.
// Reading past the stream's end yields zero bytes and sets `overrun` (a valid stream never does:
// the encoder flushes the bytes the decoder reads ahead), so no read leaves [p, end).
#include <stdint.h>

#include "tristream/compressed_blob.h"

namespace tristream::core::detail {
namespace {

constexpr uint32_t range_top = 1u << 24;

inline uint8_t next_byte(RangeDecoder& d) {
  if (d.p < d.end) return *d.p++;
  d.overrun = true;
  return 0;
}

// The encoder's first output byte is always zero and is not stored: the code starts with 4 bytes.
inline void start(RangeDecoder& d, const uint8_t* p, const uint8_t* end) {
  d.p = p;
  d.end = end;
  d.overrun = false;
  d.range = 0xFFFFFFFFu;
  d.code = 0;
  for (int i = 0; i < 4; ++i) d.code = (d.code << 8) | next_byte(d);
}

// After a bit the range is at least (2^24 >> 11) x 31 (a probability stays in [31, 2017]) or 2^23
// (a direct bit), so one byte restores it to 2^24 or more: an `if`, not a loop.
inline void normalize(RangeDecoder& d) {
  if (d.range < range_top) {
    d.range <<= 8;
    d.code = (d.code << 8) | next_byte(d);
  }
}

__attribute__((always_inline)) inline uint32_t decode_bit(RangeDecoder& d, Prob& prob) {
  const uint32_t bound = (d.range >> prob_bits) * prob;
  uint32_t bit;
  if (d.code < bound) {
    d.range = bound;
    prob = Prob(prob + (((1u << prob_bits) - prob) >> prob_shift));
    bit = 0;
  } else {
    d.code -= bound;
    d.range -= bound;
    prob = Prob(prob - (prob >> prob_shift));
    bit = 1;
  }
  normalize(d);
  return bit;
}

// `count` (<= 31) bits at probability 1/2, most significant first.
inline uint32_t decode_direct(RangeDecoder& d, int count) {
  uint32_t v = 0;
  for (int i = 0; i < count; ++i) {
    d.range >>= 1;
    const uint32_t bit = d.code >= d.range;
    d.code -= d.range & (0u - bit);
    v = (v << 1) | bit;
    normalize(d);
  }
  return v;
}

inline void reset(Prob* p, int n) {
  for (int i = 0; i < n; ++i) p[i] = prob_half;
}
inline void reset(UintModel& m) {
  reset(m.prefix, 16);
  reset(&m.mantissa[0][0], 16 * 3);
}
inline void reset(IntModel& m) {
  m.zero = m.sign = prob_half;
  reset(m.magnitude);
}

// A symbol of 3 bits through a binary tree of contexts (tree[1 .. 7]).
inline uint32_t decode_symbol8(RangeDecoder& d, Prob* tree) {
  uint32_t node = 1;
  for (int i = 0; i < 3; ++i) node = (node << 1) | decode_bit(d, tree[node]);
  return node - 8;
}

// An unsigned integer of at most `max_bits` bits (<= 31) below the leading one of u + 1; false
// when the prefix runs longer (a corrupt stream).
inline bool decode_uint(RangeDecoder& d, UintModel& m, int max_bits, uint32_t* out) {
  int k = 0;
  while (decode_bit(d, m.prefix[k < 15 ? k : 15])) {
    if (++k > max_bits) return false;
  }
  uint32_t n = 1;
  if (k > 0) {
    Prob* tree = m.mantissa[k < 15 ? k : 15];
    n = 2 | decode_bit(d, tree[0]);
    if (k > 1) {
      n = (n << 1) | decode_bit(d, tree[1 + (n & 1)]);
      if (k > 2) n = (n << (k - 2)) | decode_direct(d, k - 2);
    }
  }
  *out = n - 1;
  return true;
}

// A signed integer with |s| - 1 of at most max_bits bits (<= 31); the magnitude is at most 2^31.
inline bool decode_int(RangeDecoder& d, IntModel& m, int max_bits, int64_t* out) {
  if (!decode_bit(d, m.zero)) {
    *out = 0;
    return true;
  }
  const uint32_t negative = decode_bit(d, m.sign);
  uint32_t u;
  if (!decode_uint(d, m.magnitude, max_bits, &u)) return false;
  const int64_t magnitude = int64_t(u) + 1;
  *out = negative ? -magnitude : magnitude;
  return true;
}

}  // namespace
}  // namespace tristream::core::detail
