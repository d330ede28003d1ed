/* SPDX-License-Identifier: MIT */
#pragma once
// A blob file holds one blob and nothing after it. The core reads a blob from a pointer and a
// length that may run past its total size (a flash section padded or aligned beyond the blob) and
// ignores those bytes; a file the host tools read is the blob tripack wrote, so bytes after it are
// a damaged or wrong file (two blobs concatenated, a write appended to) and are refused.
#include <cstdint>
#include <span>
#include <string_view>

namespace tristream {

// Throws DataError "<name>: byte <total>: expected the end of the file, where the blob ends (its
// total size at byte 8), found N bytes more (a file of L bytes) ..." when `bytes` (a v1 or
// compressed blob the core has opened, so its header's total size is at most bytes.size()) run
// past the blob's total size.
void check_blob_file_length(std::span<const std::uint8_t> bytes, std::string_view name);

}  // namespace tristream
