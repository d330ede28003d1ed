/* SPDX-License-Identifier: MIT */
#pragma once
// ZienkiewiczChannel's Horner evaluations (interpolate.h: eval32, steps_at) in Thumb-2 assembly
// with SMMLA, for Cortex-M with the DSP extension (TS_ARM_SMMLA 1). The same steps as the C forms
// there, which every other target uses (and which give the same values: SMMLA is mla_high): the
// coefficients are read in runs of loads (on Cortex-M4 a load right after a load takes one cycle,
// interleaved with the products two). GCC interleaves them in the C form, and a barrier on the
// loaded values costs register copies.
//
// One base register and the coefficients' offsets from it, the words one memory operand: an
// operand a coefficient takes an address register each where the compiler does not share them
// (-O0, clang), more than there are. interpolate.h asserts the offsets.
#include <stdint.h>

#include "../tuning.h"

#if defined(__ARM_FEATURE_DSP) && defined(__thumb2__)
#define TS_ARM_SMMLA 1
#else
#define TS_ARM_SMMLA 0
#endif

#if TS_ARM_SMMLA
namespace tristream::core::detail::arm {

// eval32 of the ten scaled coefficients s00, s01, s02, s03, s10, s11, s12, s20, s21, s30 at s
// (4 bytes apart, in that order).
TS_INLINE inline int32_t eval32(const int32_t* s, int32_t a, int32_t b) {
  int32_t v, t0, t1, t2, t3;
  __asm__(
      "ldr %[t3], [%[p], #12]\n\tldr %[t2], [%[p], #8]\n\tldr %[t1], [%[p], #4]\n\tldr %[t0], [%[p]]\n\t"
      "smmla %[t3], %[b], %[t3], %[t2]\n\tsmmla %[t3], %[b], %[t3], %[t1]\n\tsmmla %[v], %[b], %[t3], %[t0]\n\t"
      "ldr %[t2], [%[p], #36]\n\tldr %[t1], [%[p], #32]\n\tldr %[t0], [%[p], #28]\n\t"
      "smmla %[t1], %[b], %[t1], %[t0]\n\tsmmla %[t2], %[a], %[t2], %[t1]\n\t"
      "ldr %[t3], [%[p], #24]\n\tldr %[t1], [%[p], #20]\n\tldr %[t0], [%[p], #16]\n\t"
      "smmla %[t3], %[b], %[t3], %[t1]\n\tsmmla %[t3], %[b], %[t3], %[t0]\n\t"
      "smmla %[t2], %[a], %[t2], %[t3]\n\tsmmla %[v], %[a], %[t2], %[v]"
      : [v] "=&r"(v), [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2), [t3] "=&r"(t3)
      : [a] "r"(a), [b] "r"(b), [p] "r"(s), "m"(*reinterpret_cast<const int32_t(*)[10]>(s)));
  return v;
}

// steps_at's value, D1 and D2 (before the value's final shift) from the 20 words of
// ZienkiewiczChannel::RowCoefficients at r (e00 e01 e02 e10 e11 e20 e03x4 e12x4 e21x4 e30x4, g00
// g01 g10 g02x4 g11x4 g20x4, h00 h01x4 h10x4, d3), m's multiplicand shifted left by 2 first.
TS_INLINE inline void steps_at(const int32_t* r, int32_t a, int32_t b, int32_t* value, int32_t* d1_out,
                               int32_t* d2_out) {
  const auto& words = *reinterpret_cast<const int32_t(*)[20]>(r);
  int32_t d1, d2, v, t0, t1, t2, t3;
  __asm__(
      "ldr %[t0], [%[p], #56]\n\tldr %[t1], [%[p], #48]\n\tldr %[t2], [%[p], #60]\n\tldr %[t3], [%[p], #52]\n\t"
      "smmla %[t0], %[b], %[t0], %[t1]\n\tsmmla %[t2], %[a], %[t2], %[t0]\n\t"
      "ldr %[t1], [%[p], #44]\n\tldr %[t0], [%[p], #40]\n\t"
      "smmla %[t3], %[b], %[t3], %[t1]\n\tlsl %[t3], %[t3], #2\n\tsmmla %[t3], %[b], %[t3], %[t0]\n\t"
      "lsl %[t2], %[t2], #2\n\tsmmla %[d1], %[a], %[t2], %[t3]"
      : [d1] "=&r"(d1), [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2), [t3] "=&r"(t3)
      : [a] "r"(a), [b] "r"(b), [p] "r"(r), "m"(words));
  __asm__(
      "ldr %[t0], [%[p], #68]\n\tldr %[t1], [%[p], #64]\n\tldr %[t2], [%[p], #72]\n\t"
      "smmla %[t0], %[b], %[t0], %[t1]\n\tsmmla %[d2], %[a], %[t2], %[t0]"
      : [d2] "=&r"(d2), [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2)
      : [a] "r"(a), [b] "r"(b), [p] "r"(r), "m"(words));
  __asm__(
      "ldr %[t0], [%[p], #24]\n\tldr %[t1], [%[p], #8]\n\tldr %[t2], [%[p], #4]\n\tldr %[t3], [%[p]]\n\t"
      "smmla %[t0], %[b], %[t0], %[t1]\n\tlsl %[t0], %[t0], #2\n\tsmmla %[t0], %[b], %[t0], %[t2]\n\t"
      "lsl %[t0], %[t0], #2\n\tsmmla %[v], %[b], %[t0], %[t3]\n\t"
      "ldr %[t0], [%[p], #32]\n\tldr %[t1], [%[p], #20]\n\tldr %[t2], [%[p], #36]\n\t"
      "smmla %[t0], %[b], %[t0], %[t1]\n\tsmmla %[t2], %[a], %[t2], %[t0]\n\t"
      "ldr %[t0], [%[p], #28]\n\tldr %[t1], [%[p], #16]\n\tldr %[t3], [%[p], #12]\n\t"
      "smmla %[t0], %[b], %[t0], %[t1]\n\tlsl %[t0], %[t0], #2\n\tsmmla %[t0], %[b], %[t0], %[t3]\n\t"
      "lsl %[t2], %[t2], #2\n\tsmmla %[t2], %[a], %[t2], %[t0]\n\t"
      "lsl %[t2], %[t2], #2\n\tsmmla %[v], %[a], %[t2], %[v]"
      : [v] "=&r"(v), [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2), [t3] "=&r"(t3)
      : [a] "r"(a), [b] "r"(b), [p] "r"(r), "m"(words));
  *value = v;
  *d1_out = d1;
  *d2_out = d2;
}

}  // namespace tristream::core::detail::arm
#endif
