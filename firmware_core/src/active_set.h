/* SPDX-License-Identifier: MIT */
#pragma once
// The active set of a layer: the triangles that meet the current band, as a ring bitmap in the
// caller's workspace.
#include <stddef.h>
#include <stdint.h>

#include "frame_plan.h"
#include "output_mapping.h"
#include "triangle_view.h"
#include "tristream/blob.h"

namespace tristream::core::detail {
namespace {

// The active triangles of one layer: a bitmap over the window [base, cursor) of the triangle
// stream (sorted by top row), in caller memory, addressed as a ring (triangle t at bit
// t mod capacity, unique while the window is no longer than the capacity). base only passes
// triangles that ended above the current band, so the window is the stretch from the oldest
// live triangle to the newest started one: at most the layer's triangle count, and one bit per
// triangle instead of an index per live triangle.
struct ActiveSet {
  const BlobLayer* layer = nullptr;
  uint32_t* words = nullptr;
  uint32_t capacity = 0;  // bits, a multiple of 32
  uint32_t base = 0;
  uint32_t cursor = 0;

  // Bit positions: pos(t) = t mod capacity, stepped with next() to avoid a division per test.
  // A capacity of 0 (a workspace without room for a bitmap) is valid for a window of 0.
  uint32_t pos(uint32_t t) const { return capacity ? t % capacity : 0; }
  uint32_t next(uint32_t p) const { return next(p, capacity); }
  bool test_at(uint32_t p) const { return (words[p / 32] >> (p % 32)) & 1u; }
  // next and setting a bit on a capacity and bitmap held in locals (advance's loop).
  static uint32_t next(uint32_t p, uint32_t capacity) { return p + 1 == capacity ? 0 : p + 1; }
  static void set_at(uint32_t* words, uint32_t p) { words[p / 32] |= 1u << (p % 32); }

  // Calls f(t, w, span, p) for the live triangles of the window a word at a time, in order: bit i
  // of w (nonzero) is triangle t + i, triangles t .. t + span - 1 are in the window (span <= 32),
  // and p is the bit position of triangle t (bit p % 32 of words[p / 32]).
  template <typename F>
  void for_each_live_word(F&& f) const {
    uint32_t t = base, p = base < cursor ? pos(base) : 0;
    while (t < cursor) {
      uint32_t w = words[p / 32] >> (p % 32);
      uint32_t span = 32 - p % 32;
      if (span > cursor - t) {
        span = cursor - t;
        w &= (1u << span) - 1;  // span < 32 here
      }
      if (w) f(t, w, span, p);
      t += span;
      p += span;
      if (p == capacity) p = 0;
    }
  }

  void reset() {
    for (uint32_t i = 0; i < capacity / 32; ++i) words[i] = 0;
    base = cursor = 0;
  }
  // Drops triangles ending above row y0, adds those starting at or before row y1 (inclusive).
  // False when the window would exceed the capacity.
  bool advance(const Mapping& map, int32_t y0, int32_t y1) {
    if (base < cursor) {
      // A word of the bitmap at a time: the ended triangles' bits collected without branches on
      // the data, then cleared at once (no division per triangle for its bit position).
      for_each_live_word([&](uint32_t t, uint32_t w, uint32_t, uint32_t p) {
        uint32_t ended = 0;
        for (; w; w &= w - 1) {
          const uint32_t i = uint32_t(__builtin_ctz(w));
          int32_t top, bottom;
          row_extent(*layer, t + i, map, &top, &bottom);
          ended |= uint32_t(bottom < y0) << i;
        }
        words[p / 32] &= ~(ended << (p % 32));
      });
      uint32_t p = pos(base);
      while (base < cursor && !test_at(p)) ++base, p = next(p);
    }
    // The window's ends, the bitmap and the bounds in locals: the bitmap's stores (uint32_t) could
    // alias the members, which the loop would otherwise load and store again a triangle.
    uint32_t b = base, c = cursor;
    uint32_t* const bits = words;
    const uint32_t n = layer->triangle_count, cap = capacity;
    bool fits = true;
    for (uint32_t p = c < n ? pos(c) : 0; c < n; p = next(p, cap)) {
      int32_t top, bottom;
      row_extent(*layer, c, map, &top, &bottom);
      if (top > y1) break;
      if (bottom >= y0 && top <= bottom) {
        if (c - b >= cap) {
          fits = false;
          break;
        }
        set_at(bits, p);
      } else if (b == c) {
        ++b;
      }
      ++c;
    }
    base = b;
    cursor = c;
    return fits;
  }
};

// Longest window of a layer's active set over the bands of the viewport (see ActiveSet), or
// `least` when none is longer. A band's window runs from its first live triangle to its cursor
// (the first triangle starting below the band), found by bisection (open_blob checks the top-row
// order). The first live triangle is found by a scan that only moves forward (a triangle not live
// in a band is live in no later one: it ended above, or has no rows) and stops where the window
// could no longer exceed the longest so far: each triangle's rows are read once at most, and
// render's check (least = the bitmap's capacity) reads only those of triangles more than the
// capacity behind a band's cursor.
inline uint32_t max_window(const BlobLayer& layer, const FramePlan& r, uint32_t least = 0) {
  uint32_t best = least, base = 0, cursor = 0;
  for (int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const int32_t y1 = (by + r.tile_h < r.view.y1 ? by + r.tile_h : r.view.y1) - 1;
    int32_t top, bottom;
    for (uint32_t hi = layer.triangle_count; cursor < hi;) {
      const uint32_t mid = cursor + (hi - cursor) / 2;
      row_extent(layer, mid, r.map, &top, &bottom);
      if (top > y1) {
        hi = mid;
      } else {
        cursor = mid + 1;
      }
    }
    // A triangle's last row is at or below the band's first exactly when its largest raw y
    // reaches `reach`: the triangles that ended need no mapping.
    const int32_t reach = r.map.first_y_at_least(by * (1 << config::subpixel_bits));
    for (; cursor - base > best; ++base) {
      if (raw_max_y(layer, base) < reach) continue;
      row_extent(layer, base, r.map, &top, &bottom);
      if (top <= bottom) {
        best = cursor - base;
        break;
      }
    }
  }
  return best;
}

}  // namespace
}  // namespace tristream::core::detail
