// SPDX-License-Identifier: MIT
// The C API of compressed blobs (tristream.h: ts_open_compressed ... ts_render_compressed), apart
// from c_api.cpp so that a firmware without compressed blobs links none of it.
#include "c_api_support.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"
#include "tristream/tristream.h"

using namespace tristream_c_api;

extern "C" {

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
  if (!blob || !buffers) return ts_status(core::Status::null_argument);
  if (!convert(params, &p)) return ts_status(core::Status::bad_params);
  const core::RenderBuffers b = render_buffers(*buffers);
  FrameSinkAdapter adapter{sink, context};
  core::BlobError error;
  const core::Status s = core::render(*view(blob), p, b, sink ? forward_frame : nullptr, &adapter, &error);
  if (error_offset) *error_offset = error.offset;
  return ts_status(s);
}

}  // extern "C"
