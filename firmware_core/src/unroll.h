/* SPDX-License-Identifier: MIT */
#pragma once
// TS_UNROLL: put before a loop of a fixed small count (a triangle's three vertices or edges, its
// channels) to have it unrolled on targets without SSE2 (Cortex-M). GCC keeps such loops rolled
// when their bodies select by index (k == 2 ? 0 : k + 1) or store through it, and then keeps their
// values in memory: unrolled, the Cortex-M4 scan path's set-up costs 5 % to 10 % fewer modelled
// cycles per frame. On x86-64 (SSE2) the loops stay as the compiler chooses (unrolled there, 1.6 %
// more instructions). TS_UNROLL_FAST: the same when optimizing for speed only (where the flash it
// costs at -Os buys less).
#include "tristream/config.h"

#if !defined(__GNUC__) || TS_USE_SSE2
#define TS_UNROLL
#else
#define TS_UNROLL _Pragma("GCC unroll 4")
#endif
#if defined(__OPTIMIZE_SIZE__)
#define TS_UNROLL_FAST
#else
#define TS_UNROLL_FAST TS_UNROLL
#endif
