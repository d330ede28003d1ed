/* SPDX-License-Identifier: MIT */
#pragma once
// What the C API's translation units share (c_api.cpp, compressed_c_api.cpp): views of the C
// structs as the core's, the conversion of ts_params and the sink adapters. Internal linkage:
// each unit keeps its own copy of what it uses.
#include "tristream/compressed_blob.h"
#include "tristream/render_params.h"
#include "tristream/tristream.h"

namespace tristream_c_api {
namespace core = tristream::core;
namespace {

inline const core::Blob* view(const ts_blob* b) { return reinterpret_cast<const core::Blob*>(b); }
inline const core::CompressedBlob* view(const ts_compressed_blob* b) { return reinterpret_cast<const core::CompressedBlob*>(b); }

// The C formats start at 1 (0 is TS_FORMAT_UNSET); coverage counts, a test aid, have none.
constexpr core::PixelFormat c_formats[] = {core::PixelFormat::l8, core::PixelFormat::rgb888,
                                           core::PixelFormat::rgb565_le, core::PixelFormat::rgb565_be,
                                           core::PixelFormat::xrgb8888};
static_assert(TS_L8 == 1 && TS_RGB888 == 2 && TS_RGB565_LE == 3 && TS_RGB565_BE == 4 && TS_XRGB8888 == 5,
              "c_formats lists the C formats in order");

static_assert(TS_FIT_STRETCH == int(core::Fit::stretch) && TS_FIT_INSIDE == int(core::Fit::inside) &&
                  TS_FIT_FILL == int(core::Fit::fill),
              "the C fits are the values of core::Fit");

inline int c_format(core::PixelFormat f) {
  for (int i = 0; i < int(sizeof c_formats / sizeof c_formats[0]); ++i)
    if (c_formats[i] == f) return i + 1;
  return TS_FORMAT_UNSET;
}

inline bool convert(const ts_params* p, core::RenderParams* out) {
  if (!p || p->format < TS_L8 || p->format > TS_XRGB8888) return false;
  if (p->fit < TS_FIT_STRETCH || p->fit > TS_FIT_FILL) return false;
  out->output_width = p->output_width;
  out->output_height = p->output_height;
  out->viewport = core::Rect{p->viewport.x0, p->viewport.y0, p->viewport.x1, p->viewport.y1};
  out->tile_width = p->tile_width;
  out->tile_height = p->tile_height;
  out->format = c_formats[p->format - 1];
  out->dither = p->dither != 0;
  for (int c = 0; c < 3; ++c) out->background[c] = p->background[c];
  out->packed_tiles = p->packed_tiles != 0;
  out->fit = core::Fit(p->fit);
  out->target_stride = p->target_stride;
  out->target = p->target;
  return true;
}

inline core::RenderBuffers render_buffers(const ts_buffers& c) {
  core::RenderBuffers b;
  b.tile[0] = c.tile[0];
  b.tile[1] = c.tile[1];
  b.tile_bytes = c.tile_size;
  b.workspace = c.workspace;
  b.workspace_bytes = c.workspace_size;
  return b;
}

struct SinkAdapter {
  ts_sink sink;
  void* context;
};

inline ts_tile c_tile(const core::Tile* tile) {
  ts_tile t;
  t.pixels = tile->pixels;
  t.stride = tile->stride;
  t.rect = ts_rect{tile->rect.x0, tile->rect.y0, tile->rect.x1, tile->rect.y1};
  t.format = c_format(tile->format);
  return t;
}

inline void forward(void* context, const core::Tile* tile) {
  const SinkAdapter* a = static_cast<const SinkAdapter*>(context);
  const ts_tile t = c_tile(tile);
  a->sink(a->context, &t);
}

struct FrameSinkAdapter {
  ts_frame_sink sink;
  void* context;
};

inline bool forward_frame(void* context, const core::Tile* tile) {
  const FrameSinkAdapter* a = static_cast<const FrameSinkAdapter*>(context);
  const ts_tile t = c_tile(tile);
  return a->sink(a->context, &t) != 0;
}

}  // namespace
}  // namespace tristream_c_api
