// SPDX-License-Identifier: MIT
// The compile-time buffer bounds of tripack's generated header (core_bridge/c_source.h): for many
// output sizes up to the given one, each fit, viewports of them and tile sizes up to the given one, the
// core's own tile_buffer_size and workspace_size never exceed them, and rendering with buffers of
// exactly the bounds succeeds.
#include <catch2/catch.hpp>

#include <random>

#include "core_bridge/c_source.h"
#include "core_bridge/compress.h"
#include "core_bridge/pack.h"
#include "io/tri_file.h"
#include "tristream/render.h"

using namespace tristream;

namespace {

struct Case {
  const char* tri;
  core::Method method;
  core::PixelFormat format;
  int width, height, tile_width, tile_height;
};

}  // namespace

TEST_CASE("no render up to the given output and tile size needs more than the header's bounds") {
  const Case cases[] = {
      {"data/demo/kodim23.rgb.tri", core::Method::zienkiewicz, core::PixelFormat::rgb565_be, 320, 240, 0, 16},
      {"data/demo/kodim23.rgb.tri", core::Method::bilinear, core::PixelFormat::rgb565_be, 960, 640, 32, 32},
      {"data/demo/kodim23.ycbcr-layers.tri", core::Method::zienkiewicz, core::PixelFormat::rgb888, 768, 512, 24, 16},
      {"data/demo/kodim23.ycbcr-layers.tri", core::Method::bilinear, core::PixelFormat::xrgb8888, 240, 320, 0, 0},
      {"data/demo/kodim23.grey.tri", core::Method::bilinear, core::PixelFormat::l8, 768, 512, 64, 8},
  };
  std::mt19937 rng(18);
  auto below = [&](int n) { return std::uniform_int_distribution<int>(1, n)(rng); };
  for (const Case& c : cases) {
    const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/" + c.tri);
    const std::vector<std::uint8_t> bytes = pack_blob(tri, c.method);
    core::Blob blob;
    REQUIRE(core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok);
    const BufferBounds bound = buffer_upper_bounds(blob, c.format, c.width, c.height, c.tile_width, c.tile_height);
    INFO(c.tri << " " << to_string(c.method) << " up to " << c.width << "x" << c.height << ", tiles "
               << c.tile_width << "x" << c.tile_height << ": bounds " << bound.tile_buffer_bytes << " + "
               << bound.workspace_bytes);
    std::size_t largest_tile = 0, largest_work = 0;
    for (int k = 0; k < 300; ++k) {
      core::RenderParams p;
      p.format = c.format;
      // The given size itself, the domain's size when it is not larger, and random smaller ones.
      const int w = k == 0 ? c.width : (k == 1 ? std::min<int>(c.width, blob.width) : std::max(2, below(c.width)));
      const int h = k == 0 ? c.height : (k == 1 ? std::min<int>(c.height, blob.height) : std::max(2, below(c.height)));
      p.output_width = std::uint16_t(w);
      p.output_height = std::uint16_t(h);
      p.fit = core::Fit(k / 3 % 3);  // stretch, inside, fill: the bounds do not depend on the mapping
      if (k % 3 == 2) {  // a viewport of the output
        const int x0 = below(w) - 1, y0 = below(h) - 1;
        p.viewport = core::Rect{x0, y0, x0 + below(w - x0), y0 + below(h - y0)};
      }
      p.tile_width = std::uint16_t(c.tile_width == 0 || k < 2 ? c.tile_width : below(c.tile_width));
      p.tile_height = std::uint16_t(c.tile_height == 0 || k < 2 ? c.tile_height : below(c.tile_height));
      std::size_t tile = 0, work = 0;
      REQUIRE(core::tile_buffer_size(blob, p, &tile) == core::Status::ok);
      REQUIRE(core::workspace_size(blob, p, &work) == core::Status::ok);
      INFO("output " << w << "x" << h << ", fit " << int(p.fit) << ", viewport " << p.viewport.x0 << "," << p.viewport.y0 << ".."
                     << p.viewport.x1 << "," << p.viewport.y1 << ", tiles " << p.tile_width << "x" << p.tile_height
                     << ": " << tile << " + " << work);
      REQUIRE(tile <= bound.tile_buffer_bytes);
      REQUIRE(work <= bound.workspace_bytes);
      largest_tile = std::max(largest_tile, tile);
      largest_work = std::max(largest_work, work);
      if (k < 4) {  // and the core renders with buffers of exactly the bounds
        std::vector<std::uint8_t> tb(bound.tile_buffer_bytes), ws(bound.workspace_bytes);
        auto sink = [](void*, const core::Tile*) {};
        REQUIRE(core::render(blob, p, tb.data(), tb.size(), ws.data(), ws.size(), sink, nullptr) == core::Status::ok);
      }
    }
    // The tile buffer bound is met by the full-size output; the workspace bound is loose by the
    // difference between all triangles and the longest window (none for these: one band of a
    // small output holds every triangle).
    CHECK(largest_tile == bound.tile_buffer_bytes);
    CHECK(largest_work <= bound.workspace_bytes);
  }
}

TEST_CASE("no render of the compressed blob from its streams needs more than the header's bounds") {
  // The same checks for compressed_buffer_upper_bounds against the core's workspace_size of the
  // render from the streams (its band stores hold at most every triangle of a layer).
  const Case cases[] = {
      {"data/demo/kodim23.rgb.tri", core::Method::zienkiewicz, core::PixelFormat::rgb565_be, 320, 240, 0, 16},
      {"data/demo/kodim23.ycbcr-layers.tri", core::Method::bilinear, core::PixelFormat::rgb888, 768, 512, 24, 16},
      {"data/demo/kodim23.grey.tri", core::Method::bilinear, core::PixelFormat::l8, 240, 320, 64, 8},
      {"data/demo/kodim23.rgb.tri", core::Method::bilinear, core::PixelFormat::rgb565_be, 768, 512, 0, 0},
  };
  std::mt19937 rng(41);
  auto below = [&](int n) { return std::uniform_int_distribution<int>(1, n)(rng); };
  for (const Case& c : cases) {
    const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/" + c.tri);
    const std::vector<std::uint8_t> bytes = pack_blob(tri, c.method);
    const std::vector<std::uint8_t> packed = compress_blob(bytes);
    core::Blob blob;
    core::CompressedBlob cblob;
    REQUIRE(core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok);
    REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &cblob) == core::Status::ok);
    std::vector<std::uint8_t> scratch;
    auto measure = [&](const core::RenderParams& p) {
      std::size_t need = 0;
      REQUIRE(core::measure_scratch_size(cblob, p, &need) == core::Status::ok);
      scratch.resize(need);
      core::CompressedWorkspace figures;
      REQUIRE(core::workspace_size(cblob, p, scratch.data(), scratch.size(), &figures) == core::Status::ok);
      return figures;
    };
    core::RenderParams first;
    first.format = c.format;
    const BufferBounds bound = compressed_buffer_upper_bounds(blob, measure(first).decoders, c.format, c.width,
                                                              c.height, c.tile_width, c.tile_height);
    INFO(c.tri << " " << to_string(c.method) << " up to " << c.width << "x" << c.height << ", tiles "
               << c.tile_width << "x" << c.tile_height << ": bounds " << bound.tile_buffer_bytes << " + "
               << bound.workspace_bytes);
    std::size_t largest_work = 0;
    for (int k = 0; k < 60; ++k) {
      core::RenderParams p;
      p.format = c.format;
      const int w = k == 0 ? c.width : (k == 1 ? 2 : std::max(2, below(c.width)));
      const int h = k == 0 ? c.height : (k == 1 ? 2 : std::max(2, below(c.height)));
      p.output_width = std::uint16_t(w);
      p.output_height = std::uint16_t(h);
      p.fit = core::Fit(k / 3 % 3);
      if (k % 3 == 2) {
        const int x0 = below(w) - 1, y0 = below(h) - 1;
        p.viewport = core::Rect{x0, y0, x0 + below(w - x0), y0 + below(h - y0)};
      }
      p.tile_width = std::uint16_t(c.tile_width == 0 || k < 2 ? c.tile_width : below(c.tile_width));
      p.tile_height = std::uint16_t(c.tile_height == 0 || k < 2 ? c.tile_height : below(c.tile_height));
      std::size_t tile = 0;
      REQUIRE(core::tile_buffer_size(cblob, p, &tile) == core::Status::ok);
      const core::CompressedWorkspace figures = measure(p);
      INFO("output " << w << "x" << h << ", fit " << int(p.fit) << ", viewport " << p.viewport.x0 << ","
                     << p.viewport.y0 << ".." << p.viewport.x1 << "," << p.viewport.y1 << ", tiles " << p.tile_width
                     << "x" << p.tile_height << ": " << tile << " + " << figures.bytes);
      REQUIRE(tile <= bound.tile_buffer_bytes);
      REQUIRE(figures.bytes <= bound.workspace_bytes);
      largest_work = std::max(largest_work, figures.bytes);
      if (k < 4) {  // the core renders with buffers of exactly the bounds
        std::vector<std::uint8_t> tb(bound.tile_buffer_bytes), ws(bound.workspace_bytes);
        auto sink = [](void*, const core::Tile*) {};
        REQUIRE(core::render(cblob, p, tb.data(), tb.size(), ws.data(), ws.size(), sink, nullptr) == core::Status::ok);
      }
    }
    // The bound is met within the flagged triangles' records and the triangles without a sample
    // row when one band holds the whole frame at the mesh's size (full-frame tiles); elsewhere a
    // band holds fewer triangles than the bound counts.
    if (c.tile_width == 0 && c.tile_height == 0) CHECK(largest_work * 100 >= bound.workspace_bytes * 90);
  }
}
