/* SPDX-License-Identifier: MIT */
#pragma once
// The header fields a v1 blob (blob.h) and a compressed blob (compressed_blob.h) share, and their
// checks, written once (offsets: wire_layout.h): first the fields that frame the blob (version,
// header size, total size), then sub-pixel and gradient bits, the configuration hash, width and
// height, colour space, method, layer count and values per vertex, and the zero flags (in that
// order). open_blob checks its checksum between the two.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/config.h"
#include "bytes.h"
#include "tristream/status.h"
#include "wire_layout.h"

namespace tristream::core::detail {

// b: at least header_size bytes (the magic already checked); size: the caller's byte count.
// Returns Status::ok with the total size in *total (header_size .. size), or the first problem
// with its byte offset in *at.
inline Status check_frame(const uint8_t* b, size_t size, uint16_t version, uint32_t header_size, uint32_t* total,
                          uint32_t* at) {
  namespace h = wire::header;
  auto fail = [at](Status s, uint32_t offset) {
    *at = offset;
    return s;
  };
  if (load_u16(b + h::version) != version) return fail(Status::bad_version, h::version);
  if (load_u16(b + h::header_size) != header_size) return fail(Status::bad_header, h::header_size);
  *total = load_u32(b + h::total_size);
  if (*total < header_size || *total > size) return fail(Status::truncated, h::total_size);
  return Status::ok;
}

// b: a header whose frame check_frame accepted. Fills *info but its bytes and size; returns
// Status::ok, or the first problem with its byte offset in *at.
inline Status check_fields(const uint8_t* b, BlobInfo* info, uint32_t* at) {
  namespace h = wire::header;
  auto fail = [at](Status s, uint32_t offset) {
    *at = offset;
    return s;
  };
  if (b[h::subpixel_bits] != config::subpixel_bits) return fail(Status::config_mismatch, h::subpixel_bits);
  if (b[h::gradient_frac_bits] != config::gradient_frac_bits)
    return fail(Status::config_mismatch, h::gradient_frac_bits);
  if (load_u32(b + h::config_hash) != blob_config_hash()) return fail(Status::config_mismatch, h::config_hash);
  info->width = load_u16(b + h::width);
  info->height = load_u16(b + h::height);
  if (info->width < 2 || info->width > config::max_dimension) return fail(Status::too_large, h::width);
  if (info->height < 2 || info->height > config::max_dimension) return fail(Status::too_large, h::height);
  if (b[h::color_space] > 2) return fail(Status::bad_header, h::color_space);
  info->space = ColorSpace(b[h::color_space]);
  if (b[h::method] > 1) return fail(Status::bad_header, h::method);
  info->method = Method(b[h::method]);
  info->layer_count = b[h::layer_count];
  info->values_per_vertex = b[h::values_per_vertex];
  const int channels = info->space == ColorSpace::grey ? 1 : 3;
  const bool single = info->layer_count == 1 && info->values_per_vertex == channels;
  const bool layered = channels == 3 && info->layer_count == 3 && info->values_per_vertex == 1;
  if (!single && !layered)
    return fail(Status::bad_header,
                info->layer_count == 1 || info->layer_count == 3 ? h::values_per_vertex : h::layer_count);
  if (load_u16(b + h::flags) != 0) return fail(Status::bad_header, h::flags);
  return Status::ok;
}

// check_frame, then check_fields (a header without a checksum): fills *info but its bytes.
inline Status check_shared_header(const uint8_t* b, size_t size, uint16_t version, uint32_t header_size,
                                  BlobInfo* info, uint32_t* at) {
  const Status s = check_frame(b, size, version, header_size, &info->size, at);
  return s == Status::ok ? check_fields(b, info, at) : s;
}

}  // namespace tristream::core::detail
