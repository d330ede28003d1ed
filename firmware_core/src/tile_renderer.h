/* SPDX-License-Identifier: MIT */
#pragma once
// One tile of a frame: the background, then each layer's live triangles that meet the tile with the
// shader of the blob's method and the writer of the pixel format; the tile function per format.
#include <stdint.h>
#include <string.h>

#include "active_set.h"
#include "bilinear_shader.h"
#include "channel_scratch.h"
#include "output_mapping.h"
#include "pixel_writers.h"
#include "rasterize.h"
#include "tile_cull.h"
#include "triangle_view.h"
#include "workspace_layout.h"
#include "zienkiewicz_shader.h"
#include "tristream/blob.h"
#include "tristream/config.h"
#include "tuning.h"
#include "pixel_conversion.h"
#include "tristream/render_params.h"

namespace tristream::core::detail {
namespace {

// Draws the live triangles of a layer that meet the tile `rect`. A triangle whose last pixel column
// is in this tile or left of it (nothing for the band's later tiles) and whose last row is in this
// band (the band advance would drop it) leaves the active set now: the later tiles of the band then
// skip it without the column test, and the band advance without reading its rows. The pixels are
// the same (those tiles would have culled it, the advance dropped it). When the tile spans the
// band's whole width (cull_columns false) every live triangle is drawn without the column test:
// the test only skips triangles that rasterize would clip away, so the pixels and the triangles
// found done are the same.
template <typename Records, typename Shader>
void draw_layer(ActiveSet& set, const Mapping& map, const Rect& rect, bool cull_columns, Shader& shader) {
  const ColumnWindow columns(map, rect);
  set.for_each_live_word([&](uint32_t t, uint32_t live, uint32_t span, uint32_t p) {
    uint32_t done = 0;
    if constexpr (IsBandStore<Records>::value) {
      // The band store's records in the layout of its slots (triangle_records.h): a test a word and
      // a triangle, one tile path for both layouts (rasterize keeps one call site, inlined). The
      // loop of a single layout below is kept apart: a helper choosing the layout for both loops
      // would change the v1 render's Cortex-M4 code.
      const BlobLayer& layer = *set.layer;
      const bool packed = layer.vertex_count <= store_packed_slots;
      uint32_t hits = live;
      if (cull_columns)
        hits = packed ? backend::meeting<PackedStoreRecords>(columns, layer, t, live, span)
                      : backend::meeting<StoreRecords>(columns, layer, t, live, span);
      for (; hits; hits &= hits - 1) {
        const uint32_t i = uint32_t(__builtin_ctz(hits));
        TriangleView tv;
        if (packed) {
          load_triangle<PackedStoreRecords>(layer, t + i, map, &tv);
        } else {
          load_triangle<StoreRecords>(layer, t + i, map, &tv);
        }
        done |= uint32_t(rasterize(tv, rect, shader)) << i;
      }
    } else {
      for (uint32_t hits = cull_columns ? backend::meeting<Records>(columns, *set.layer, t, live, span) : live; hits;
           hits &= hits - 1) {
        const uint32_t i = uint32_t(__builtin_ctz(hits));
        TriangleView tv;
        load_triangle<Records>(*set.layer, t + i, map, &tv);
        done |= uint32_t(rasterize(tv, rect, shader)) << i;
      }
    }
    set.words[p / 32] &= ~(done << (p % 32));
  });
}

template <typename Records, int Channels, typename Writer>
void draw_with(const Blob& blob, int layer_index, int first_channel, ActiveSet& list, const Mapping& map,
               const Rect& rect, bool cull_columns, const Writer& writer, int step) {
  const BlobLayer* layer = &blob.layers[layer_index];
  // Only the methods compiled in (plan_frame rejects the others before any tile is drawn).
  if (blob.method == Method::bilinear) {
    if constexpr (config::methods & 1) {
      BilinearShader<Channels, Writer> s{layer, blob.values_per_vertex, first_channel, writer, step, {}, 0, 0, {}};
      draw_layer<Records>(list, map, rect, cull_columns, s);
    }
  } else {
    if constexpr (config::methods & 2) {
      ZienkiewiczShader<Channels, Writer> s{
          {layer, blob.values_per_vertex, uint8_t(first_channel), 0, false, {}, {}}, writer, step};
      draw_layer<Records>(list, map, rect, cull_columns, s);
    }
  }
}

// Bytes [have, all) of p as copies of [0, have): doubling copies, [0, n) to [n, 2n) (never
// overlapping), then the rest. Out of line: one copy of the loop for rows and blocks of rows.
TS_NOINLINE inline void repeat_prefix(uint8_t* p, size_t have, size_t all) {
  while (have < all) {
    const size_t n = have < all - have ? have : all - have;
    memcpy(p + have, p, n);
    have += n;
  }
}

template <PixelFormat F>
void fill_background(uint8_t* base, int32_t stride, const Rect& rect, const RenderParams& p, bool grey) {
  // Without dithering every row is the same: write the first, copy it to the others. With it the
  // pixels repeat every 4 columns and every 4 rows (the Bayer matrix): 4 pixels of each of the
  // first 4 rows, copied along the row, then whole rows copied from 4 rows above.
  constexpr int bpp = bytes_per_pixel(F);
  const bool dithered = p.dither && (F == PixelFormat::rgb565_le || F == PixelFormat::rgb565_be);
  const int32_t period = dithered ? 4 : 1;
  // Rows back to back (the stride is a row), on Cortex-M: the first `period` rows, then the rest
  // of the tile as copies of them, a few long copies instead of one a row. Not on x86-64, where
  // copies beyond 2 KiB take glibc's `rep movsb` (counted per byte by tests/core/callgrind_core.sh).
  const bool contiguous = !TS_USE_SSE2 && size_t(stride) == size_t(rect.width()) * bpp;
  const size_t row_bytes = size_t(rect.width()) * bpp;
  const int32_t rows = contiguous && rect.height() > period ? period : rect.height();
  for (int32_t y = rect.y0; y < rect.y0 + rows; ++y) {
    uint8_t* row = base + (y - rect.y0) * stride;
    if (y - rect.y0 >= period) {
      memcpy(row, row - period * stride, row_bytes);
      continue;
    }
    const int32_t first = rect.width() < period ? rect.width() : period;
    for (int32_t x = rect.x0; x < rect.x0 + first; ++x) {
      uint8_t* px = row + (x - rect.x0) * bpp;
      if constexpr (F == PixelFormat::coverage8) {
        px[0] = 0;
      } else if (grey) {
        store_grey<F>(px, p.background[0], x, y, p.dither);
      } else {
        store_rgb<F>(px, p.background[0], p.background[1], p.background[2], x, y, p.dither);
      }
    }
    repeat_prefix(row, size_t(first) * bpp, row_bytes);
  }
  // The period's rows repeat: copies of [0, n rows) to [n, 2n), n a multiple of the period.
  if (rows < rect.height()) repeat_prefix(base, row_bytes * size_t(rows), row_bytes * size_t(rect.height()));
}

// fill_background out of line where zienkiewicz is compiled in on Cortex-M (no SSE2), and in
// builds for size: its registers then are not saved in render_tile's frame, under the tile
// function (the deepest stack). On x86-64, render_tile's code then does not change with the
// fill's. Inlined otherwise (Cortex-M4 bilinear at -O2: a call per tile costs more than it saves).
inline constexpr bool fill_apart = TS_SIZE || (config::methods & 2) != 0 || TS_USE_SSE2;
template <PixelFormat F>
TS_NOINLINE void fill_background_apart(uint8_t* base, int32_t stride, const Rect& rect,
                                                     const RenderParams& p, bool grey) {
  fill_background<F>(base, stride, rect, p, grey);
}

template <typename Records, PixelFormat F>
void render_tile(const Blob& blob, const RenderParams& p, const Mapping& map, ActiveSet* sets, const Rect& rect,
                 bool cull_columns, uint8_t* base, int32_t stride, int16_t* scratch) {
  const bool grey = blob.space == ColorSpace::grey;
  if constexpr (fill_apart) {
    fill_background_apart<F>(base, stride, rect, p, grey);
  } else {
    fill_background<F>(base, stride, rect, p, grey);
  }
  constexpr int bpp = bytes_per_pixel(F);
  // Only the colour spaces and layering compiled in (plan_frame rejects the others).
  constexpr uint32_t spaces = config::color_spaces;
  if (F == PixelFormat::coverage8 || !layered(blob)) {
    if (F == PixelFormat::coverage8 && layered(blob)) {
      if constexpr (config::layered) {
        const DirectWriter<F, 1, false> w{base, stride, rect, p.dither};
        for (int l = 0; l < blob.layer_count; ++l)
          draw_with<Records, 1>(blob, l, 0, sets[l], map, rect, cull_columns, w, bpp);
      }
    } else if (grey) {
      if constexpr (spaces & 1) {
        const DirectWriter<F, 1, false> w{base, stride, rect, p.dither};
        draw_with<Records, 1>(blob, 0, 0, sets[0], map, rect, cull_columns, w, bpp);
      }
    } else if (blob.space == ColorSpace::ycbcr) {
      if constexpr (spaces & 4) {
        const DirectWriter<F, 3, true> w{base, stride, rect, p.dither};
        draw_with<Records, 3>(blob, 0, 0, sets[0], map, rect, cull_columns, w, bpp);
      }
    } else {
      if constexpr (spaces & 2) {
        const DirectWriter<F, 3, false> w{base, stride, rect, p.dither};
        draw_with<Records, 3>(blob, 0, 0, sets[0], map, rect, cull_columns, w, bpp);
      }
    }
    return;
  }
  if constexpr (config::layered) {
    const int32_t n = rect.width() * rect.height() * 3;
    for (int32_t i = 0; i < n; ++i) scratch[i] = scratch_empty;
    for (int l = 0; l < blob.layer_count; ++l) {
      const ScratchWriter w{scratch, rect.width(), rect, l};
      draw_with<Records, 1>(blob, l, 0, sets[l], map, rect, cull_columns, w, 3);
    }
    convert_scratch<F>(scratch, base, stride, rect, p, blob.space == ColorSpace::ycbcr);
  }
}

// The tile function: cull_columns false when the tile spans its band's whole width.
using TileRenderer = void (*)(const Blob&, const RenderParams&, const Mapping&, ActiveSet*, const Rect&, bool,
                              uint8_t*, int32_t, int16_t*);

template <typename Records, PixelFormat F>
constexpr TileRenderer compiled_renderer() {
  if constexpr (config::pixel_formats >> int(F) & 1) {
    return render_tile<Records, F>;
  } else {
    return nullptr;
  }
}

// The tile function of a format for layers whose triangle records are laid out as Records
// (triangle_records.h); null for a format not compiled in (plan_frame rejects those).
template <typename Records>
inline TileRenderer tile_renderer(PixelFormat f) {
  switch (f) {
    case PixelFormat::l8: return compiled_renderer<Records, PixelFormat::l8>();
    case PixelFormat::rgb888: return compiled_renderer<Records, PixelFormat::rgb888>();
    case PixelFormat::rgb565_le: return compiled_renderer<Records, PixelFormat::rgb565_le>();
    case PixelFormat::rgb565_be: return compiled_renderer<Records, PixelFormat::rgb565_be>();
    case PixelFormat::xrgb8888: return compiled_renderer<Records, PixelFormat::xrgb8888>();
    case PixelFormat::coverage8: return compiled_renderer<Records, PixelFormat::coverage8>();
  }
  return nullptr;
}

}  // namespace
}  // namespace tristream::core::detail
