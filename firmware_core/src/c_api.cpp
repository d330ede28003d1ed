// SPDX-License-Identifier: MIT
#include "tristream/tristream.h"

#include "tristream/compressed_blob.h"
#include "tristream/render.h"

namespace core = tristream::core;

static_assert(sizeof(core::Blob) <= sizeof(ts_blob), "ts_blob must hold a core::Blob");
static_assert(alignof(core::Blob) <= alignof(ts_blob), "ts_blob must be aligned for a core::Blob");
static_assert(sizeof(core::CompressedBlob) <= sizeof(ts_compressed_blob), "ts_compressed_blob must hold a core::CompressedBlob");
static_assert(alignof(core::CompressedBlob) <= alignof(ts_compressed_blob),
              "ts_compressed_blob must be aligned for a core::CompressedBlob");

// Every C status name is the value of its C++ enumerator, and none is missing.
#define TS_SAME_STATUS(c_name, cxx_name) \
  static_assert(c_name == int(core::Status::cxx_name), #c_name " must equal Status::" #cxx_name);
TS_SAME_STATUS(TS_OK, ok)
TS_SAME_STATUS(TS_NULL_ARGUMENT, null_argument)
TS_SAME_STATUS(TS_TRUNCATED, truncated)
TS_SAME_STATUS(TS_BAD_MAGIC, bad_magic)
TS_SAME_STATUS(TS_BAD_VERSION, bad_version)
TS_SAME_STATUS(TS_CONFIG_MISMATCH, config_mismatch)
TS_SAME_STATUS(TS_BAD_HEADER, bad_header)
TS_SAME_STATUS(TS_BAD_SECTION, bad_section)
TS_SAME_STATUS(TS_TOO_LARGE, too_large)
TS_SAME_STATUS(TS_COORDINATE_OUT_OF_RANGE, coordinate_out_of_range)
TS_SAME_STATUS(TS_VALUE_OUT_OF_RANGE, value_out_of_range)
TS_SAME_STATUS(TS_BAD_INDEX, bad_index)
TS_SAME_STATUS(TS_BAD_TRIANGLE, bad_triangle)
TS_SAME_STATUS(TS_UNSORTED, unsorted)
TS_SAME_STATUS(TS_BAD_PARAMS, bad_params)
TS_SAME_STATUS(TS_TILE_BUFFER_TOO_SMALL, tile_buffer_too_small)
TS_SAME_STATUS(TS_NOT_COMPILED, not_compiled)
TS_SAME_STATUS(TS_WORKSPACE_TOO_SMALL, workspace_too_small)
TS_SAME_STATUS(TS_STOPPED, stopped)
#undef TS_SAME_STATUS

namespace {

const core::Blob* view(const ts_blob* b) { return reinterpret_cast<const core::Blob*>(b); }
const core::CompressedBlob* view(const ts_compressed_blob* b) { return reinterpret_cast<const core::CompressedBlob*>(b); }

// The C formats start at 1 (0 is TS_FORMAT_UNSET); coverage counts, a test aid, have none.
constexpr core::PixelFormat c_formats[] = {core::PixelFormat::l8, core::PixelFormat::rgb888,
                                           core::PixelFormat::rgb565_le, core::PixelFormat::rgb565_be,
                                           core::PixelFormat::xrgb8888};
static_assert(TS_L8 == 1 && TS_RGB888 == 2 && TS_RGB565_LE == 3 && TS_RGB565_BE == 4 && TS_XRGB8888 == 5,
              "c_formats lists the C formats in order");

static_assert(TS_FIT_STRETCH == int(core::Fit::stretch) && TS_FIT_INSIDE == int(core::Fit::inside) &&
                  TS_FIT_FILL == int(core::Fit::fill),
              "the C fits are the values of core::Fit");

int c_format(core::PixelFormat f) {
  for (int i = 0; i < int(sizeof c_formats / sizeof c_formats[0]); ++i)
    if (c_formats[i] == f) return i + 1;
  return TS_FORMAT_UNSET;
}

bool convert(const ts_params* p, core::RenderParams* out) {
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
  return true;
}

struct SinkAdapter {
  ts_sink sink;
  void* context;
};

ts_tile c_tile(const core::Tile* tile) {
  ts_tile t;
  t.pixels = tile->pixels;
  t.stride = tile->stride;
  t.rect = ts_rect{tile->rect.x0, tile->rect.y0, tile->rect.x1, tile->rect.y1};
  t.format = c_format(tile->format);
  return t;
}

void forward(void* context, const core::Tile* tile) {
  const SinkAdapter* a = static_cast<const SinkAdapter*>(context);
  const ts_tile t = c_tile(tile);
  a->sink(a->context, &t);
}

struct FrameSinkAdapter {
  ts_frame_sink sink;
  void* context;
};

bool forward_frame(void* context, const core::Tile* tile) {
  const FrameSinkAdapter* a = static_cast<const FrameSinkAdapter*>(context);
  const ts_tile t = c_tile(tile);
  return a->sink(a->context, &t) != 0;
}

}  // namespace

extern "C" {

ts_status ts_open(const void* bytes, size_t size, ts_blob* blob, uint32_t* error_offset) {
  if (!blob) return ts_status(core::Status::null_argument);
  core::BlobError error;
  core::Blob* out = reinterpret_cast<core::Blob*>(blob);
  *out = core::Blob{};
  const core::Status s = core::open_blob(bytes, size, out, &error);
  if (error_offset) *error_offset = error.offset;
  return ts_status(s);
}

ts_status ts_tile_buffer_size(const ts_blob* blob, const ts_params* params, size_t* bytes) {
  core::RenderParams p;
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  return ts_status(core::tile_buffer_size(*view(blob), p, bytes));
}

ts_status ts_workspace_size(const ts_blob* blob, const ts_params* params, size_t* bytes) {
  core::RenderParams p;
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  return ts_status(core::workspace_size(*view(blob), p, bytes));
}

ts_status ts_render(const ts_blob* blob, const ts_params* params, void* tile_buffer, size_t tile_buffer_size,
                    void* workspace, size_t workspace_size, ts_sink sink, void* context) {
  core::RenderParams p;
  if (!blob || !sink) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  SinkAdapter adapter{sink, context};
  return ts_status(
      core::render(*view(blob), p, tile_buffer, tile_buffer_size, workspace, workspace_size, forward, &adapter));
}

ts_status ts_render_frame(const ts_blob* blob, const ts_params* params, const ts_buffers* buffers, ts_frame_sink sink,
                          void* context) {
  core::RenderParams p;
  if (!blob || !buffers || !sink) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  core::RenderBuffers b;
  b.tile[0] = buffers->tile[0];
  b.tile[1] = buffers->tile[1];
  b.tile_bytes = buffers->tile_size;
  b.workspace = buffers->workspace;
  b.workspace_bytes = buffers->workspace_size;
  FrameSinkAdapter adapter{sink, context};
  return ts_status(core::render(*view(blob), p, b, forward_frame, &adapter));
}

ts_status ts_open_compressed(const void* bytes, size_t size, ts_compressed_blob* blob, uint32_t* error_offset) {
  if (!blob) return ts_status(core::Status::null_argument);
  core::BlobError error;
  core::CompressedBlob* out = reinterpret_cast<core::CompressedBlob*>(blob);
  *out = core::CompressedBlob{};
  const core::Status s = core::open_compressed_blob(bytes, size, out, &error);
  if (error_offset) *error_offset = error.offset;
  return ts_status(s);
}

ts_status ts_compressed_tile_buffer_size(const ts_compressed_blob* blob, const ts_params* params, size_t* bytes) {
  core::RenderParams p;
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  return ts_status(core::tile_buffer_size(*view(blob), p, bytes));
}

ts_status ts_compressed_scratch_size(const ts_compressed_blob* blob, const ts_params* params, size_t* bytes) {
  core::RenderParams p;
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  return ts_status(core::measure_scratch_size(*view(blob), p, bytes));
}

ts_status ts_compressed_workspace_size(const ts_compressed_blob* blob, const ts_params* params, void* scratch,
                                       size_t scratch_size, size_t* bytes, uint32_t* error_offset) {
  core::RenderParams p;
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  core::BlobError error;
  const core::Status s = core::workspace_size(*view(blob), p, scratch, scratch_size, bytes, &error);
  if (error_offset) *error_offset = error.offset;
  return ts_status(s);
}

ts_status ts_render_compressed(const ts_compressed_blob* blob, const ts_params* params, const ts_buffers* buffers,
                               ts_frame_sink sink, void* context, uint32_t* error_offset) {
  core::RenderParams p;
  if (!blob || !buffers || !sink) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  core::RenderBuffers b;
  b.tile[0] = buffers->tile[0];
  b.tile[1] = buffers->tile[1];
  b.tile_bytes = buffers->tile_size;
  b.workspace = buffers->workspace;
  b.workspace_bytes = buffers->workspace_size;
  FrameSinkAdapter adapter{sink, context};
  core::BlobError error;
  const core::Status s = core::render(*view(blob), p, b, forward_frame, &adapter, &error);
  if (error_offset) *error_offset = error.offset;
  return ts_status(s);
}

const char* ts_status_text(ts_status status) { return core::status_text(core::Status(status)); }

}  // extern "C"
