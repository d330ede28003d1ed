// SPDX-License-Identifier: MIT
// Buffers that share bytes are refused before the first tile (TS_BAD_PARAMS, Status::bad_params)
// in every render entry point, v1 and compressed: a tile buffer or a target over the workspace
// (which holds a compressed blob's decoders, pointers included: drawing over it had crashed
// ts_render_compressed) and two tile buffers over each other; buffers that only touch render as
// apart. Also expand_compressed_blob's output over its workspace. Run under ASan too.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "core_bridge/compress.h"
#include "core_bridge/pack.h"
#include "core_support.h"
#include "tristream/compressed_blob.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

struct Setup {
  std::vector<std::uint8_t> bytes = pack_blob(
      single_mesh(random_lattice_mesh(40, 24, 30, 20, 0, 3), 40, 24, ColorSpace::rgb), core::Method::bilinear);
  std::vector<std::uint8_t> stream = compress_blob(bytes, "small");
  ts_blob blob{};
  ts_compressed_blob compressed{};
  ts_params p = TS_PARAMS_INIT;
  std::size_t tile = 0, work = 0;  // the larger of the two blobs' needs

  Setup() {
    REQUIRE(ts_open(bytes.data(), bytes.size(), &blob, nullptr) == TS_OK);
    REQUIRE(ts_open_compressed(stream.data(), stream.size(), &compressed, nullptr) == TS_OK);
    p.format = TS_RGB888;
    p.tile_width = 16;
    p.tile_height = 8;
    REQUIRE(ts_tile_buffer_size(&blob, &p, &tile) == TS_OK);
    REQUIRE(ts_workspace_size(&blob, &p, &work) == TS_OK);
    std::size_t scratch = 0, stream_work = 0;
    REQUIRE(ts_compressed_scratch_size(&compressed, &p, &scratch) == TS_OK);
    std::vector<std::uint8_t> scratch_bytes(scratch);
    REQUIRE(ts_compressed_workspace_size(&compressed, &p, scratch_bytes.data(), scratch, &stream_work, nullptr) ==
            TS_OK);
    work = stream_work > work ? stream_work : work;
  }
};

void drop(void*, const ts_tile*) {}
int keep(void*, const ts_tile*) { return 1; }

// The three C render calls with these buffers (ts_render takes the first tile buffer).
struct Results {
  ts_status render, frame, compressed;
};
Results render_all(const Setup& s, const ts_params& p, const ts_buffers& b) {
  return {ts_render(&s.blob, &p, b.tile[0], b.tile_size, b.workspace, b.workspace_size, p.target ? nullptr : drop,
                    nullptr),
          ts_render_frame(&s.blob, &p, &b, p.target ? nullptr : keep, nullptr),
          ts_render_compressed(&s.compressed, &p, &b, p.target ? nullptr : keep, nullptr, nullptr)};
}

void require_all(const Results& r, ts_status want) {
  CHECK(r.render == want);
  CHECK(r.frame == want);
  CHECK(r.compressed == want);
}

}  // namespace

TEST_CASE("a tile buffer sharing bytes with the workspace is refused by every render call") {
  Setup s;
  // One arena: the workspace at `w`, the tile buffer moved across it byte by byte near its ends.
  std::vector<std::uint8_t> arena(s.tile * 2 + s.work + 64);
  std::uint8_t* w = arena.data() + s.tile + 16;
  for (std::ptrdiff_t shift : {-std::ptrdiff_t(s.tile), -std::ptrdiff_t(s.tile) + 1, std::ptrdiff_t(-1),
                               std::ptrdiff_t(0), std::ptrdiff_t(8), std::ptrdiff_t(s.work) - 1,
                               std::ptrdiff_t(s.work)}) {
    CAPTURE(shift);
    ts_buffers b{};
    b.tile[0] = w + shift;
    b.tile_size = s.tile;
    b.workspace = w;
    b.workspace_size = s.work;
    const bool apart = shift <= -std::ptrdiff_t(s.tile) || shift >= std::ptrdiff_t(s.work);
    require_all(render_all(s, s.p, b), apart ? TS_OK : TS_BAD_PARAMS);
  }
}

TEST_CASE("the workspace inside a tile buffer, and two tile buffers over each other, are refused") {
  Setup s;
  std::vector<std::uint8_t> big(s.tile + s.work + 64), other(s.tile), work(s.work);
  ts_buffers b{};
  b.tile[0] = big.data();
  b.tile_size = big.size();  // a tile buffer larger than needed, the workspace in its middle
  b.workspace = big.data() + 32;
  b.workspace_size = s.work;
  require_all(render_all(s, s.p, b), TS_BAD_PARAMS);

  // Two tile buffers: overlapping by one byte, then touching, then the second over the workspace.
  std::vector<std::uint8_t> pair(2 * s.tile);
  ts_buffers d{};
  d.tile_size = s.tile;
  d.workspace = work.data();
  d.workspace_size = work.size();
  d.tile[0] = pair.data();
  d.tile[1] = pair.data() + s.tile - 1;
  CHECK(ts_render_frame(&s.blob, &s.p, &d, keep, nullptr) == TS_BAD_PARAMS);
  CHECK(ts_render_compressed(&s.compressed, &s.p, &d, keep, nullptr, nullptr) == TS_BAD_PARAMS);
  std::vector<std::uint8_t> pair2(2 * s.tile);
  d.tile[0] = pair2.data();
  d.tile[1] = pair2.data() + s.tile;
  CHECK(ts_render_frame(&s.blob, &s.p, &d, keep, nullptr) == TS_OK);
  CHECK(ts_render_compressed(&s.compressed, &s.p, &d, keep, nullptr, nullptr) == TS_OK);
  d.tile[1] = work.data() + work.size() - 1;
  d.tile[0] = other.data();
  CHECK(ts_render_frame(&s.blob, &s.p, &d, keep, nullptr) == TS_BAD_PARAMS);
  CHECK(ts_render_compressed(&s.compressed, &s.p, &d, keep, nullptr, nullptr) == TS_BAD_PARAMS);
}

TEST_CASE("a target sharing bytes with the workspace is refused, for either stride sign") {
  Setup s;
  const std::int32_t row = 40 * 3, stride = row + 8;
  const std::size_t target_bytes = std::size_t(23) * stride + row;  // 24 rows, the last without its padding
  std::vector<std::uint8_t> arena(target_bytes + s.work + 64);
  for (int sign : {1, -1}) {
    for (std::ptrdiff_t gap : {std::ptrdiff_t(0), std::ptrdiff_t(-1)}) {
      CAPTURE(sign, gap);
      // The target's bytes first, the workspace right after them (gap 0) or one byte into them.
      std::uint8_t* first = arena.data() + 8;
      ts_params p = s.p;
      p.target_stride = sign * stride;
      p.target = sign > 0 ? first : first + 23 * stride;  // a bottom-up target names its top row
      ts_buffers b{};
      b.workspace = first + std::ptrdiff_t(target_bytes) + gap;
      b.workspace_size = s.work;
      require_all(render_all(s, p, b), gap == 0 ? TS_OK : TS_BAD_PARAMS);
      // And the workspace ending one byte into the target's first byte, or just before it.
      std::vector<std::uint8_t> below(s.work + 64 + target_bytes);
      p.target = sign > 0 ? below.data() + s.work + 8 : below.data() + s.work + 8 + 23 * stride;
      b.workspace = below.data() + 8 + 1 + gap;
      require_all(render_all(s, p, b), gap == 0 ? TS_BAD_PARAMS : TS_OK);
    }
  }
}

TEST_CASE("expand_compressed_blob refuses an output over its workspace") {
  Setup s;
  core::CompressedBlob blob;
  REQUIRE(core::open_compressed_blob(s.stream.data(), s.stream.size(), &blob) == core::Status::ok);
  const std::size_t out = core::expanded_blob_size(blob), work = core::expand_workspace_size(blob);
  std::vector<std::uint8_t> arena(out + work + 16);
  CHECK(core::expand_compressed_blob(blob, arena.data(), out, arena.data() + out - 1, work) ==
        core::Status::bad_params);
  CHECK(core::expand_compressed_blob(blob, arena.data() + work, out, arena.data() + 1, work) ==
        core::Status::bad_params);
  REQUIRE(core::expand_compressed_blob(blob, arena.data(), out, arena.data() + out, work) == core::Status::ok);
  core::Blob v1;
  CHECK(core::open_blob(arena.data(), out, &v1) == core::Status::ok);
}
