// SPDX-License-Identifier: MIT
#include "core_bridge/blob_error.h"

#include <cstdio>

#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "bytes.h"
#include "wire_layout.h"

namespace tristream {

namespace {

std::string hex32(std::uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", unsigned(v));
  return b;
}

}  // namespace

std::string blob_error_message(std::string_view name, std::span<const std::uint8_t> bytes, core::Status status,
                               std::uint32_t offset) {
  namespace h = core::wire::header;
  std::string m = std::string(name) + ": byte " + std::to_string(offset) + ": ";
  const bool v1 = bytes.size() >= h::bytes && core::wire::has_magic(bytes.data() + h::magic, core::wire::v1_magic);
  if (status == core::Status::bad_version && v1 && core::detail::load_u16(bytes.data() + h::version) == 1)
    return m + "version 1 blob without checksum: pack it again with tripack (this core reads version " +
           std::to_string(core::blob_version) + ")";
  const bool compressed =
      bytes.size() >= h::bytes && core::wire::has_magic(bytes.data() + h::magic, core::wire::compressed_magic);
  if (status == core::Status::bad_version && compressed &&
      core::detail::load_u16(bytes.data() + h::version) == core::compressed_version - 1)
    return m + "version " + std::to_string(core::compressed_version - 1) +
           " compressed blob, whose fresh third corners have no reach limit: pack it again with tripack --compress "
           "(this core reads version " + std::to_string(core::compressed_version) + ")";
  m += core::status_text(status);
  if (status == core::Status::bad_checksum && v1) {
    const std::uint32_t total = core::detail::load_u32(bytes.data() + h::total_size);  // open_blob checked it
    m += " (the header records CRC-32 " + hex32(core::detail::load_u32(bytes.data() + h::checksum)) +
         ", bytes 0.." + std::to_string(total - 1) + " have " + hex32(core::blob_checksum(bytes.data(), total)) + ")";
  }
  return m;
}

}  // namespace tristream
