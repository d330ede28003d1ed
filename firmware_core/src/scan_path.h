/* SPDX-License-Identifier: MIT */
#pragma once
// The scan path: small triangles (pixel box below scan_max_extent each way, no explicit corner) take
// int32 edge values and find each row's covered columns as a mask over the box (RowMasks), instead
// of the span steppers and their divisions. Both paths test the same exact predicate.
#include <stdint.h>

#include "shader.h"
#include "triangle_view.h"
#include "tristream/config.h"
#if TS_USE_SSE2
#include <emmintrin.h>
#include "scan_row_masks_sse2.h"
#else
#include "scan_row_masks_scalar.h"
#endif
#include "tristream/blob.h"
#include "edge.h"
#include "unroll.h"
#include "tristream/fixed_point.h"

namespace tristream::core::detail {
namespace {

static_assert(scan_max_extent <= 62, "the scan path's int32 edge values need boxes below 64 pixels");

// Edge values on the pixel box of a triangle whose box is below 64 x 64 pixels: for a pixel x of
// the box, |x 2^S - Px| < 64 * 2^S and |dy| < 64 * 2^S, so |E| < 2 * (64 * 2^S)^2 = 2^21 for
// S = 4 (and below 2^31 for every S up to 8), plus the bias; int32 suffices.
static_assert(2 * (int64_t(64) << config::subpixel_bits) * (int64_t(64) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path edge values must fit int32");

// RowMasks<Groups> (scan_row_masks_sse2.h, scan_row_masks_scalar.h): the covered columns of a box
// row as a 16-bit mask (bit i: column left + i), from the three edge values at the row's first
// column and their steps per column (a) and per row (b):
//   RowMasks(row, a, b, box)  the edges at the box's first pixel, per column, per row, and the
//                         box's columns as a mask;
//   uint32_t covered()    the current row's mask;
//   void next_row()       steps to the next row.
// With SSE2 four columns at a time and without branches, whose mispredictions cost more than the
// rest of a small triangle's rows; elsewhere column by column, stopping at the first uncovered
// column after the covered ones (a row's covered columns are contiguous).

// The edges of a scan-path triangle (edge k from vertex k to vertex k + 1) in int32, with its doubled
// area. Its vertices span fewer than scan_max_extent + 2 pixels each way, so every coordinate
// difference, and the offset of every vertex from a pixel of the box or from vertex 0 floored, is
// below 19 * 2^S: int16 (S <= 8), and the area is below 2 * (19 * 2^S)^2. Edge values
// E_k(x, y) = -dy_k (x 2^S - x_k) + dx_k (y 2^S - y_k): the same integer as A x + B y + C of
// detail/edge.h.
static_assert((int32_t(19) << config::subpixel_bits) < 32768, "scan-path differences must fit int16");
static_assert(2 * (int64_t(19) << config::subpixel_bits) * (int64_t(19) << config::subpixel_bits) < (int64_t(1) << 30),
              "scan-path areas must fit int32");
struct SmallEdges {
#if TS_USE_SSE2
  // Lane k: the int16 pair (-dy_k, dx_k) (low half, high half); A_k; B_k; E_k - bias_k at the box's
  // first pixel.
  __m128i pairs, a, b, row;
#else
  int32_t a[3], b[3], row[3];
  int32_t first[3];  // E_k at the box's first pixel (row without the bias), for small_setup
  int32_t left, y0;
#endif
  int32_t area2;
};

#if TS_USE_SSE2
// Lanes 0..2 (int32, each below 2^15 in magnitude) of lo and hi as int16 pairs (lo low, hi high).
inline __m128i int16_pairs(__m128i lo, __m128i hi) {
  return _mm_or_si128(_mm_and_si128(lo, _mm_set1_epi32(0xFFFF)), _mm_slli_epi32(hi, 16));
}
#endif

// The edges of a scan-path triangle, for its rows from (left, y0).
inline void small_edges(const TriangleView& tv, int32_t area2, int32_t left, int32_t y0, SmallEdges* e) {
  constexpr int S = config::subpixel_bits;
  e->area2 = area2;
#if TS_USE_SSE2
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i dx = _mm_sub_epi32(_mm_shuffle_epi32(x, _MM_SHUFFLE(3, 0, 2, 1)), x);
  const __m128i dy = _mm_sub_epi32(_mm_shuffle_epi32(y, _MM_SHUFFLE(3, 0, 2, 1)), y);
  const __m128i zero = _mm_setzero_si128();
  const __m128i neg_dy = _mm_sub_epi32(zero, dy);
  e->pairs = int16_pairs(neg_dy, dx);
  e->a = _mm_slli_epi32(neg_dy, S);
  e->b = _mm_slli_epi32(dx, S);
  // The tie rule of detail/edge.h.
  const __m128i bits = _mm_setr_epi32(boundary_edge0, boundary_edge0 << 1, boundary_edge0 << 2, 0);
  const __m128i boundary = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(tv.flags), bits), bits);
  const __m128i inclusive = inclusive_edge_lanes(dx, dy, boundary);
  const __m128i offsets = int16_pairs(_mm_sub_epi32(_mm_set1_epi32(left * (1 << S)), x),
                                      _mm_sub_epi32(_mm_set1_epi32(y0 * (1 << S)), y));
  // E - bias = E - 1 - (inclusive ? -1 : 0) = E + ~inclusive.
  e->row = _mm_add_epi32(_mm_madd_epi16(e->pairs, offsets), _mm_xor_si128(inclusive, _mm_set1_epi32(-1)));
#else
  e->left = left;
  e->y0 = y0;
  TS_UNROLL
  for (int k = 0; k < 3; ++k) {
    const int n = k == 2 ? 0 : k + 1;
    const int32_t dx = tv.x[n] - tv.x[k], dy = tv.y[n] - tv.y[k];
    e->a[k] = -dy * (1 << S);
    e->b[k] = dx * (1 << S);
    const bool inclusive = inclusive_edge(dx, dy, (tv.flags & (boundary_edge0 << k)) != 0);
    e->first[k] = -dy * (left * (1 << S) - tv.x[k]) + dx * (y0 * (1 << S) - tv.y[k]);
    e->row[k] = e->first[k] - (inclusive ? 0 : 1);
  }
#endif
}

// The setup of a scan-path triangle for the shader (on its first covered row in the clip).
// Without SSE2 e_ref32 and e_ref are set only where the shader reads them (ERefsRead).
template <unsigned Reads = scan_e_ref32 | scan_e_ref64>
inline void small_setup(const TriangleView& tv, const SmallEdges& e, TriangleSetup* s) {
  const int32_t xr = position_fx::from_raw(tv.x[0]).floor_to_int();
  const int32_t yr = position_fx::from_raw(tv.y[0]).floor_to_int();
  s->xr = xr;
  s->yr = yr;
  s->area2 = e.area2;
  s->scan_path = true;
#if TS_USE_SSE2
  constexpr int S = config::subpixel_bits;
  const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.x));
  const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(tv.y));
  const __m128i ref = _mm_madd_epi16(e.pairs, int16_pairs(_mm_sub_epi32(_mm_set1_epi32(xr * (1 << S)), x),
                                                          _mm_sub_epi32(_mm_set1_epi32(yr * (1 << S)), y)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->a), e.a);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->b), e.b);
  const __m128i sign = _mm_srai_epi32(ref, 31);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(s->e_ref), _mm_unpacklo_epi32(ref, sign));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(s->e_ref + 2), _mm_unpackhi_epi32(ref, sign));
#else
  // E_k is A_k x + B_k y + C_k (per pixel: a = A 2^S, b = B 2^S): from the box's first pixel.
  const int32_t ox = xr - e.left, oy = yr - e.y0;
  TS_UNROLL
  for (int k = 0; k < 3; ++k) {
    s->a[k] = e.a[k];
    s->b[k] = e.b[k];
    if (Reads != 0) {
      const int32_t ref = e.first[k] + e.a[k] * ox + e.b[k] * oy;
      if (Reads & scan_e_ref32) s->e_ref32[k] = ref;
      if (Reads & scan_e_ref64) s->e_ref[k] = ref;
    }
  }
#endif
}

template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader);

// Rows y0..y1 (already clipped) of a triangle whose pixel box has columns left..right: each row
// is scanned over the whole box, so xs is the row's first covered pixel even when the clip
// (columns cx0..cx1) cuts the span.
template <typename Shader>
void scan_small(const TriangleView& tv, int32_t area2, int32_t left, int32_t right, int32_t y0, int32_t y1,
                int32_t cx0, int32_t cx1, Shader& shader) {
  if (right < left) return;  // no pixel column between the vertices
  SmallEdges e;
  small_edges(tv, area2, left, y0, &e);
  const uint32_t box = (2u << (right - left)) - 1;  // covered columns at most; right - left < 16
  static_assert(scan_max_extent <= 16, "scan rows are at most four groups of four columns");
#if TS_USE_SSE2
  switch ((right - left) / 4) {
    case 0: return scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    case 1: return scan_rows<2>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    case 2: return scan_rows<3>(tv, e, left, box, y0, y1, cx0, cx1, shader);
    default: return scan_rows<4>(tv, e, left, box, y0, y1, cx0, cx1, shader);
  }
#else
  scan_rows<1>(tv, e, left, box, y0, y1, cx0, cx1, shader);  // one copy: Groups unused
#endif
}

// The rows of scan_small with masks of Groups * 4 columns (the box's width at most).
template <int Groups, typename Shader>
void scan_rows(const TriangleView& tv, const SmallEdges& e, int32_t left, uint32_t box, int32_t y0, int32_t y1,
               int32_t cx0, int32_t cx1, Shader& shader) {
  RowMasks<Groups> masks(e.row, e.a, e.b, box);
  bool started = false;
  for (int32_t y = y0; y <= y1; ++y, masks.next_row()) {
    const uint32_t mask = masks.covered() & box;
    if (!mask) continue;
    const int32_t xs = left + __builtin_ctz(mask);
    const int32_t x = left + 32 - __builtin_clz(mask);  // one past the last covered column
    const int32_t cs = xs > cx0 ? xs : cx0;
    const int32_t ce = x - 1 < cx1 ? x - 1 : cx1;
    if (cs > ce) continue;
    if (!started) {
      TriangleSetup s;
      small_setup<ERefsRead<Shader>::value>(tv, e, &s);
      shader.begin(tv, s);
      started = true;
    }
    shader.span(y, xs, x - 1, cs, ce);
  }
}

}  // namespace
}  // namespace tristream::core::detail
