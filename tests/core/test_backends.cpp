// SPDX-License-Identifier: MIT
// The kernels' platform forms (firmware_core/src/backend.h) against each other: the portable form
// (every target without SSE2, Cortex-M among them) and the SSE2 form (x86-64 hosts) must give the
// same results for the same input. Here the tile cull's test (meeting: the bits of the triangles
// that meet a tile's columns, also checked against a direct test) and the scan path's part (the
// covered-column masks of every box row and the shader's set-up), and the pixels the shaders' SSE2
// lanes write against DirectWriter's (put_rounded). The span path's row bounds are
// compared in test_span_stepper.cpp; the golden images run with each form (test_core_golden and
// test_core_golden_portable). Without SSE2 (another host) the portable form is checked against the
// direct test only.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "tristream/config.h"
#include "pixel_writers.h"
#include "portable/scan_path.h"
#include "portable/tile_cull.h"
#include "sse2/pixel_writers.h"
#include "sse2/scan_path.h"
#include "sse2/tile_cull.h"
#include "triangle_records.h"

using namespace tristream::core;
using namespace tristream::core::detail;

namespace {

constexpr int S = config::subpixel_bits;

// The window of a tile's columns on raw vertex x, as ColumnWindow holds it.
struct Window {
  int32_t lo, hi;
};

// 32 records of layout Records (and their guard) over `positions`, with random vertices; in the
// band store's layouts some triangles are followed by a flag record (flagged[i]: record i is one).
template <typename Records>
std::vector<uint8_t> records(std::mt19937& rng, uint32_t vertex_count, std::vector<bool>* flagged) {
  std::vector<uint8_t> bytes(33 * Records::stride + 8, 0);
  flagged->assign(32, false);
  std::uniform_int_distribution<uint32_t> vertex(0, vertex_count - 1);
  for (uint32_t i = 0; i < 32; ++i) {
    uint8_t* p = bytes.data() + i * Records::stride;
    if (Records::has_flag_records && i > 0 && !(*flagged)[i - 1] && rng() % 5 == 0) {
      (*flagged)[i] = true;
      if constexpr (Records::stride == PackedStoreRecords::stride) {
        const uint32_t w = packed_flag_marker | (rng() & 0x1FF);
        std::memcpy(p, &w, 4);
      } else {
        p[0] = p[1] = 0xFF;
        p[2] = uint8_t(rng() & 0xFF);
      }
      continue;
    }
    const uint32_t v[3] = {vertex(rng), vertex(rng), vertex(rng)};
    if constexpr (Records::stride == PackedStoreRecords::stride) {
      const uint32_t w = PackedStoreRecords::pack(v[0], v[1], v[2]);
      std::memcpy(p, &w, 4);
    } else {
      for (int k = 0; k < 3; ++k) p[2 * k] = uint8_t(v[k]), p[2 * k + 1] = uint8_t(v[k] >> 8);
    }
  }
  return bytes;
}

// The direct test: triangle i meets the window unless its x are all below lo or all above hi - 1.
template <typename Records>
uint32_t meeting_direct(const Window& w, const BlobLayer& layer, uint32_t live) {
  uint32_t hits = 0;
  for (uint32_t i = 0; i < 32; ++i) {
    if (!(live >> i & 1)) continue;
    const uint8_t* p = layer.triangles + i * Records::stride;
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    for (int k = 0; k < 3; ++k) {
      const uint8_t* q = layer.positions + 4 * Records::vertex(p, k);
      const int32_t x = q[0] | q[1] << 8;
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    if (!(hi < w.lo || lo > w.hi - 1)) hits |= 1u << i;
  }
  return hits;
}

template <typename Records>
void check_meeting(uint32_t seed) {
  std::mt19937 rng(seed);
  const uint32_t vertex_count = Records::stride == PackedStoreRecords::stride ? 1024 : 3000;
  std::vector<uint8_t> positions(4 * vertex_count);
  // Vertex x anywhere in 16 bits, a share at the extremes and at the window's edges below.
  for (uint32_t v = 0; v < vertex_count; ++v) {
    const uint32_t r = rng() % 8;
    const uint32_t x = r == 0 ? 0 : (r == 1 ? 65535 : (r < 4 ? 30000 + rng() % 512 : rng() & 0xFFFF));
    positions[4 * v] = uint8_t(x), positions[4 * v + 1] = uint8_t(x >> 8);
  }
  for (int round = 0; round < 400; ++round) {
    std::vector<bool> flagged;
    const std::vector<uint8_t> bytes = records<Records>(rng, vertex_count, &flagged);
    BlobLayer layer;
    layer.vertex_count = vertex_count;
    layer.positions = positions.data();
    layer.triangles = bytes.data();
    // Windows as first_at_least gives them: 0 <= lo <= hi <= 65536; also lo == hi and the ends.
    int32_t a = int32_t(rng() % 65537), b = int32_t(rng() % 65537);
    if (round % 7 == 0) a = 30000 + int32_t(rng() % 512), b = a + int32_t(rng() % 64);
    if (round % 11 == 0) a = 0;
    if (round % 13 == 0) b = 65536;
    const Window w{std::min(a, b), std::max(a, b)};
    uint32_t live = rng();
    if (round % 3 == 0) live = 0xFFFFFFFFu;
    for (uint32_t i = 0; i < 32; ++i)
      if (flagged[i]) live &= ~(1u << i);  // a flag record is never live
    const uint32_t span = round % 4 == 0 ? 32 - rng() % 32 : 32;
    INFO("seed " << seed << " round " << round << " window [" << w.lo << ", " << w.hi << ") live " << live
                 << " span " << span);
    const uint32_t want = meeting_direct<Records>(w, layer, live);
    CHECK(portable::meeting<Records>(w, layer, 0, live, span) == want);
#if TS_USE_SSE2
    CHECK(sse2::meeting<Records>(w, layer, 0, live, span) == want);
#endif
  }
}

TEST_CASE("the tile cull's portable and SSE2 forms give the same bits") {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    check_meeting<BlobRecords>(seed);
    check_meeting<StoreRecords>(seed);
    check_meeting<PackedStoreRecords>(seed);
  }
}

// A random scan-path triangle (pixel box below 15 each way, positive orientation), as
// load_triangle gives it: its box's first column and row in *left and *top, last column *right.
bool small_triangle(std::mt19937& rng, TriangleView* tv, int32_t* left, int32_t* right, int32_t* top,
                    int32_t* bottom, int32_t* area2) {
  const int32_t ox = int32_t(rng() % 300) << S, oy = int32_t(rng() % 300) << S;
  const int32_t extent = int32_t(1 + rng() % 15) << S;
  *tv = TriangleView{};
  for (int k = 0; k < 3; ++k) {
    // On whole pixels (every encoder mesh) or anywhere.
    int32_t dx = int32_t(rng() % uint32_t(extent)), dy = int32_t(rng() % uint32_t(extent));
    if (rng() % 2) dx &= ~((1 << S) - 1), dy &= ~((1 << S) - 1);
    tv->x[k] = ox + dx, tv->y[k] = oy + dy;
    tv->v[k] = uint16_t(k);
  }
  *area2 = (tv->x[1] - tv->x[0]) * (tv->y[2] - tv->y[0]) - (tv->y[1] - tv->y[0]) * (tv->x[2] - tv->x[0]);
  if (*area2 < 0) {
    std::swap(tv->x[1], tv->x[2]), std::swap(tv->y[1], tv->y[2]);
    *area2 = -*area2;
  }
  tv->flags = uint16_t(rng() & 7);  // boundary edges
  auto ceil_px = [](int32_t v) { return (v + (1 << S) - 1) >> S; };
  *left = ceil_px(std::min({tv->x[0], tv->x[1], tv->x[2]}));
  *right = std::max({tv->x[0], tv->x[1], tv->x[2]}) >> S;
  *top = ceil_px(std::min({tv->y[0], tv->y[1], tv->y[2]}));
  *bottom = std::max({tv->y[0], tv->y[1], tv->y[2]}) >> S;
  return *area2 > 0 && *right >= *left && *bottom >= *top && *right - *left < 15 && *bottom - *top < 15;
}

// The covered columns of each row by the direct test of every pixel's edge values (the bias: 0
// on inclusive edges, 1 on the others), as masks over the box.
std::vector<uint32_t> masks_direct(const TriangleView& tv, int32_t left, int32_t right, int32_t top, int32_t bottom) {
  std::vector<uint32_t> out;
  for (int32_t y = top; y <= bottom; ++y) {
    uint32_t m = 0;
    for (int32_t x = left; x <= right; ++x) {
      bool in = true;
      for (int k = 0; k < 3; ++k) {
        const int n = (k + 1) % 3;
        const int32_t dx = tv.x[n] - tv.x[k], dy = tv.y[n] - tv.y[k];
        const int64_t e = -int64_t(dy) * ((x << S) - tv.x[k]) + int64_t(dx) * ((y << S) - tv.y[k]);
        const bool inclusive = inclusive_edge(dx, dy, (tv.flags & (boundary_edge0 << k)) != 0);
        in = in && e >= (inclusive ? 0 : 1);
      }
      if (in) m |= 1u << (x - left);
    }
    out.push_back(m);
  }
  return out;
}

template <typename Edges, typename Masks>
std::vector<uint32_t> masks_of(const Edges& e, uint32_t box, int32_t rows) {
  Masks masks(e.row, e.a, e.b, box);
  std::vector<uint32_t> out;
  for (int32_t y = 0; y < rows; ++y, masks.next_row()) {
    // The row's columns as a mask: bits first .. last.
    int32_t first = 0, last = -1;
    const bool any = masks.columns(box, &first, &last);
    out.push_back(any ? ((2u << last) - 1) & ~((1u << first) - 1) : 0u);
  }
  return out;
}

#if TS_USE_SSE2
template <int Groups>
std::vector<uint32_t> sse2_masks(const sse2::SmallEdges& e, uint32_t box, int32_t rows) {
  return masks_of<sse2::SmallEdges, sse2::RowMasks<Groups>>(e, box, rows);
}
#endif

TEST_CASE("the scan path's portable and SSE2 forms give the same masks and set-up") {
  std::mt19937 rng(38);
  int checked = 0;
  for (int round = 0; round < 20000; ++round) {
    TriangleView tv;
    int32_t left, right, top, bottom, area2;
    if (!small_triangle(rng, &tv, &left, &right, &top, &bottom, &area2)) continue;
    ++checked;
    INFO("triangle (" << tv.x[0] << "," << tv.y[0] << ") (" << tv.x[1] << "," << tv.y[1] << ") (" << tv.x[2] << ","
                      << tv.y[2] << ") flags " << tv.flags);
    const uint32_t box = (2u << (right - left)) - 1;
    const int32_t rows = bottom - top + 1;
    const std::vector<uint32_t> want = masks_direct(tv, left, right, top, bottom);
    portable::SmallEdges pe;
    portable::small_edges(tv, area2, left, top, &pe);
    CHECK((masks_of<portable::SmallEdges, portable::RowMasks<1>>(pe, box, rows) == want));
    TriangleSetup ps{};
    portable::small_setup<scan_e_ref32 | scan_e_ref64>(tv, pe, &ps);
    // The set-up's edge values at the reference pixel against the exact edge functions (edge.h).
    for (int k = 0; k < 3; ++k) {
      const int n = (k + 1) % 3;
      const Edge edge = make_edge(tv.x[k], tv.y[k], tv.x[n], tv.y[n], false);
      CHECK(ps.a[k] == edge.a);
      CHECK(ps.b[k] == edge.b);
      CHECK(ps.e_ref[k] == edge.exact_at(ps.xr, ps.yr));
      CHECK(ps.e_ref32[k] == edge.exact_at(ps.xr, ps.yr));
    }
#if TS_USE_SSE2
    sse2::SmallEdges se;
    sse2::small_edges(tv, area2, left, top, &se);
    std::vector<uint32_t> got;
    switch ((right - left) / 4) {
      case 0: got = sse2_masks<1>(se, box, rows); break;
      case 1: got = sse2_masks<2>(se, box, rows); break;
      case 2: got = sse2_masks<3>(se, box, rows); break;
      default: got = sse2_masks<4>(se, box, rows); break;
    }
    CHECK(got == want);
    TriangleSetup ss{};
    sse2::small_setup<scan_e_ref32 | scan_e_ref64>(tv, se, &ss);
    CHECK(ss.xr == ps.xr);
    CHECK(ss.yr == ps.yr);
    CHECK(ss.area2 == ps.area2);
    CHECK(ss.small_box == ps.small_box);
    for (int k = 0; k < 3; ++k) {
      CHECK(ss.a[k] == ps.a[k]);
      CHECK(ss.b[k] == ps.b[k]);
      CHECK(ss.e_ref[k] == ps.e_ref[k]);
    }
#endif
  }
  CHECK(checked > 5000);
}

#if TS_USE_SSE2
// sse2::PixelLanes<F>::put_lanes and put_span_lanes against DirectWriter::put_rounded of the same
// rounded values, in range and beyond it (clamped), with and without dithering.
template <PixelFormat F>
void check_pixel_lanes() {
  std::mt19937 rng(static_cast<uint32_t>(F) + 7);
  constexpr int bpp = bytes_per_pixel(F);
  using Px = sse2::PixelLanes<F>;
  for (int round = 0; round < 20000; ++round) {
    const bool dither = round & 1;
    const int32_t x = int32_t(rng() % 64), y = int32_t(rng() % 64);
    int32_t r[3];
    for (int c = 0; c < 3; ++c) {
      const uint32_t k = rng() % 8;
      r[c] = k == 0 ? -int32_t(rng() % 70000) : (k == 1 ? 256 + int32_t(rng() % 70000) : int32_t(rng() % 256));
    }
    uint8_t want[8] = {}, got[8] = {};
    DirectWriter<F, 3, false> w{want, 0, Rect{0, 0, 64, 64}, dither};
    w.put_rounded(want, x, y, r);
    Px::put_lanes(got, Px::ordered(_mm_setr_epi32(r[0], r[1], r[2], 0)), x, y, dither, false);
    INFO("format " << int(F) << " values " << r[0] << " " << r[1] << " " << r[2] << " dither " << dither);
    CHECK(std::memcmp(want, got, bpp) == 0);
  }
  // A span of q16_16 values (rounding offset included) in range, stepped.
  for (int round = 0; round < 2000; ++round) {
    const bool dither = round & 1;
    const int32_t x0 = int32_t(rng() % 16), n = 1 + int32_t(rng() % 24), y = int32_t(rng() % 64);
    uint32_t v[3], d[3];
    for (int c = 0; c < 3; ++c) {
      const uint32_t end = rng() % (256u << 16), start = rng() % (256u << 16);
      v[c] = start;
      d[c] = uint32_t((int64_t(end) - start) / n);
    }
    uint8_t want[32 * 4 + 4] = {}, got[32 * 4 + 4] = {};
    DirectWriter<F, 3, false> w{want, 0, Rect{0, 0, 64, 64}, dither};
    for (int32_t i = 0; i < n; ++i) {
      const int32_t q[3] = {int32_t((v[0] + d[0] * uint32_t(i)) >> 16), int32_t((v[1] + d[1] * uint32_t(i)) >> 16),
                            int32_t((v[2] + d[2] * uint32_t(i)) >> 16)};
      w.put_rounded(want + i * bpp, x0 + i, y, q);
    }
    Px::put_span_lanes(got, x0, x0 + n - 1, y, dither, Px::lanes(v[0], v[1], v[2], true), Px::lanes(d[0], d[1], d[2], false));
    INFO("format " << int(F) << " span of " << n << " dither " << dither);
    CHECK(std::memcmp(want, got, size_t(n * bpp)) == 0);
  }
}

TEST_CASE("the SSE2 pixel lanes write DirectWriter's pixels") {
  check_pixel_lanes<PixelFormat::rgb888>();
  check_pixel_lanes<PixelFormat::rgb565_le>();
  check_pixel_lanes<PixelFormat::rgb565_be>();
  check_pixel_lanes<PixelFormat::xrgb8888>();
}
#endif

}  // namespace
