/* SPDX-License-Identifier: MIT */
#pragma once
// The adaptive models of a compressed blob's layer stream (docs/COMPRESSED_BLOB.md), shared by the
// core's decoder (layer_decoder_state.h) and the host's encoder (host_sim/core_bridge/compress.cpp):
// one set of contexts, one adaptation rule.
#include <stdint.h>

namespace tristream::core::detail {

// An adaptive probability of a 0 in 1/2048 (11 bits), moved 1/32 of the way per coded bit.
using Prob = uint16_t;
inline constexpr int prob_bits = 11;
inline constexpr int prob_shift = 5;
inline constexpr Prob prob_half = 1u << (prob_bits - 1);

// Contexts of an unsigned integer u in adaptive Exp-Golomb form: k = floor(log2(u + 1)) as k ones
// and a zero (bit i with prefix[min(i, 15)]), then the k bits of u + 1 below its leading one, the
// first two through a small tree per k (mantissa[min(k, 15)]), the others at probability 1/2.
struct UintModel {
  Prob prefix[16];
  Prob mantissa[16][3];
};
// A signed integer: zero or not, the sign, then |s| - 1 as an UintModel.
struct IntModel {
  Prob zero;
  Prob sign;
  UintModel magnitude;
};

// Every context of one layer's stream (docs/COMPRESSED_BLOB.md lists what each codes) but the
// value models: those of the integer parts of the values (predicted, see the doc) and of the
// gradients (gx, gy, against their prediction), of which a layer has only those it codes
// (compressed_value_models), in its decoder's ring memory.
struct StreamModels {
  UintModel gap;            // raster pixel gap to the previous vertex
  Prob subpixel;            // the vertex has non-zero sub-pixel bits
  Prob fraction;            // some value of the vertex has a non-zero fraction byte
  // A triangle's first vertex a against the previous triangle's: 0, +1, +2, -1 or an escape (7) to
  // top_far, context: how the previous triangle's anchor and third vertex were coded (6 classes).
  Prob top[6][8];
  IntModel top_far;
  // The anchor s (a second corner): one of a's open edges (0, 1) or gap-coded (7); context: a's step.
  Prob anchor[3][8];
  UintModel anchor_gap;     // a gap-coded anchor: s - a - 1
  Prob side;                // a gap-coded anchor: the side of a->s the third corner is on
  // The third corner t: the predicted one (the largest angle over a->s among the candidates) or
  // not; if not, unused so far (then the count of such vertices in the edge's columns between a
  // and t) or a gap t - a - 1; contexts: how the anchor was coded (open edge 0, 1, gap-coded).
  Prob predicted[3];
  Prob fresh[3];
  UintModel fresh_count;
  UintModel third_gap;
  Prob lift;                // a corner far ahead is decoded into a pinned slot
  UintModel lift_gap;       // its raster pixel gap to the last vertex of the ring
  Prob rotation[2];
  Prob flags_nonzero;
  Prob flag_bit[9];
};

}  // namespace tristream::core::detail
