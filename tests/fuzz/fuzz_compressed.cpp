// SPDX-License-Identifier: MIT
// Fuzz target of the compressed blob: header checks, then (for headers that pass) the expansion
// to a v1 blob, which decodes every layer's stream. Every buffer is exactly sized (ASan sees
// overreads and overwrites); what expands must open as a v1 blob, and a second expansion into
// a buffer with different prior contents gives the same bytes (nothing depends on stale memory).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "tristream/compressed_blob.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace core = tristream::core;
  std::vector<std::uint8_t> bytes(data, data + size);
  core::CompressedBlob blob;
  core::BlobError error;
  if (core::open_compressed_blob(bytes.data(), bytes.size(), &blob, &error) != core::Status::ok) return 0;
  if (error.offset > size) std::abort();
  std::vector<std::uint8_t> out(core::expanded_blob_size(blob), 0x00), ring(core::expand_workspace_size(blob));
  const core::Status s = core::expand_compressed_blob(blob, out.data(), out.size(), ring.data(), ring.size(), &error);
  if (s != core::Status::ok) {
    if (error.offset > size) std::abort();
    return 0;
  }
  core::Blob v1;
  if (core::open_blob(out.data(), out.size(), &v1) != core::Status::ok) std::abort();
  std::vector<std::uint8_t> again(out.size(), 0xA5);
  std::memset(ring.data(), 0x5A, ring.size());
  if (core::expand_compressed_blob(blob, again.data(), again.size(), ring.data(), ring.size()) != core::Status::ok ||
      again != out)
    std::abort();
  return 0;
}
