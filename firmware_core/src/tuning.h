/* SPDX-License-Identifier: MIT */
#pragma once
// The core's code-generation switches, in one place: inlining, placement (out of line) and
// unrolling. None changes a pixel; each trades speed, flash or stack on the targets named. The
// measured effect of each, as of a version, is in docs/MCU_BENCH.md; the reasons are here.
//
// The targets: Cortex-M (no SSE2, no 128-bit integers; speed at -O2 or size at -Os) and 64-bit
// hosts (x86-64 with SSE2 and 128-bit integers). TS_SIZE is 1 where the code is optimized for size.
#include "tristream/config.h"

#if defined(__OPTIMIZE_SIZE__)
#define TS_SIZE 1
#else
#define TS_SIZE 0
#endif

// Always inlined: a step of a per-pixel or per-row loop, or a small accessor whose values must stay
// in the caller's registers. GCC at -Os, and at -O2 in large callers, would otherwise call it.
#define TS_INLINE __attribute__((always_inline))

// Never inlined: a rare path kept out of the hot loop's code, or a function whose frame must not
// add to its caller's (the deepest stack is one frame of the two, not their sum).
#define TS_NOINLINE __attribute__((noinline))

// Before a loop of a fixed small count (a triangle's three vertices or edges, its channels): GCC
// keeps such loops rolled when their bodies select by index (k == 2 ? 0 : k + 1) or store through
// it, and then keeps their values in memory. Unrolled on Cortex-M; on x86-64 (SSE2) left to the
// compiler, which unrolls them where it pays. TS_UNROLL_FAST: the same, but not at -Os (where the
// flash it costs buys less).
#if !defined(__GNUC__) || TS_USE_SSE2
#define TS_UNROLL
#else
#define TS_UNROLL _Pragma("GCC unroll 4")
#endif
#if TS_SIZE
#define TS_UNROLL_FAST
#else
#define TS_UNROLL_FAST TS_UNROLL
#endif

// A shader's span (shader.h): inlined into the rasterizer's row loops at -O2 (no call per row);
// called at -Os, where a copy at every call site costs several KB of flash and cycles too.
#if TS_SIZE
#define TS_SPAN_INLINE
#else
#define TS_SPAN_INLINE TS_INLINE
#endif

// ZienkiewiczChannel::setup (interpolate.h): inlined into each shader's begin at -O2 (its loads
// and the triangle's edges stay in registers), one copy at -Os.
#if TS_SIZE
#define TS_ZIENKIEWICZ_SETUP_INLINE inline
#else
#define TS_ZIENKIEWICZ_SETUP_INLINE inline TS_INLINE
#endif

// Where the 32-bit forms of the zienkiewicz set-up are used (no 128-bit integers: Cortex-M):
// - CubicSteps::skip out of line (inlined, its binomials were formed on every restart of a row cut
//   by a tile's left edge) and ZienkiewiczChannel::setup_rows_within out of line (called per
//   channel; its frame would otherwise be the deepest of the zienkiewicz render);
// - ZienkiewiczTriangle::begin's parts out of line, one called after another, so the deepest stack
//   is one part's frame, not their sum.
// On 64-bit hosts all inlined: GCC would leave setup_rows_within out of line, and begin is one
// function there.
#if TS_USE_INT128
#define TS_CUBIC_SKIP_ATTRIBUTES
#define TS_SETUP_ROWS_ATTRIBUTES TS_INLINE
#define TS_ZIENKIEWICZ_BEGIN_PART inline TS_INLINE
#else
#define TS_CUBIC_SKIP_ATTRIBUTES TS_NOINLINE
#define TS_SETUP_ROWS_ATTRIBUTES TS_NOINLINE
#define TS_ZIENKIEWICZ_BEGIN_PART TS_NOINLINE
#endif

// BilinearShader::begin out of line with SSE2: inlined at one of rasterize's call sites it makes
// rasterize's bilinear RGB888 loop slower on x86-64. Elsewhere as the compiler chooses.
#if TS_USE_SSE2
#define TS_BILINEAR_BEGIN TS_NOINLINE
#else
#define TS_BILINEAR_BEGIN
#endif

// A compressed render's step between bands (its layer source's advance): out of line when
// optimizing for size, where GCC otherwise keeps the decoding's locals in the render's frame,
// under every tile's stack (core_compressed_stack_bytes); inlined for speed, where they share
// the frame's slots.
#if TS_SIZE
#define TS_BAND_ADVANCE TS_NOINLINE
#else
#define TS_BAND_ADVANCE
#endif

namespace tristream::core::detail::tuning {

// Whether a clamp to [0, 255] is one instruction (USAT: __ARM_FEATURE_SAT, Cortex-M3 and later).
// Where it is, clamps are written as clamps; elsewhere as a rare branch, and three channels in
// range are found by one test of their bitwise or (x86-64: fewer instructions a pixel than
// conditional moves).
#if defined(__ARM_FEATURE_SAT)
constexpr bool saturates = true;
#else
constexpr bool saturates = false;
#endif

// Whether __builtin_ctz and __builtin_clz are instructions (Cortex-M3 and later: CLZ, RBIT; x86-64;
// RISC-V with Zbb), not library calls (ARMv6-M, RISC-V without Zbb).
#if defined(__ARM_FEATURE_CLZ) || defined(__x86_64__) || defined(__aarch64__) || defined(__riscv_zbb)
constexpr bool scans_bits = true;
#else
constexpr bool scans_bits = false;
#endif

// Whether a 32-bit division is an instruction of a few cycles (SDIV, UDIV: Cortex-M3 and later, 2
// to 12 cycles; x86-64), not a library call (ARMv6-M) or a 3- to 35-cycle divider (RISC-V cores).
#if defined(__ARM_FEATURE_IDIV) || defined(__x86_64__) || defined(__aarch64__)
constexpr bool divides_fast = true;
#else
constexpr bool divides_fast = false;
#endif

// Whether a 32 x 32 -> 64 product is an instruction (UMULL, MULHU, x86-64), not a library call
// (ARMv6-M).
#if defined(__ARM_ARCH_6M__)
constexpr bool multiplies_wide = false;
#else
constexpr bool multiplies_wide = true;
#endif

// ZienkiewiczShader's forward differencing: with SSE2 set up within span, on the first long row
// (a separate call costs x86-64 more than it saves); elsewhere by first_long_row, a tail call from
// span, so that span's frame is gone before the set-up's (the deepest stack on Cortex-M).
constexpr bool zienkiewicz_set_up_in_span = TS_USE_SSE2;

// ZienkiewiczShader's writer: the caller's (draw_with's argument, alive for the shader's life) by
// reference where stack is scarce (not copied into the frame that holds the shader, the deepest of
// the render on Cortex-M4); a copy with SSE2, where stack is plentiful.
template <bool ByValue, typename Writer>
struct WriterHold {
  using type = const Writer&;
};
template <typename Writer>
struct WriterHold<true, Writer> {
  using type = Writer;
};
template <typename Writer>
using ZienkiewiczWriter = typename WriterHold<TS_USE_SSE2, Writer>::type;

}  // namespace tristream::core::detail::tuning
