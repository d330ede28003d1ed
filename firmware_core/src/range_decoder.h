/* SPDX-License-Identifier: MIT */
#pragma once
// The adaptive binary range decoder of compressed blobs and its integer binarizations
// (docs/COMPRESSED_BLOB.md). One multiply and one shift per coded bit, no division, no table.
// Reading past the stream's end yields zero bytes and sets `overrun` (a valid stream never does:
// the encoder flushes the bytes the decoder reads ahead), so no read leaves [p, end).
#include <stdint.h>

#include "stream_models.h"

namespace tristream::core::detail {

// The coder's state, set by start(); no initializers, so that the decoder state
// (layer_decoder_state.h) stays a trivial type.
struct RangeDecoder {
  const uint8_t* p;
  const uint8_t* end;
  uint32_t range;
  uint32_t code;
  bool overrun;  // asked for bytes past the end (never in a valid stream)
};

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
// The byte is read out of line (once in about eight bits); the test is inlined in every bit.
__attribute__((noinline)) inline void refill(RangeDecoder& d) {
  d.range <<= 8;
  d.code = (d.code << 8) | next_byte(d);
}
__attribute__((always_inline)) inline void normalize(RangeDecoder& d) {
  if (d.range < range_top) refill(d);
}

// One adaptive decision on a range and code (before the renormalisation), and its bit.
__attribute__((always_inline)) inline uint32_t decide(uint32_t& range, uint32_t& code, Prob& prob) {
  const uint32_t bound = (range >> prob_bits) * prob;
  if (code < bound) {
    range = bound;
    prob = Prob(prob + (((1u << prob_bits) - prob) >> prob_shift));
    return 0;
  }
  code -= bound;
  range -= bound;
  prob = Prob(prob - (prob >> prob_shift));
  return 1;
}

__attribute__((always_inline)) inline uint32_t decode_bit(RangeDecoder& d, Prob& prob) {
  const uint32_t bit = decide(d.range, d.code, prob);
  normalize(d);
  return bit;
}

// The same coder with its range and code in locals (registers) for the length of a multi-bit
// decode (an integer, a symbol), written back by `done`: the bits of one integer then cost no
// loads and stores of the coder's state. Only the byte reads touch `d` (p, end, overrun).
struct LocalCoder {
  RangeDecoder& d;
  uint32_t range, code;
  __attribute__((always_inline)) explicit LocalCoder(RangeDecoder& from) : d(from), range(from.range), code(from.code) {}
  __attribute__((always_inline)) void normalize() {
    if (range < range_top) {
      range <<= 8;
      code = (code << 8) | next_byte(d);
    }
  }
  __attribute__((always_inline)) uint32_t bit(Prob& prob) {
    const uint32_t b = decide(range, code, prob);
    normalize();
    return b;
  }
  // `count` (<= 31) bits at probability 1/2, most significant first.
  __attribute__((always_inline)) uint32_t direct(int count) {
    uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
      range >>= 1;
      const uint32_t b = code >= range;
      code -= range & (0u - b);
      v = (v << 1) | b;
      normalize();
    }
    return v;
  }
  __attribute__((always_inline)) void done() {
    d.range = range;
    d.code = code;
  }
};

// `count` (<= 31) bits at probability 1/2, most significant first.
inline uint32_t decode_direct(RangeDecoder& d, int count) {
  LocalCoder c(d);
  const uint32_t v = c.direct(count);
  c.done();
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
__attribute__((always_inline)) inline uint32_t decode_symbol8(LocalCoder& c, Prob* tree) {
  uint32_t node = 1;
  for (int i = 0; i < 3; ++i) node = (node << 1) | c.bit(tree[node]);
  return node - 8;
}
inline uint32_t decode_symbol8(RangeDecoder& d, Prob* tree) {
  LocalCoder c(d);
  const uint32_t v = decode_symbol8(c, tree);
  c.done();
  return v;
}

// An unsigned integer of at most `max_bits` bits (<= 31) below the leading one of u + 1; false
// when the prefix runs longer (a corrupt stream: the coder's state is then left unwritten, as a
// failed decoder is not read again).
__attribute__((always_inline)) inline bool decode_uint(LocalCoder& c, UintModel& m, int max_bits, uint32_t* out) {
  int k = 0;
  while (c.bit(m.prefix[k < 15 ? k : 15])) {
    if (++k > max_bits) return false;
  }
  uint32_t n = 1;
  if (k > 0) {
    Prob* tree = m.mantissa[k < 15 ? k : 15];
    n = 2 | c.bit(tree[0]);
    if (k > 1) {
      n = (n << 1) | c.bit(tree[1 + (n & 1)]);
      if (k > 2) n = (n << (k - 2)) | c.direct(k - 2);
    }
  }
  *out = n - 1;
  return true;
}
inline bool decode_uint(RangeDecoder& d, UintModel& m, int max_bits, uint32_t* out) {
  LocalCoder c(d);
  if (!decode_uint(c, m, max_bits, out)) return false;
  c.done();
  return true;
}

// A signed integer with |s| - 1 of at most max_bits bits (<= 31); the magnitude is at most 2^31.
inline bool decode_int(LocalCoder& c, IntModel& m, int max_bits, int64_t* out) {
  if (!c.bit(m.zero)) {
    *out = 0;
    return true;
  }
  const uint32_t negative = c.bit(m.sign);
  uint32_t u;
  if (!decode_uint(c, m.magnitude, max_bits, &u)) return false;
  const int64_t magnitude = int64_t(u) + 1;
  *out = negative ? -magnitude : magnitude;
  return true;
}
inline bool decode_int(RangeDecoder& d, IntModel& m, int max_bits, int64_t* out) {
  LocalCoder c(d);
  if (!decode_int(c, m, max_bits, out)) return false;
  c.done();
  return true;
}
// The same for max_bits <= 30, in 32 bits.
__attribute__((always_inline)) inline bool decode_int32(LocalCoder& c, IntModel& m, int max_bits, int32_t* out) {
  if (!c.bit(m.zero)) {
    *out = 0;
    return true;
  }
  const uint32_t negative = c.bit(m.sign);
  uint32_t u;
  if (!decode_uint(c, m.magnitude, max_bits, &u)) return false;
  const int32_t magnitude = int32_t(u) + 1;
  *out = negative ? -magnitude : magnitude;
  return true;
}

}  // namespace
}  // namespace tristream::core::detail
