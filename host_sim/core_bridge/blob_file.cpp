// SPDX-License-Identifier: MIT
#include "core_bridge/blob_file.h"

#include <string>

#include "bytes.h"
#include "common/errors.h"
#include "wire_layout.h"

namespace tristream {

void check_blob_file_length(std::span<const std::uint8_t> bytes, std::string_view name) {
  namespace h = core::wire::header;
  // Both blob forms record their total size at the same offset (wire_layout.h).
  if (bytes.size() < h::total_size + 4) return;
  const std::uint64_t total = core::detail::load_u32(bytes.data() + h::total_size);
  if (bytes.size() <= total) return;
  const std::uint64_t more = bytes.size() - total;
  const std::string t = std::to_string(total);
  throw DataError(std::string(name) + ": byte " + t +
                  ": expected the end of the file, where the blob ends (its total size at byte " +
                  std::to_string(h::total_size) + "), found " + std::to_string(more) +
                  (more == 1 ? " byte" : " bytes") + " more (a file of " + std::to_string(bytes.size()) +
                  " bytes): a blob file holds one blob; for a flash "
                  "image padded after its blob, keep its first " +
                  t + " bytes (head -c " + t + ")");
}

}  // namespace tristream
