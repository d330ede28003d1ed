// SPDX-License-Identifier: MIT
// Blob validation: every kind of damage is reported with its status and byte offset, and the
// core never reads outside the bytes it is given (run under ASan: the blob is copied into a
// buffer of exactly its size). The damage is sealed with a new checksum (seal_blob) to reach the
// checks behind it; test_blob_checksum.cpp has the damage the checksum refuses.
#include <catch2/catch.hpp>

#include <cstring>

#include "../support/blob_seal.h"
#include "core_bridge/compress.h"
#include "core_support.h"
#include "tristream/compressed_blob.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

std::vector<std::uint8_t> sample_blob(core::Method method = core::Method::zienkiewicz) {
  return pack_blob(single_mesh(random_lattice_mesh(40, 30, 60, 5, 10, 3), 40, 30, ColorSpace::rgb), method);
}

// Opens `bytes` sealed with their checksum (when their total size allows).
core::Status open(const std::vector<std::uint8_t>& bytes, std::uint32_t* offset = nullptr) {
  std::vector<std::uint8_t> exact(bytes);  // heap block of exactly this size
  seal_blob(exact.data(), exact.size());
  core::Blob blob;
  core::BlobError error;
  const core::Status s = core::open_blob(exact.data(), exact.size(), &blob, &error);
  if (offset) *offset = error.offset;
  return s;
}

void put16(std::vector<std::uint8_t>& b, std::size_t at, unsigned v) {
  b[at] = std::uint8_t(v), b[at + 1] = std::uint8_t(v >> 8);
}
unsigned get32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return b[at] | b[at + 1] << 8 | b[at + 2] << 16 | unsigned(b[at + 3]) << 24;
}

}  // namespace

TEST_CASE("a packed blob opens") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz})
    CHECK(open(sample_blob(m)) == core::Status::ok);
}

TEST_CASE("bytes after the blob's total size are ignored (a blob in a larger flash section)") {
  // The C API takes a pointer and a length, and firmware may give the length of a padded or
  // aligned section; the header's total size says where the blob ends (docs/FORMAT.md).
  const std::vector<std::uint8_t> blob = sample_blob(core::Method::bilinear);
  std::vector<std::uint8_t> padded(blob);
  padded.resize(blob.size() + 61, 0xFF);
  core::Blob b;
  REQUIRE(core::open_blob(padded.data(), padded.size(), &b) == core::Status::ok);
  CHECK(b.size == blob.size());
  ts_blob c;
  CHECK(ts_open(padded.data(), padded.size(), &c, nullptr) == TS_OK);
  std::vector<std::uint8_t> tstc = compress_blob(blob);
  const std::size_t compressed = tstc.size();
  tstc.resize(compressed + 61, 0xFF);
  core::CompressedBlob cb;
  CHECK(core::open_compressed_blob(tstc.data(), tstc.size(), &cb) == core::Status::ok);
  ts_compressed_blob cc;
  CHECK(ts_open_compressed(tstc.data(), tstc.size(), &cc, nullptr) == TS_OK);
  // The streams end where the header says: the padded blob expands as the exact one does.
  auto expand = [](const std::uint8_t* bytes, std::size_t size) {
    core::CompressedBlob x;
    REQUIRE(core::open_compressed_blob(bytes, size, &x) == core::Status::ok);
    std::vector<std::uint8_t> out(core::expanded_blob_size(x)), ring(core::expand_workspace_size(x) + 1);
    REQUIRE(core::expand_compressed_blob(x, out.data(), out.size(), ring.data(), ring.size()) == core::Status::ok);
    return out;
  };
  CHECK(expand(tstc.data(), tstc.size()) == expand(tstc.data(), compressed));
}

TEST_CASE("damaged headers are named with their offset") {
  const auto good = sample_blob();
  std::uint32_t at = 0;
  auto damaged = [&](std::size_t offset, std::uint8_t value) {
    auto b = good;
    b[offset] = value;
    return open(b, &at);
  };
  CHECK(damaged(0, 'X') == core::Status::bad_magic);
  CHECK(at == 0);
  CHECK(damaged(4, 3) == core::Status::bad_version);
  CHECK(at == 4);
  CHECK(damaged(20, 5) == core::Status::config_mismatch);
  CHECK(at == 20);
  CHECK(damaged(16, 3) == core::Status::bad_header);
  CHECK(at == 16);
  CHECK(damaged(17, 2) == core::Status::bad_header);
  CHECK(damaged(18, 2) == core::Status::bad_header);
  CHECK(damaged(40, 1) == core::Status::bad_header);
  CHECK(at == 40);
  CHECK(damaged(63, 1) == core::Status::bad_header);
  CHECK(at == 63);
  CHECK(damaged(13, 0x10) == core::Status::too_large);  // width 4096 + 40
  CHECK(at == 12);
  {
    auto b = good;
    b.pop_back();
    CHECK(open(b, &at) == core::Status::truncated);
    CHECK(at == 8);
  }
  {
    std::vector<std::uint8_t> b(good.begin(), good.begin() + 10);
    CHECK(open(b) == core::Status::truncated);
  }
}

TEST_CASE("damaged sections, vertices and triangles") {
  const auto good = sample_blob();
  const std::size_t table = get32(good, 28);
  const std::size_t positions = get32(good, table + 8), values = get32(good, table + 12);
  const std::size_t gradients = get32(good, table + 16), triangles = get32(good, table + 20);
  std::uint32_t at = 0;
  {
    auto b = good;
    b[table + 8] += 2;  // misaligned positions
    CHECK(open(b, &at) == core::Status::bad_section);
    CHECK(at == table + 8);
  }
  {
    auto b = good;
    put16(b, table + 22, 0x7FFF);  // triangles far beyond the end
    CHECK(open(b, &at) == core::Status::bad_section);
  }
  {
    auto b = good;
    put16(b, positions + 4 * 7, 40 * 16);  // x = 40 > W - 1
    CHECK(open(b, &at) == core::Status::coordinate_out_of_range);
    CHECK(at == positions + 4 * 7);
  }
  {
    auto b = good;
    put16(b, values + 2 * 5, 255 * 256 + 1);
    CHECK(open(b, &at) == core::Status::value_out_of_range);
    CHECK(at == values + 2 * 5);
  }
  {
    auto b = good;
    b[gradients + 3] = 0x7F;
    CHECK(open(b, &at) == core::Status::value_out_of_range);
    CHECK(at == gradients);
  }
  {
    auto b = good;
    put16(b, triangles + 8 * 3 + 2, 60000);
    CHECK(open(b, &at) == core::Status::bad_index);
    CHECK(at == triangles + 8 * 3);
  }
  {
    auto b = good;
    put16(b, triangles + 8 * 3 + 2, b[triangles + 8 * 3] | b[triangles + 8 * 3 + 1] << 8);
    CHECK(open(b, &at) == core::Status::bad_index);
  }
  {
    auto b = good;  // swap two vertices: negative area
    std::swap(b[triangles + 8 * 4 + 2], b[triangles + 8 * 4 + 4]);
    std::swap(b[triangles + 8 * 4 + 3], b[triangles + 8 * 4 + 5]);
    CHECK(open(b, &at) == core::Status::bad_triangle);
    CHECK(at == triangles + 8 * 4);
  }
  {
    auto b = good;
    b[triangles + 8 * 2 + 7] = 0x80;
    CHECK(open(b, &at) == core::Status::bad_triangle);
    CHECK(at == triangles + 8 * 2 + 6);
  }
  {
    auto b = good;  // move the last triangle first: out of order
    const std::size_t n = get32(good, table + 4);
    std::vector<std::uint8_t> last(b.begin() + triangles + 8 * (n - 1), b.begin() + triangles + 8 * n);
    std::memmove(b.data() + triangles + 8, b.data() + triangles, 8 * (n - 1));
    std::memcpy(b.data() + triangles, last.data(), 8);
    CHECK(open(b, &at) == core::Status::unsorted);
  }
}

TEST_CASE("random damage never crashes open or render") {
  const auto good = sample_blob();
  std::mt19937 rng(3);
  int opened = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    auto b = good;
    const int flips = 1 + int(rng() % 4);
    for (int k = 0; k < flips; ++k) b[rng() % b.size()] = std::uint8_t(rng());
    if (trial % 7 == 0) b.resize(rng() % b.size());
    std::vector<std::uint8_t> exact(b);
    seal_blob(exact.data(), exact.size());
    core::Blob blob;
    if (core::open_blob(exact.data(), exact.size(), &blob) != core::Status::ok) continue;
    ++opened;
    core::RenderParams p;
    p.tile_width = p.tile_height = 16;
    std::size_t tile = 0, work = 0;
    REQUIRE(core::tile_buffer_size(blob, p, &tile) == core::Status::ok);
    REQUIRE(core::workspace_size(blob, p, &work) == core::Status::ok);
    std::vector<std::uint8_t> tb(tile), ws(work);
    auto sink = [](void*, const core::Tile*) {};
    CHECK(core::render(blob, p, tb.data(), tb.size(), ws.data(), ws.size(), sink, nullptr) == core::Status::ok);
  }
  CHECK(opened > 0);  // some damage is harmless (values, flags of interior edges)
}

TEST_CASE("render parameters and buffers are checked") {
  const auto bytes = sample_blob(core::Method::bilinear);
  core::Blob blob;
  REQUIRE(core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok);
  core::RenderParams p;
  p.tile_width = p.tile_height = 8;
  std::size_t tile = 0, work = 0;
  REQUIRE(core::tile_buffer_size(blob, p, &tile) == core::Status::ok);
  REQUIRE(core::workspace_size(blob, p, &work) == core::Status::ok);
  CHECK(tile == 8 * 8 * 3);
  std::vector<std::uint8_t> tb(tile), ws(work);
  auto sink = [](void*, const core::Tile*) {};
  CHECK(core::render(blob, p, tb.data(), tile - 1, ws.data(), ws.size(), sink, nullptr) ==
        core::Status::tile_buffer_too_small);
  CHECK(core::render(blob, p, tb.data(), tile, ws.data(), 8, sink, nullptr) == core::Status::workspace_too_small);
  CHECK(core::render(blob, p, tb.data(), tile, ws.data(), ws.size(), nullptr, nullptr) == core::Status::null_argument);
  core::RenderParams bad = p;
  bad.viewport = core::Rect{0, 0, 41, 30};
  CHECK(core::render(blob, bad, tb.data(), tile, ws.data(), ws.size(), sink, nullptr) == core::Status::bad_params);
  bad = p;
  bad.format = core::PixelFormat(9);
  CHECK(core::tile_buffer_size(blob, bad, &tile) == core::Status::bad_params);
  bad = p;
  bad.output_width = 1;
  CHECK(core::workspace_size(blob, bad, &work) == core::Status::bad_params);
}

TEST_CASE("TS_PARAMS_INIT and ts_params_init give the C++ defaults, and need only a format") {
  // Garbage first: ts_params_init must write every field, not rely on zeroed memory.
  ts_params from_function = TS_PARAMS_INIT;  // then overwritten with garbage
  std::memset(&from_function, 0xA5, sizeof from_function);
  ts_params_init(&from_function);
  ts_params from_macro = TS_PARAMS_INIT;
  // Field by field (memcmp would compare the padding byte after background, which no
  // initialisation defines).
  auto all_default = [](const ts_params& p) {
    return p.output_width == 0 && p.output_height == 0 && p.viewport.x0 == 0 && p.viewport.y0 == 0 &&
           p.viewport.x1 == 0 && p.viewport.y1 == 0 && p.tile_width == 0 && p.tile_height == 0 &&
           p.format == TS_FORMAT_UNSET && p.dither == 0 && p.background[0] == 0 && p.background[1] == 0 &&
           p.background[2] == 0 && p.packed_tiles == 0 && p.fit == TS_FIT_STRETCH && p.target_stride == 0 && p.target == nullptr;
  };
  CHECK(all_default(from_function));
  CHECK(all_default(from_macro));
  ts_params_init(nullptr);  // no-op, no crash

  const auto bytes = sample_blob();
  ts_blob blob;
  REQUIRE(ts_open(bytes.data(), bytes.size(), &blob, nullptr) == TS_OK);
  std::size_t tile = 0, work = 0;
  CHECK(ts_tile_buffer_size(&blob, &from_function, &tile) == TS_BAD_PARAMS);  // no format chosen
  from_function.format = TS_RGB888;
  REQUIRE(ts_tile_buffer_size(&blob, &from_function, &tile) == TS_OK);
  REQUIRE(ts_workspace_size(&blob, &from_function, &work) == TS_OK);
  core::RenderParams defaults;  // the C++ defaults, format rgb888
  core::Blob b;
  REQUIRE(core::open_blob(bytes.data(), bytes.size(), &b) == core::Status::ok);
  std::size_t cxx_tile = 0, cxx_work = 0;
  REQUIRE(core::tile_buffer_size(b, defaults, &cxx_tile) == core::Status::ok);
  REQUIRE(core::workspace_size(b, defaults, &cxx_work) == core::Status::ok);
  CHECK(tile == cxx_tile);
  CHECK(work == cxx_work);
  std::vector<std::uint8_t> tb(tile), ws(work), c_frame, cxx_frame;
  auto collect = [](void* ctx, const ts_tile* t) {
    auto* f = static_cast<std::vector<std::uint8_t>*>(ctx);
    for (int y = 0; y < t->rect.y1 - t->rect.y0; ++y)
      f->insert(f->end(), t->pixels + std::ptrdiff_t(y) * t->stride,
                t->pixels + std::ptrdiff_t(y) * t->stride + (t->rect.x1 - t->rect.x0) * 3);
  };
  REQUIRE(ts_render(&blob, &from_function, tb.data(), tb.size(), ws.data(), ws.size(), collect, &c_frame) == TS_OK);
  CHECK(c_frame.size() == std::size_t(b.width) * b.height * 3);
  auto collect_cxx = [](void* ctx, const core::Tile* t) {
    auto* f = static_cast<std::vector<std::uint8_t>*>(ctx);
    for (int y = 0; y < t->rect.y1 - t->rect.y0; ++y)
      f->insert(f->end(), t->pixels + std::ptrdiff_t(y) * t->stride,
                t->pixels + std::ptrdiff_t(y) * t->stride + (t->rect.x1 - t->rect.x0) * 3);
  };
  REQUIRE(core::render(b, defaults, tb.data(), tb.size(), ws.data(), ws.size(), collect_cxx, &cxx_frame) ==
          core::Status::ok);
  CHECK(c_frame == cxx_frame);
}

TEST_CASE("the C interface renders the same pixels as the C++ one") {
  const auto bytes = sample_blob();
  ts_blob blob;
  std::uint32_t offset = 99;
  REQUIRE(ts_open(bytes.data(), bytes.size(), &blob, &offset) == TS_OK);
  ts_params p{};
  p.tile_width = 13;
  p.tile_height = 7;
  p.format = TS_RGB565_BE;
  p.dither = 1;
  std::size_t tile = 0, work = 0;
  REQUIRE(ts_tile_buffer_size(&blob, &p, &tile) == TS_OK);
  REQUIRE(ts_workspace_size(&blob, &p, &work) == TS_OK);
  std::vector<std::uint8_t> tb(tile), ws(work), frame(40 * 30 * 2);
  auto sink = [](void* ctx, const ts_tile* t) {
    auto* f = static_cast<std::vector<std::uint8_t>*>(ctx);
    for (int y = t->rect.y0; y < t->rect.y1; ++y)
      std::memcpy(f->data() + (y * 40 + t->rect.x0) * 2, t->pixels + (y - t->rect.y0) * t->stride,
                  std::size_t(t->rect.x1 - t->rect.x0) * 2);
  };
  REQUIRE(ts_render(&blob, &p, tb.data(), tb.size(), ws.data(), ws.size(), sink, &frame) == TS_OK);
  CoreOptions o;
  o.format = core::PixelFormat::rgb565_be;
  o.dither = true;
  CHECK(bytes_differing(core_frame(bytes, o, {0, 0}).bytes, frame) == 0);
  std::vector<std::uint8_t> broken(bytes);
  broken[0] = 'x';
  CHECK(ts_open(broken.data(), broken.size(), &blob, &offset) != TS_OK);
  CHECK(std::string(ts_status_text(ts_open(broken.data(), broken.size(), &blob, &offset))).find("magic") !=
        std::string::npos);
}

// Issue 16 (a second tile buffer, a sink that stops the frame) and issue 18 item 9 (packed tiles,
// empty viewports).
TEST_CASE("two tile buffers alternate, a sink can stop the frame, tiles can be packed") {
  const auto bytes = sample_blob(core::Method::bilinear);
  core::Blob blob;
  REQUIRE(core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok);
  core::RenderParams p;
  p.tile_width = 16;
  p.tile_height = 8;
  std::size_t tile = 0, work = 0;
  REQUIRE(core::tile_buffer_size(blob, p, &tile) == core::Status::ok);
  REQUIRE(core::workspace_size(blob, p, &work) == core::Status::ok);
  std::vector<std::uint8_t> one(tile), a(tile), b(tile), ws(work);
  // The reference: one buffer, every tile's pixels copied out by row.
  struct Copy {
    std::vector<std::vector<std::uint8_t>> tiles;
    std::vector<const std::uint8_t*> where;
    int stop_after = -1;
  };
  auto collect = [](void* c, const core::Tile* t) {
    Copy* copy = static_cast<Copy*>(c);
    std::vector<std::uint8_t> px;
    const int row = t->rect.width() * core::bytes_per_pixel(t->format);
    for (int y = 0; y < t->rect.height(); ++y)
      px.insert(px.end(), t->pixels + y * t->stride, t->pixels + y * t->stride + row);
    copy->tiles.push_back(px);
    copy->where.push_back(t->pixels);
    return copy->stop_after < 0 || int(copy->tiles.size()) < copy->stop_after;
  };
  Copy single;
  core::RenderBuffers buffers;
  buffers.tile[0] = one.data();
  buffers.tile_bytes = tile;
  buffers.workspace = ws.data();
  buffers.workspace_bytes = ws.size();
  REQUIRE(core::render(blob, p, buffers, collect, &single) == core::Status::ok);
  REQUIRE(single.tiles.size() > 4);

  Copy twice;
  buffers.tile[0] = a.data();
  buffers.tile[1] = b.data();
  REQUIRE(core::render(blob, p, buffers, collect, &twice) == core::Status::ok);
  CHECK(twice.tiles == single.tiles);
  for (std::size_t k = 0; k < twice.where.size(); ++k) CHECK(twice.where[k] == (k % 2 ? b.data() : a.data()));

  Copy stopped;
  stopped.stop_after = 3;
  CHECK(core::render(blob, p, buffers, collect, &stopped) == core::Status::stopped);
  CHECK(stopped.tiles.size() == 3);

  // Packed tiles: the same pixels, every tile's rows back to back (the narrower last column too).
  Copy packed;
  core::RenderParams pp = p;
  pp.packed_tiles = true;
  auto check_stride = [](void* c, const core::Tile* t) {
    static_cast<Copy*>(c)->where.push_back(nullptr);
    return t->stride == t->rect.width() * core::bytes_per_pixel(t->format);
  };
  REQUIRE(core::render(blob, pp, buffers, check_stride, &packed) == core::Status::ok);
  CHECK(packed.where.size() == single.tiles.size());
  Copy packed_pixels;
  REQUIRE(core::render(blob, pp, buffers, collect, &packed_pixels) == core::Status::ok);
  CHECK(packed_pixels.tiles == single.tiles);

  // A viewport of all zeros is the whole output; any other empty one is refused.
  core::RenderParams empty = p;
  for (core::Rect r : {core::Rect{5, 5, 5, 9}, core::Rect{0, 3, 10, 3}, core::Rect{7, 0, 2, 4}}) {
    empty.viewport = r;
    CHECK(core::render(blob, empty, buffers, collect, &packed_pixels) == core::Status::bad_params);
  }
  CHECK(core::render(blob, p, buffers, nullptr, nullptr) == core::Status::null_argument);
}

TEST_CASE("each C format renders its C++ format, and a zeroed or unknown format is refused") {
  const auto bytes = sample_blob();
  ts_blob blob;
  REQUIRE(ts_open(bytes.data(), bytes.size(), &blob, nullptr) == TS_OK);
  struct Pair {
    int c;
    core::PixelFormat cxx;
  };
  for (const Pair& f :
       {Pair{TS_L8, core::PixelFormat::l8}, Pair{TS_RGB888, core::PixelFormat::rgb888},
        Pair{TS_RGB565_LE, core::PixelFormat::rgb565_le}, Pair{TS_RGB565_BE, core::PixelFormat::rgb565_be},
        Pair{TS_XRGB8888, core::PixelFormat::xrgb8888}}) {
    ts_params p{};
    p.format = f.c;
    const int bpp = core::bytes_per_pixel(f.cxx);
    std::size_t tile = 0, work = 0;
    REQUIRE(ts_tile_buffer_size(&blob, &p, &tile) == TS_OK);
    REQUIRE(ts_workspace_size(&blob, &p, &work) == TS_OK);
    CHECK(tile == std::size_t(40 * 30 * bpp));
    struct Frame {
      std::vector<std::uint8_t> bytes;
      int bpp;
      int format;
      int wrong_format = 0;
    } frame{std::vector<std::uint8_t>(std::size_t(40 * 30 * bpp)), bpp, f.c};
    std::vector<std::uint8_t> tb(tile), ws(work);
    auto sink = [](void* ctx, const ts_tile* t) {
      auto* fr = static_cast<Frame*>(ctx);
      fr->wrong_format += t->format != fr->format;
      for (int y = t->rect.y0; y < t->rect.y1; ++y)
        std::memcpy(fr->bytes.data() + (y * 40 + t->rect.x0) * fr->bpp, t->pixels + (y - t->rect.y0) * t->stride,
                    std::size_t(t->rect.x1 - t->rect.x0) * fr->bpp);
    };
    REQUIRE(ts_render(&blob, &p, tb.data(), tb.size(), ws.data(), ws.size(), sink, &frame) == TS_OK);
    CHECK(frame.wrong_format == 0);
    CoreOptions o;
    o.format = f.cxx;
    CHECK(bytes_differing(core_frame(bytes, o, {0, 0}).bytes, frame.bytes) == 0);
  }
  std::uint8_t tb[64], ws[64];
  auto never = [](void*, const ts_tile*) { FAIL("a refused render delivered a tile"); };
  for (int format : {int(TS_FORMAT_UNSET), -1, int(TS_XRGB8888) + 1}) {
    ts_params p{};
    p.format = format;
    std::size_t n = 0;
    CHECK(ts_tile_buffer_size(&blob, &p, &n) == TS_BAD_PARAMS);
    CHECK(ts_workspace_size(&blob, &p, &n) == TS_BAD_PARAMS);
    CHECK(ts_render(&blob, &p, tb, sizeof tb, ws, sizeof ws, never, nullptr) == TS_BAD_PARAMS);
  }
}
