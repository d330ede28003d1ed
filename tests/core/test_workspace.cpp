// SPDX-License-Identifier: MIT
// The one workspace carver (firmware_core/src/workspace_layout.h) and its padding rule, which the
// render of a v1 blob and of a compressed one both follow: a workspace starts with 8 - address
// mod 8 bytes (1 to 8), so workspace_size is exact for an 8-aligned workspace (one byte less is
// workspace_too_small) and enough at any other alignment, with the same pixels at every one.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "bench_support.h"
#include "core_bridge/compress.h"
#include "core_support.h"
#include "io/tri_file.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"
#include "workspace_layout.h"

using namespace tristream;
using core::detail::WorkspaceCarver;

TEST_CASE("the carver measures and carves one layout") {
  alignas(8) std::uint8_t mem[64] = {};
  for (int off = 0; off < 8; ++off) {
    CAPTURE(off);
    WorkspaceCarver c(mem + off, 40);
    // 1 to 8 bytes of padding: the first section starts at the next 8-aligned byte after the start.
    CHECK(core::detail::workspace_padding(mem + off) == std::size_t(8 - off));
    CHECK(c.take(16) == mem + 8);
    CHECK(c.take(16) == mem + 24);
    CHECK(c.used() == std::size_t(8 - off + 32));
    CHECK(c.fits());
    CHECK(c.share(2) == (40 - c.used()) / 2 / 4 * 4);
    // A section past the end is counted, and fits() says so.
    c.take(16);
    CHECK_FALSE(c.fits());
  }
  // A measure counts the most padding, 8.
  WorkspaceCarver m;
  m.take(16);
  m.take(4);
  CHECK(m.used() == 28);
  CHECK(m.fits());
  // No workspace: no padding, room for nothing.
  CHECK(core::detail::workspace_padding(nullptr) == 0);
  WorkspaceCarver none(nullptr, 0);
  none.take(0);
  CHECK(none.fits());
  none.take(1);
  CHECK_FALSE(none.fits());
  // An exact fit: 8 bytes of padding and 16 of sections in 24 bytes.
  WorkspaceCarver exact(mem, 24);
  CHECK(exact.take(16) == mem + 8);
  CHECK(exact.fits());
  CHECK(exact.share(3) == 0);
}

namespace {

// The frame's bytes in tile order, rendered with a workspace of `bytes` bytes `offset` bytes past
// an 8-aligned address; the status of the render.
template <typename B>
core::Status frame_at(const B& blob, const core::RenderParams& p, std::size_t offset, std::size_t bytes,
                      std::vector<std::uint8_t>* out) {
  std::size_t tb = 0;
  REQUIRE(core::tile_buffer_size(blob, p, &tb) == core::Status::ok);
  std::vector<std::uint8_t> tile(tb);
  std::vector<std::uint64_t> work((offset + bytes) / 8 + 1);
  core::RenderBuffers b;
  b.tile[0] = tile.data();
  b.tile_bytes = tb;
  b.workspace = reinterpret_cast<std::uint8_t*>(work.data()) + offset;
  b.workspace_bytes = bytes;
  out->clear();
  auto sink = [](void* c, const core::Tile* t) {
    auto* o = static_cast<std::vector<std::uint8_t>*>(c);
    const int row = t->rect.width() * core::bytes_per_pixel(t->format);
    for (int y = 0; y < t->rect.height(); ++y) {
      const std::uint8_t* p = t->pixels + y * t->stride;
      o->insert(o->end(), p, p + row);
    }
    return true;
  };
  return core::render(blob, p, b, sink, out);
}

template <typename B>
void check_every_alignment(const B& blob, const core::RenderParams& p, std::size_t ws) {
  std::vector<std::uint8_t> reference, frame;
  REQUIRE(frame_at(blob, p, 0, ws, &reference) == core::Status::ok);
  REQUIRE(!reference.empty());
  CHECK(frame_at(blob, p, 0, ws - 1, &frame) == core::Status::workspace_too_small);
  for (std::size_t off = 1; off < 8; ++off) {
    CAPTURE(off);
    CHECK(frame_at(blob, p, off, ws, &frame) == core::Status::ok);
    CHECK(frame == reference);
  }
}

}  // namespace

TEST_CASE("v1 and compressed renders: workspace_size exact when 8-aligned, enough at any alignment") {
  const Triangulation single = testing::bench_scene(4000);
  const Triangulation layers = read_tri_file(TRISTREAM_SOURCE_DIR "/data/demo/kodim23.ycbcr-layers.tri");
  for (const Triangulation* tri : {&single, &layers})
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz})
      for (int tile : {0, 16, 32}) {
        core::RenderParams p;
        p.tile_width = p.tile_height = std::uint16_t(tile);
        p.format = core::PixelFormat::rgb565_be;
        const auto v1 = pack_blob(*tri, m);
        core::Blob b;
        REQUIRE(core::open_blob(v1.data(), v1.size(), &b) == core::Status::ok);
        CAPTURE(b.layer_count, int(m), tile);
        std::size_t ws = 0;
        REQUIRE(core::workspace_size(b, p, &ws) == core::Status::ok);
        check_every_alignment(b, p, ws);

        const auto packed = compress_blob(v1, "test");
        core::CompressedBlob c;
        REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &c) == core::Status::ok);
        std::size_t scratch_bytes = 0, cws = 0;
        REQUIRE(core::measure_scratch_size(c, p, &scratch_bytes) == core::Status::ok);
        std::vector<std::uint8_t> scratch(scratch_bytes);
        REQUIRE(core::workspace_size(c, p, scratch.data(), scratch.size(), &cws) == core::Status::ok);
        check_every_alignment(c, p, cws);
      }
}
