/* SPDX-License-Identifier: MIT */
#pragma once
// The header fields a v1 blob (blob.h) and a compressed blob (compressed_blob.h) share, and their
// checks, written once: first the fields that frame the blob (version at 4, header size at 6, total
// size at 8), then sub-pixel and gradient bits at 20 and 21, the configuration hash at 24, width
// and height at 12 and 14, colour space, method, layer count and values per vertex at 16..19, and
// the zero flags at 22 (in that order). open_blob checks its checksum between the two.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/config.h"
#include "bytes.h"
#include "tristream/status.h"

namespace tristream::core::detail {

struct SharedHeader {
  uint32_t total = 0;
  uint16_t width = 0, height = 0;
  ColorSpace space = ColorSpace::grey;
  Method method = Method::bilinear;
  uint8_t layer_count = 0, values_per_vertex = 0;
};

// b: at least header_size bytes (the magic already checked); size: the caller's byte count.
// Returns Status::ok with the total size in *total (header_size .. size), or the first problem
// with its byte offset in *at.
inline Status check_frame(const uint8_t* b, size_t size, uint16_t version, uint32_t header_size, uint32_t* total,
                          uint32_t* at) {
  auto fail = [at](Status s, uint32_t offset) {
    *at = offset;
    return s;
  };
  if (load_u16(b + 4) != version) return fail(Status::bad_version, 4);
  if (load_u16(b + 6) != header_size) return fail(Status::bad_header, 6);
  *total = load_u32(b + 8);
  if (*total < header_size || *total > size) return fail(Status::truncated, 8);
  return Status::ok;
}

// b: a header whose frame check_frame accepted. Fills *h but its total; returns Status::ok, or
// the first problem with its byte offset in *at.
inline Status check_fields(const uint8_t* b, SharedHeader* h, uint32_t* at) {
  auto fail = [at](Status s, uint32_t offset) {
    *at = offset;
    return s;
  };
  if (b[20] != config::subpixel_bits) return fail(Status::config_mismatch, 20);
  if (b[21] != config::gradient_frac_bits) return fail(Status::config_mismatch, 21);
  if (load_u32(b + 24) != blob_config_hash()) return fail(Status::config_mismatch, 24);
  h->width = load_u16(b + 12);
  h->height = load_u16(b + 14);
  if (h->width < 2 || h->width > config::max_dimension) return fail(Status::too_large, 12);
  if (h->height < 2 || h->height > config::max_dimension) return fail(Status::too_large, 14);
  if (b[16] > 2) return fail(Status::bad_header, 16);
  h->space = ColorSpace(b[16]);
  if (b[17] > 1) return fail(Status::bad_header, 17);
  h->method = Method(b[17]);
  h->layer_count = b[18];
  h->values_per_vertex = b[19];
  const int channels = h->space == ColorSpace::grey ? 1 : 3;
  const bool single = h->layer_count == 1 && h->values_per_vertex == channels;
  const bool layered = channels == 3 && h->layer_count == 3 && h->values_per_vertex == 1;
  if (!single && !layered) return fail(Status::bad_header, h->layer_count == 1 || h->layer_count == 3 ? 19 : 18);
  if (load_u16(b + 22) != 0) return fail(Status::bad_header, 22);
  return Status::ok;
}

// check_frame, then check_fields (a header without a checksum).
inline Status check_shared_header(const uint8_t* b, size_t size, uint16_t version, uint32_t header_size,
                                  SharedHeader* h, uint32_t* at) {
  const Status s = check_frame(b, size, version, header_size, &h->total, at);
  return s == Status::ok ? check_fields(b, h, at) : s;
}

}  // namespace tristream::core::detail
