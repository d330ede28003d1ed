/* SPDX-License-Identifier: MIT */
#pragma once
// The per-triangle input of a shader, and the Shader interface.
//
// A Shader interpolates one triangle's values and hands each covered pixel to its Writer
// (pixel_writers.h). The rasterizer (rasterize.h, scan_path.h) calls, per triangle and tile:
//   void begin(const TriangleView& tv, const TriangleSetup& s)
//       once, before the first span, only when the triangle covers a pixel of the tile;
//   void span(int32_t y, int32_t xs, int32_t xe, int32_t x0, int32_t x1)
//       for each covered row y in order: the row's covered columns are [xs, xe] (whole row, also
//       outside the tile), of which [x0, x1] (non-empty) are in the tile and are to be written.
// The values of a pixel must not depend on the tile: a shader may use xs and xe (the whole row)
// to choose how it steps, never x0 and x1. Shaders: BilinearShader, ZienkiewiczShader.
#include <stdint.h>

#include "tristream/config.h"
#include "tuning.h"


namespace tristream::core::detail {
namespace {

// What a shader's begin needs besides the vertices: the edge coefficients (|a|, |b| < 2^20, see
// detail/edge.h), the exact edge values at the reference pixel (xr, yr) (vertex 0 floored), and the
// doubled area.
// Small boxes: pixel box below this many pixels each way. With SSE2 they are the scan path's
// triangles (scan_path.h, those without explicit corner): a row of a 16-column box costs about as
// much as the span steppers' row, without their setup. Elsewhere 15, the largest box whose
// bilinear set-up divides in 32 bits (Mod32RoundingDivider, 2d <= 2^17); the scan path takes the
// smaller boxes of portable/rasterize.h (scan_path_extent).
constexpr int32_t scan_max_extent = TS_USE_SSE2 ? 16 : 15;

struct TriangleSetup {
  int32_t a[4], b[4];  // a[3], b[3] unused (whole vectors for SSE2)
  int64_t e_ref[3];
  // The scan path's e_ref in int32 (|E| < 2^31: scan_path.h), without SSE2 only (where a 64 x 64
  // product is one instruction it would only add stores); unset otherwise.
  int32_t e_ref32[3];
  int32_t xr, yr;
  int64_t area2;
  // A pixel box below scan_max_extent each way (the set-up's 32-bit budgets; with SSE2 also the
  // scan path's triangles, which have no explicit corner).
  bool small_box;
};

// Which edge values at the reference pixel a shader's begin reads on scan-path triangles: e_ref32
// and e_ref unless the shader declares `static constexpr unsigned e_refs` (a mask of these).
// Without SSE2 the scan path then sets only those (none: begin works from the vertices).
// Span-path triangles always get e_ref.
constexpr unsigned scan_e_ref32 = 1, scan_e_ref64 = 2;
template <typename Shader, typename = void>
struct ERefsRead {
  static constexpr unsigned value = scan_e_ref32 | scan_e_ref64;
};
template <typename Shader>
struct ERefsRead<Shader, decltype(void(Shader::e_refs))> {
  static constexpr unsigned value = Shader::e_refs;
};

// Whether a shader's begin reads e_ref on a triangle whose box is not small, of doubled area
// area2: unless the shader declares `static constexpr bool large_reads_e_ref(int64_t area2)`,
// always.
template <typename Shader, typename = void>
struct LargeERefRead {
  static constexpr bool of(int64_t) { return true; }
};
template <typename Shader>
struct LargeERefRead<Shader, decltype(void(Shader::large_reads_e_ref(0)))> {
  static constexpr bool of(int64_t area2) { return Shader::large_reads_e_ref(area2); }
};

// Whether a shader draws a table of rows itself (portable/rasterize.h): a shader that declares
// `static constexpr bool draws_rows = true` has
//   void rows(const RowSpan* rows, int32_t y, int32_t n, int32_t cx0, int32_t cx1)
// which draws, of each row y + j, the covered columns rows[j] that are within [cx0, cx1] (the
// others: none), as span would.
template <typename Shader, typename = void>
struct DrawsRows {
  static constexpr bool value = false;
};
template <typename Shader>
struct DrawsRows<Shader, decltype(void(Shader::draws_rows))> {
  static constexpr bool value = Shader::draws_rows;
};

}  // namespace
}  // namespace tristream::core::detail
