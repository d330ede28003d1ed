// SPDX-License-Identifier: MIT
// The RAM figure of issue 3: a 512 x 512 RGB565 frame in 32 x 32 tiles from a 20,000-vertex
// triangulation needs at most 8 KiB besides the blob (tile buffer + workspace), and the core
// renders with exactly the workspace it reports.
#include <catch2/catch.hpp>

#include "core_support.h"
#include "io/tri_file.h"
#include "scenes/bench_scenes.h"

using namespace tristream;

TEST_CASE("512x512 RGB565, 32x32 tiles, 20,000 vertices: at most 8 KiB") {
  const Triangulation tri = scenes::bench_scene(40000);
  REQUIRE(tri.layers[0].vertex_count() == 20002);
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    const auto blob = pack_blob(tri, m);
    CoreOptions o;
    o.format = core::PixelFormat::rgb565_le;
    o.tile_width = o.tile_height = 32;
    CoreRenderer r(blob, o);
    INFO("tile buffer " << r.tile_buffer_bytes() << ", workspace " << r.workspace_bytes());
    CHECK(r.tile_buffer_bytes() == 2048);
    CHECK(r.tile_buffer_bytes() + r.workspace_bytes() <= 8192);
    CoreFrame f;
    r.render(f);  // throws if the reported workspace were too small
    CHECK(f.tiles == 256);
  }
}

TEST_CASE("one byte less workspace than reported is refused, never overrun") {
  const auto blob = pack_blob(scenes::bench_scene(4000), core::Method::bilinear);
  core::Blob b;
  REQUIRE(core::open_blob(blob.data(), blob.size(), &b) == core::Status::ok);
  for (int tile : {8, 32, 0}) {
    core::RenderParams p;
    p.tile_width = p.tile_height = std::uint16_t(tile);
    std::size_t tb = 0, ws = 0;
    REQUIRE(core::tile_buffer_size(b, p, &tb) == core::Status::ok);
    REQUIRE(core::workspace_size(b, p, &ws) == core::Status::ok);
    std::vector<std::uint8_t> tiles(tb);
    std::vector<std::uint64_t> work(ws / 8 + 1);  // 8-aligned: the padding is then 8 bytes
    auto sink = [](void*, const core::Tile*) {};
    CHECK(core::render(b, p, tiles.data(), tb, work.data(), ws, sink, nullptr) == core::Status::ok);
    CHECK(core::render(b, p, tiles.data(), tb, work.data(), ws - 1, sink, nullptr) ==
          core::Status::workspace_too_small);
  }
}

// Issue 17, items 1 and 2: every workspace size short of the need, down to none at all, is refused
// with workspace_too_small before any tile reaches the sink (no division by a zero capacity, no
// partial frame), for a single-mesh and a layered blob; a tile buffer one byte short likewise.
TEST_CASE("a buffer too small for the frame is refused before the first tile") {
  const Triangulation single = scenes::bench_scene(4000);
  const Triangulation layers = read_tri_file(TRISTREAM_SOURCE_DIR "/data/demo/kodim23.ycbcr-layers.tri");
  for (const Triangulation* tri : {&single, &layers}) {
    const auto blob = pack_blob(*tri, core::Method::bilinear);
    core::Blob b;
    REQUIRE(core::open_blob(blob.data(), blob.size(), &b) == core::Status::ok);
    core::RenderParams p;
    p.tile_width = p.tile_height = 32;
    p.format = core::PixelFormat::rgb565_be;
    std::size_t tb = 0, ws = 0;
    REQUIRE(core::tile_buffer_size(b, p, &tb) == core::Status::ok);
    REQUIRE(core::workspace_size(b, p, &ws) == core::Status::ok);
    std::vector<std::uint8_t> tiles(tb);
    // 8-aligned storage: the padding is 8 bytes and workspace_size exact.
    std::vector<std::uint64_t> work(ws / 8 + 1);
    int delivered = 0;
    auto sink = [](void* c, const core::Tile*) { ++*static_cast<int*>(c); };
    INFO("layers " << b.layer_count << ", workspace " << ws);
    CHECK(core::render(b, p, tiles.data(), tb, nullptr, 0, sink, &delivered) == core::Status::workspace_too_small);
    for (std::size_t n = 0; n < ws; ++n) {
      const core::Status s = core::render(b, p, tiles.data(), tb, work.data(), n, sink, &delivered);
      if (s != core::Status::workspace_too_small) FAIL_CHECK("workspace of " << n << " bytes: status " << int(s));
    }
    CHECK(delivered == 0);
    CHECK(core::render(b, p, tiles.data(), tb - 1, work.data(), ws, sink, &delivered) ==
          core::Status::tile_buffer_too_small);
    CHECK(delivered == 0);
    CHECK(core::render(b, p, tiles.data(), tb, work.data(), ws, sink, &delivered) == core::Status::ok);
    CHECK(delivered > 0);
  }
}
