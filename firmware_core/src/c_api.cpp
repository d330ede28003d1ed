// SPDX-License-Identifier: MIT
#include "tristream/tristream.h"

#include "c_api_support.h"
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
TS_SAME_STATUS(TS_BAD_CHECKSUM, bad_checksum)
#undef TS_SAME_STATUS

using namespace tristream_c_api;


// TS_PARAMS_INIT names every field: a field added to ts_params and not to the macro fails here
// (-Werror=missing-field-initializers), and its default must be what convert reads as the default.
#pragma GCC diagnostic push
#pragma GCC diagnostic error "-Wmissing-field-initializers"
static constexpr ts_params params_init = TS_PARAMS_INIT;
#pragma GCC diagnostic pop

extern "C" {

void ts_params_init(ts_params* params) {
  if (params) *params = params_init;
}

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
  if (!blob) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  SinkAdapter adapter{sink, context};
  return ts_status(core::render(*view(blob), p, tile_buffer, tile_buffer_size, workspace, workspace_size,
                                sink ? forward : nullptr, &adapter));
}

ts_status ts_render_frame(const ts_blob* blob, const ts_params* params, const ts_buffers* buffers, ts_frame_sink sink,
                          void* context) {
  core::RenderParams p;
  if (!blob || !buffers) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  const core::RenderBuffers b = render_buffers(*buffers);
  FrameSinkAdapter adapter{sink, context};
  return ts_status(core::render(*view(blob), p, b, sink ? forward_frame : nullptr, &adapter));
}

const char* ts_status_text(ts_status status) { return core::status_text(core::Status(status)); }

}  // extern "C"
