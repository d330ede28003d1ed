// SPDX-License-Identifier: MIT
// Fuzz target of the core: blob validation, then (for blobs that pass) sizing and rendering
// with parameters taken from the first 4 bytes. Validation must reject or accept without
// reading outside the input; rendering a validated blob must stay inside its buffers.
// The bytes are opened twice: as they are (the checksum refuses nearly every mutation), then
// sealed with their checksum (tests/support/blob_seal.h), so that mutations reach the field
// checks behind it and the renderer.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "../support/blob_seal.h"
#include "tristream/render.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace core = tristream::core;
  if (size < 4) return 0;
  const std::uint8_t* p = data;
  std::vector<std::uint8_t> bytes(data + 4, data + size);  // exactly sized: ASan sees overreads
  core::Blob blob;
  const bool raw_ok = core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok;
  tristream::testing::seal_blob(bytes.data(), bytes.size());
  if (core::open_blob(bytes.data(), bytes.size(), &blob) != core::Status::ok) {
    if (raw_ok) std::abort();  // sealing a blob that opened changes nothing
    return 0;
  }
  core::RenderParams params;
  params.tile_width = std::uint16_t(p[0] % 70);
  params.tile_height = std::uint16_t(p[1] % 70);
  params.format = core::PixelFormat(p[2] % core::pixel_format_count);
  params.dither = p[2] & 0x80;
  if (p[3] & 1) {
    params.output_width = std::uint16_t(2 + p[3] % 61);
    params.output_height = std::uint16_t(2 + (p[3] >> 2) % 47);
  }
  if (p[3] & 2) params.viewport = core::Rect{1, 1, 2 + p[0] % 5, 2 + p[1] % 5};
  std::size_t tile = 0, work = 0;
  if (core::tile_buffer_size(blob, params, &tile) != core::Status::ok) return 0;
  if (core::workspace_size(blob, params, &work) != core::Status::ok) return 0;
  std::vector<std::uint8_t> tile_buffer(tile), workspace(work);
  (void)core::render(blob, params, tile_buffer.data(), tile_buffer.size(), workspace.data(), workspace.size(),
                     [](void*, const core::Tile*) {}, nullptr);
  return 0;
}
