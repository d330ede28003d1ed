// SPDX-License-Identifier: MIT
// The C form tripack --compress writes, linked into a program: its descriptor's bytes open, expand into the
// v1 blob tripack writes for the same mesh (up to the vertex numbering: same size, same header but
// its checksum, which covers the renumbered sections), and the header's figures are the core's.
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "demo_compressed.h"
#include "tristream/compressed_blob.h"

int main(int argc, char** argv) {
  namespace core = tristream::core;
  if (argc != 2) return 64;
  std::ifstream in(argv[1], std::ios::binary);
  const std::vector<unsigned char> v1((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  core::CompressedBlob blob;
  if (core::open_compressed_blob(demo_compressed.bytes, demo_compressed.size, &blob) != core::Status::ok) return 1;
  if (demo_compressed.size != DEMO_COMPRESSED_BYTES) return 6;
  if (core::expanded_blob_size(blob) != DEMO_COMPRESSED_EXPANDED_BYTES || core::expanded_blob_size(blob) != v1.size())
    return 2;
  if (core::expand_workspace_size(blob) != DEMO_COMPRESSED_DECODER_RING_BYTES) return 3;
  std::vector<unsigned char> out(DEMO_COMPRESSED_EXPANDED_BYTES), ring(DEMO_COMPRESSED_DECODER_RING_BYTES);
  if (core::expand_compressed_blob(blob, out.data(), out.size(), ring.data(), ring.size()) != core::Status::ok) return 4;
  for (std::size_t k = 0; k < core::blob_header_size; ++k)
    if ((k < core::blob_checksum_offset || k >= core::blob_checksum_offset + 4) && out[k] != v1[k]) return 5;
  std::printf("compressed C array: %u bytes, expands to %zu\n", unsigned(DEMO_COMPRESSED_BYTES), out.size());
  return 0;
}
