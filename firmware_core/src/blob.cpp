// SPDX-License-Identifier: MIT
#include "tristream/blob.h"

#include "blob_header.h"
#include "crc32.h"
#include "bytes.h"
#include "tristream/fixed_point.h"
#include "wire_layout.h"

namespace tristream::core {

using detail::load_i32;
using detail::load_u16;
using detail::load_u32;

const char* status_text(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::null_argument: return "null argument";
    case Status::truncated: return "blob truncated";
    case Status::bad_magic: return "bad magic (expected \"TSTB\")";
    case Status::bad_version: return "unsupported blob version";
    case Status::config_mismatch: return "blob packed for another core configuration";
    case Status::bad_header: return "invalid header field";
    case Status::bad_section: return "section misaligned or out of bounds";
    case Status::too_large: return "size or count beyond the documented limits";
    case Status::coordinate_out_of_range: return "vertex outside the domain";
    case Status::value_out_of_range: return "vertex value or gradient out of range";
    case Status::bad_index: return "triangle vertex index out of range or repeated";
    case Status::bad_triangle: return "triangle with non-positive area or unknown flags";
    case Status::unsorted: return "triangles not sorted by top row";
    case Status::bad_params: return "invalid render parameters";
    case Status::tile_buffer_too_small: return "tile buffer too small (see tile_buffer_size)";
    case Status::workspace_too_small: return "workspace too small (see workspace_size)";
    case Status::stopped: return "stopped by the sink";
    case Status::bad_checksum: return "checksum mismatch: the blob is damaged";
    case Status::not_compiled: return "pixel format, method, colour space or layering not compiled into this core (config.h)";
  }
  return "unknown status";
}

uint32_t blob_checksum(const void* bytes, uint32_t total) {
  const uint8_t* b = static_cast<const uint8_t*>(bytes);
  const uint32_t after = wire::header::checksum + 4;
  return detail::crc32(detail::crc32(0, b, wire::header::checksum), b + after, total - after);
}

namespace {

struct Checker {
  const uint8_t* b;
  uint32_t size;
  BlobError* error;

  Status fail(Status s, uint32_t offset) const {
    if (error) error->offset = offset;
    return s;
  }
  // True when [offset, offset + count * unit) lies inside the blob after the header.
  bool section_ok(uint32_t offset, uint64_t count, uint32_t unit) const {
    if (offset < wire::header::bytes || offset % wire::section_alignment != 0) return false;
    uint64_t end = uint64_t(offset) + count * unit;
    return end <= size;
  }
};

Status check_layer(const Checker& c, const Blob& blob, uint32_t entry, BlobLayer* out) {
  namespace L = wire::v1_layer;
  namespace P = wire::position;
  namespace T = wire::triangle;
  const uint8_t* e = c.b + entry;
  uint32_t vertices = load_u32(e + L::vertex_count);
  uint32_t triangles = load_u32(e + L::triangle_count);
  uint32_t pos_off = load_u32(e + L::positions);
  uint32_t val_off = load_u32(e + L::values);
  uint32_t grad_off = load_u32(e + L::gradients);
  uint32_t tri_off = load_u32(e + L::triangles);
  for (uint32_t k = L::reserved; k < L::bytes; ++k)
    if (e[k] != 0) return c.fail(Status::bad_header, entry + k);
  if (vertices < 3 || vertices > blob_max_vertices) return c.fail(Status::too_large, entry + L::vertex_count);
  if (triangles < 1 || triangles > blob_max_triangles) return c.fail(Status::too_large, entry + L::triangle_count);
  const uint32_t nv = blob.values_per_vertex;
  if (!c.section_ok(pos_off, vertices, P::bytes)) return c.fail(Status::bad_section, entry + L::positions);
  if (!c.section_ok(val_off, uint64_t(vertices) * nv, wire::value::bytes))
    return c.fail(Status::bad_section, entry + L::values);
  if (blob.method == Method::zienkiewicz) {
    if (!c.section_ok(grad_off, uint64_t(vertices) * nv, wire::gradient::bytes))
      return c.fail(Status::bad_section, entry + L::gradients);
  } else if (grad_off != 0) {
    return c.fail(Status::bad_section, entry + L::gradients);
  }
  if (!c.section_ok(tri_off, triangles, T::bytes)) return c.fail(Status::bad_section, entry + L::triangles);

  const int32_t max_x = int32_t(blob.width - 1) << config::subpixel_bits;
  const int32_t max_y = int32_t(blob.height - 1) << config::subpixel_bits;
  for (uint32_t v = 0; v < vertices; ++v) {
    const uint32_t at = pos_off + P::bytes * v;
    if (int32_t(load_u16(c.b + at + P::x)) > max_x || int32_t(load_u16(c.b + at + P::y)) > max_y)
      return c.fail(Status::coordinate_out_of_range, at);
  }
  for (uint32_t k = 0; k < vertices * nv; ++k) {
    const uint32_t at = val_off + wire::value::bytes * k;
    if (load_u16(c.b + at) > 255 * 256) return c.fail(Status::value_out_of_range, at);
  }
  if (blob.method == Method::zienkiewicz) {
    // Every gx and gy alike: the section is 2 * vertices * nv i32s.
    static_assert(wire::gradient::gy == wire::gradient::gx + 4 && wire::gradient::bytes == 8, "gx, gy: two i32s");
    const int32_t limit = config::max_gradient << config::gradient_frac_bits;
    for (uint32_t k = 0; k < 2 * vertices * nv; ++k) {
      const uint32_t at = grad_off + 4 * k;
      const int32_t g = load_i32(c.b + at);
      if (g > limit || g < -limit) return c.fail(Status::value_out_of_range, at);
    }
  }
  int32_t previous_top = 0;
  for (uint32_t t = 0; t < triangles; ++t) {
    const uint32_t at = tri_off + T::bytes * t;
    const uint8_t* p = c.b + at;
    const uint32_t i0 = load_u16(p + T::corner(0)), i1 = load_u16(p + T::corner(1)), i2 = load_u16(p + T::corner(2));
    const uint16_t flags = load_u16(p + T::flags);
    if (i0 >= vertices || i1 >= vertices || i2 >= vertices || i0 == i1 || i1 == i2 || i0 == i2)
      return c.fail(Status::bad_index, at);
    if (flags & ~uint16_t(triangle_flags_mask)) return c.fail(Status::bad_triangle, at + T::flags);
    const uint8_t* pos = c.b + pos_off;
    const int64_t x0 = load_u16(pos + P::bytes * i0 + P::x), y0 = load_u16(pos + P::bytes * i0 + P::y);
    const int64_t x1 = load_u16(pos + P::bytes * i1 + P::x), y1 = load_u16(pos + P::bytes * i1 + P::y);
    const int64_t x2 = load_u16(pos + P::bytes * i2 + P::x), y2 = load_u16(pos + P::bytes * i2 + P::y);
    if ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) <= 0) return c.fail(Status::bad_triangle, at);
    int32_t top = int32_t(y0 < y1 ? (y0 < y2 ? y0 : y2) : (y1 < y2 ? y1 : y2));
    if (top < previous_top) return c.fail(Status::unsorted, at);
    previous_top = top;
  }
  out->vertex_count = vertices;
  out->triangle_count = triangles;
  out->positions = c.b + pos_off;
  out->values = c.b + val_off;
  out->gradients = blob.method == Method::zienkiewicz ? c.b + grad_off : nullptr;
  out->triangles = c.b + tri_off;
  return Status::ok;
}

}  // namespace

Status open_blob(const void* bytes, size_t size, Blob* out, BlobError* error) {
  if (!bytes || !out) return Status::null_argument;
  const uint8_t* b = static_cast<const uint8_t*>(bytes);
  Checker c{b, 0, error};
  if (size < wire::header::bytes) return c.fail(Status::truncated, uint32_t(size));
  // Where a halfword load needs an even address (ARMv6-M) the tile path reads the blob's arrays
  // by halfword loads (load_u16_even): a blob at an odd address would fault there.
  if (!detail::blob_address_fits(uintptr_t(b), TS_UNALIGNED_STORES)) return c.fail(Status::bad_section, 0);
  namespace h = wire::header;
  const char* magic = wire::v1_magic;  // tested byte by byte here: has_magic costs this function registers
  if (b[0] != magic[0] || b[1] != magic[1] || b[2] != magic[2] || b[3] != magic[3])
    return c.fail(Status::bad_magic, h::magic);
  BlobInfo info;
  info.bytes = b;
  uint32_t at = 0;
  Status s = detail::check_frame(b, size, blob_version, h::bytes, &info.size, &at);
  if (s != Status::ok) return c.fail(s, at);
  if (load_u32(b + h::checksum) != blob_checksum(b, info.size)) return c.fail(Status::bad_checksum, h::checksum);
  s = detail::check_fields(b, &info, &at);
  if (s != Status::ok) return c.fail(s, at);
  c.size = info.size;

  Blob blob;
  static_cast<BlobInfo&>(blob) = info;
  for (uint32_t k = h::v1_reserved; k < h::bytes; ++k)
    if (b[k] != 0) return c.fail(Status::bad_header, k);
  const uint32_t table = load_u32(b + h::layer_table);
  if (!c.section_ok(table, blob.layer_count, wire::v1_layer::bytes)) return c.fail(Status::bad_section, h::layer_table);
  for (uint32_t l = 0; l < blob.layer_count; ++l) {
    s = check_layer(c, blob, table + l * wire::v1_layer::bytes, &blob.layers[l]);
    if (s != Status::ok) return s;
  }
  *out = blob;
  return Status::ok;
}

}  // namespace tristream::core
