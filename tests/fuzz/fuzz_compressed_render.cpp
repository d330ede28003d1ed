// SPDX-License-Identifier: MIT
// Fuzz target of the render of a compressed blob from its streams (render.h), on the compressed
// corpus: for a header that opens, the render with a generous workspace and without the measure
// (it meets damage while drawing) ends in a status with an offset in the input; then the measure
// (workspace_size), and when it accepts, the render with exactly that workspace succeeds and its
// pixels equal those of the v1 blob the stream expands to. Every buffer is exactly sized.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "tristream/compressed_blob.h"
#include "tristream/render.h"

namespace {

namespace core = tristream::core;

struct Frame {
  std::vector<std::uint8_t> pixels;
  int width = 0;
};

void collect(void* context, const core::Tile* t) {
  Frame* f = static_cast<Frame*>(context);
  for (int y = t->rect.y0; y < t->rect.y1; ++y)
    for (int x = t->rect.x0; x < t->rect.x1; ++x)
      for (int k = 0; k < 3; ++k)
        f->pixels[(std::size_t(y) * f->width + x) * 3 + k] = t->pixels[(y - t->rect.y0) * t->stride + (x - t->rect.x0) * 3 + k];
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> bytes(data, data + size);
  core::CompressedBlob blob;
  core::BlobError error;
  if (core::open_compressed_blob(bytes.data(), bytes.size(), &blob, &error) != core::Status::ok) return 0;
  core::RenderParams p;
  p.output_width = 40;  // a small output whatever the domain: the decode is the part under test
  p.output_height = 24;
  p.tile_width = 16;
  p.tile_height = 8;
  p.format = core::PixelFormat::rgb888;
  std::size_t tile = 0, scratch_bytes = 0;
  if (core::tile_buffer_size(blob, p, &tile) != core::Status::ok ||
      core::measure_scratch_size(blob, p, &scratch_bytes) != core::Status::ok)
    std::abort();
  std::vector<std::uint8_t> tiles(tile);
  Frame frame{std::vector<std::uint8_t>(40 * 24 * 3), 40};
  {
    std::vector<std::uint8_t> work(scratch_bytes + 64 * 1024);
    core::RenderBuffers b;
    b.tile[0] = tiles.data();
    b.tile_bytes = tiles.size();
    b.workspace = work.data();
    b.workspace_bytes = work.size();
    auto go_on = [](void* context, const core::Tile* t) {
      collect(context, t);
      return true;
    };
    core::BlobError at;
    const core::Status s = core::render(blob, p, b, go_on, &frame, &at);
    if (s != core::Status::ok && s != core::Status::workspace_too_small && at.offset > size) std::abort();
  }
  std::vector<std::uint8_t> scratch(scratch_bytes);
  std::size_t work_bytes = 0;
  if (core::workspace_size(blob, p, scratch.data(), scratch.size(), &work_bytes, &error) != core::Status::ok) {
    if (error.offset > size) std::abort();
    return 0;
  }
  std::vector<std::uint8_t> work(work_bytes);
  if (core::render(blob, p, tiles.data(), tiles.size(), work.data(), work.size(), collect, &frame) != core::Status::ok)
    std::abort();
  // The v1 blob of the same stream renders the same pixels.
  std::vector<std::uint8_t> v1(core::expanded_blob_size(blob)), ring(core::expand_workspace_size(blob));
  if (core::expand_compressed_blob(blob, v1.data(), v1.size(), ring.data(), ring.size()) != core::Status::ok)
    std::abort();
  core::Blob opened;
  std::size_t v1_work = 0;
  if (core::open_blob(v1.data(), v1.size(), &opened) != core::Status::ok ||
      core::workspace_size(opened, p, &v1_work) != core::Status::ok)
    std::abort();
  std::vector<std::uint8_t> v1_space(v1_work);
  Frame expected{std::vector<std::uint8_t>(40 * 24 * 3), 40};
  if (core::render(opened, p, tiles.data(), tiles.size(), v1_space.data(), v1_space.size(), collect, &expected) !=
          core::Status::ok ||
      expected.pixels != frame.pixels)
    std::abort();
  return 0;
}
