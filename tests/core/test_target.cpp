// SPDX-License-Identifier: MIT
// Rendering in place into a caller's framebuffer (RenderParams::target, ts_params.target): every
// pixel as the tile path's assembled frame, for every format, tiling, viewport, fit and dithering,
// v1 and compressed blobs; rows with a stride wider than a row (and bottom-up), the bytes around
// and between the rows untouched; the sink sees each tile where it lies in the target; bad
// strides refused. Buffers are exactly sized: run under ASan too.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "core_bridge/compress.h"
#include "core_support.h"
#include "io/tri_file.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

// A v1 or a compressed blob, opened, with the workspace its render needs.
struct Opened {
  bool compressed = false;
  core::Blob v1;
  core::CompressedBlob stream;

  explicit Opened(const std::vector<std::uint8_t>& bytes) {
    compressed = bytes.size() >= 4 && std::memcmp(bytes.data(), "TSTC", 4) == 0;
    if (compressed) {
      REQUIRE(core::open_compressed_blob(bytes.data(), bytes.size(), &stream) == core::Status::ok);
    } else {
      REQUIRE(core::open_blob(bytes.data(), bytes.size(), &v1) == core::Status::ok);
    }
  }
  core::Status tile_buffer_size(const core::RenderParams& p, std::size_t* bytes) const {
    return compressed ? core::tile_buffer_size(stream, p, bytes) : core::tile_buffer_size(v1, p, bytes);
  }
  core::Status workspace_size(const core::RenderParams& p, std::size_t* bytes) const {
    if (!compressed) return core::workspace_size(v1, p, bytes);
    std::size_t scratch = 0;
    const core::Status s = core::measure_scratch_size(stream, p, &scratch);
    if (s != core::Status::ok) return s;
    std::vector<std::uint8_t> work(scratch);
    return core::workspace_size(stream, p, work.data(), work.size(), bytes);
  }
  core::Status render(const core::RenderParams& p, const core::RenderBuffers& b, core::FrameSink sink,
                      void* context) const {
    return compressed ? core::render(stream, p, b, sink, context) : core::render(v1, p, b, sink, context);
  }
};

// The pattern of the bytes the render must not touch.
std::uint8_t guard_byte(std::size_t i) { return std::uint8_t(i * 151 + 77); }

// A framebuffer of `rows` rows of |stride| bytes, `guard` pattern bytes before and after, the
// target `offset` bytes into the first row (the viewport at a column of a larger canvas, or an
// odd address) and, for a negative stride, in the last row of memory.
struct Framebuffer {
  std::vector<std::uint8_t> bytes;
  std::size_t guard, start;  // start: the viewport's top row, from bytes.data()
  std::int32_t stride;

  Framebuffer(int rows, std::int32_t stride_, std::size_t offset, std::size_t guard_ = 64)
      : guard(guard_), stride(stride_) {
    const std::size_t step = std::size_t(stride < 0 ? -std::int64_t(stride) : stride);
    bytes.resize(2 * guard + step * std::size_t(rows));
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = guard_byte(i);
    start = guard + offset + (stride < 0 ? step * std::size_t(rows - 1) : 0);
  }
  std::uint8_t* target() { return bytes.data() + start; }
  std::size_t row_at(int y) const { return std::size_t(std::ptrdiff_t(start) + std::ptrdiff_t(y) * stride); }
};

struct SinkLog {
  const std::uint8_t* target = nullptr;
  std::int32_t stride = 0;
  int bpp = 0;
  core::Rect view;
  core::PixelFormat format{};
  std::vector<int> covered;  // per viewport pixel: tiles that held it
  int tiles = 0, misplaced = 0, stop_after = -1;
};

bool log_tile(void* context, const core::Tile* t) {
  SinkLog& log = *static_cast<SinkLog*>(context);
  ++log.tiles;
  const core::Rect& r = t->rect;
  const core::Rect& v = log.view;
  const bool inside = r.x0 >= v.x0 && r.y0 >= v.y0 && r.x1 <= v.x1 && r.y1 <= v.y1 && !r.empty();
  const std::uint8_t* expected =
      log.target + std::ptrdiff_t(r.y0 - v.y0) * log.stride + std::ptrdiff_t(r.x0 - v.x0) * log.bpp;
  if (!inside || t->pixels != expected || t->stride != log.stride || t->format != log.format) {
    ++log.misplaced;
  } else {
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) ++log.covered[std::size_t((y - v.y0) * v.width() + (x - v.x0))];
  }
  return log.tiles != log.stop_after;
}

// The viewport of the render in output pixels (the default: the whole output).
core::Rect viewport_of(const CoreFrame& reference, const CoreOptions& o) {
  if (!o.viewport.empty()) return o.viewport;
  return core::Rect{0, 0, reference.width, reference.height};
}

// Renders `o` with tiling `t` into a framebuffer of stride `stride` (0: the default) and checks it
// byte for byte against the tile path's frame, the guard bytes, and what the sink saw.
void check_target(const std::vector<std::uint8_t>& blob, const CoreOptions& o, Tiling t, std::int32_t extra,
                  bool bottom_up, std::size_t offset) {
  const CoreFrame reference = core_frame(blob, o, t);
  const Opened opened(blob);
  const int bpp = core::bytes_per_pixel(o.format);
  const core::Rect view = viewport_of(reference, o);
  REQUIRE((view.width() == reference.width && view.height() == reference.height));
  const std::int32_t row = view.width() * bpp;
  const std::int32_t step = row + extra;
  core::RenderParams p = params_of(o, t);
  Framebuffer fb(view.height(), bottom_up ? -step : step, offset);
  p.target = fb.target();
  p.target_stride = extra == 0 && !bottom_up ? 0 : fb.stride;
  CAPTURE(int(o.format), o.dither, o.width, o.height, int(o.fit), view.x0, view.y0, view.x1, view.y1, t.w, t.h,
          extra, bottom_up, offset, opened.compressed);
  std::size_t tile_bytes = 99, work_bytes = 0;
  REQUIRE(opened.tile_buffer_size(p, &tile_bytes) == core::Status::ok);
  CHECK(tile_bytes == 0);
  REQUIRE(opened.workspace_size(p, &work_bytes) == core::Status::ok);
  std::vector<std::uint8_t> work(work_bytes);
  core::RenderBuffers b;  // no tile buffer
  b.workspace = work_bytes ? work.data() : nullptr;
  b.workspace_bytes = work_bytes;
  SinkLog log;
  log.target = fb.target();
  log.stride = fb.stride;
  log.bpp = bpp;
  log.view = view;
  log.format = o.format;
  log.covered.assign(std::size_t(view.width()) * view.height(), 0);
  REQUIRE(opened.render(p, b, log_tile, &log) == core::Status::ok);
  CHECK(std::uint64_t(log.tiles) == reference.tiles);
  CHECK(log.misplaced == 0);
  int not_once = 0;
  for (int c : log.covered) not_once += c != 1;
  CHECK(not_once == 0);
  // Each viewport row as the tile path's; every other byte as before.
  std::vector<bool> pixel(fb.bytes.size(), false);
  std::size_t differing = 0;
  for (int y = 0; y < view.height(); ++y) {
    const std::size_t at = fb.row_at(y);
    for (int i = 0; i < row; ++i) {
      pixel[at + std::size_t(i)] = true;
      differing += fb.bytes[at + std::size_t(i)] != reference.bytes[std::size_t(y) * row + std::size_t(i)];
    }
  }
  CHECK(differing == 0);
  std::size_t touched = 0;
  for (std::size_t i = 0; i < fb.bytes.size(); ++i) touched += !pixel[i] && fb.bytes[i] != guard_byte(i);
  CHECK(touched == 0);
  // The same with the sink left out: it is optional with a target.
  Framebuffer quiet(view.height(), fb.stride, offset);
  p.target = quiet.target();
  REQUIRE(opened.render(p, b, nullptr, nullptr) == core::Status::ok);
  CHECK(quiet.bytes == fb.bytes);
}

std::vector<CoreOptions> every_format() {
  std::vector<CoreOptions> out;
  for (core::PixelFormat f : {core::PixelFormat::l8, core::PixelFormat::rgb888, core::PixelFormat::rgb565_le,
                              core::PixelFormat::rgb565_be, core::PixelFormat::xrgb8888})
    for (bool dither : {false, true}) {
      if (dither && f != core::PixelFormat::rgb565_le && f != core::PixelFormat::rgb565_be) continue;
      CoreOptions o;
      o.format = f;
      o.dither = dither;
      o.background = 40;
      out.push_back(o);
    }
  return out;
}

// Viewports, output sizes and fits (the border of `inside` is background, a `fill` crops).
std::vector<CoreOptions> placements(int w, int h) {
  std::vector<CoreOptions> out;
  CoreOptions v;
  v.format = core::PixelFormat::rgb565_be;
  v.dither = true;
  v.viewport = core::Rect{w / 5, h / 3, w - w / 4, h - 2};
  out.push_back(v);
  for (core::Fit fit : {core::Fit::stretch, core::Fit::inside, core::Fit::fill}) {
    CoreOptions o;
    o.width = w * 2 + 3;
    o.height = h + 5;
    o.fit = fit;
    o.format = fit == core::Fit::fill ? core::PixelFormat::xrgb8888 : core::PixelFormat::rgb888;
    out.push_back(o);
  }
  CoreOptions both;
  both.width = w / 2 + 7;
  both.height = h * 3 / 2;
  both.fit = core::Fit::inside;
  both.viewport = core::Rect{1, 3, w / 2 + 2, h * 3 / 2 - 1};
  both.format = core::PixelFormat::l8;
  out.push_back(both);
  return out;
}

// Every format with several tilings and strides, then the placements.
void check_all(const std::vector<std::uint8_t>& blob, int w, int h) {
  const std::vector<Tiling> tilings = {{0, 0}, {0, 16}, {8, 8}, {13, 7}, {1, 0}};
  for (const CoreOptions& o : every_format())
    for (const Tiling& t : tilings) {
      check_target(blob, o, t, 6, false, 3);  // 6 bytes between rows, the target at an odd address
      check_target(blob, o, t, 0, false, 0);  // rows back to back (target_stride 0)
    }
  for (const CoreOptions& o : every_format()) check_target(blob, o, {13, 7}, 12, true, 1);  // bottom-up
  for (const CoreOptions& o : placements(w, h))
    for (const Tiling& t : {Tiling{0, 0}, Tiling{13, 7}, Tiling{0, 5}}) {
      check_target(blob, o, t, 17, false, 5);
      check_target(blob, o, t, 0, true, 0);
    }
}

Triangulation layered_mesh(int w, int h, std::uint32_t seed) {
  Triangulation t;
  t.width = w;
  t.height = h;
  t.space = ColorSpace::ycbcr;
  for (int l = 0; l < 3; ++l) t.layers.push_back(random_lattice_mesh(w, h, 20 + 10 * l, seed + l, 3));
  return t;
}

}  // namespace

TEST_CASE("a target receives the tile path's pixels in place, its other bytes untouched") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    CAPTURE(int(m));
    SECTION("rgb, v1 and compressed") {
      const auto v1 = pack_blob(single_mesh(random_lattice_mesh(37, 23, 60, 2, 5, 3), 37, 23, ColorSpace::rgb), m);
      check_all(v1, 37, 23);
      check_all(compress_blob(v1, "rgb"), 37, 23);
    }
    SECTION("grey, sub-pixel vertices, convex hull domain") {
      check_all(pack_blob(single_mesh(random_subpixel_mesh(31, 26, 50, 3, false, 1), 31, 26), m), 31, 26);
    }
    SECTION("three ycbcr layers (the channel scratch), v1 and compressed") {
      const auto v1 = pack_blob(layered_mesh(29, 21, 4), m);
      for (const auto& blob : {v1, compress_blob(v1, "layers")}) {
        for (const CoreOptions& o : every_format()) check_target(blob, o, {8, 8}, 5, false, 1);
        for (const CoreOptions& o : placements(29, 21)) check_target(blob, o, {0, 4}, 0, true, 2);
      }
    }
  }
}

TEST_CASE("a demo mesh into a target: every format, tiles and bands") {
  const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.rgb.tri");
  const auto v1 = pack_blob(tri, core::Method::zienkiewicz);
  const auto stream = compress_blob(v1, "kodim23");
  CoreOptions o;
  o.width = 200;
  o.height = 133;
  for (const CoreOptions& f : every_format()) {
    o.format = f.format;
    o.dither = f.dither;
    check_target(v1, o, {32, 32}, 40, false, 2);
    check_target(stream, o, {0, 16}, 8, true, 0);
  }
}

namespace {

// A sized RGB565 render of a small blob with a target, for the refusals below.
struct Setup {
  std::vector<std::uint8_t> bytes = pack_blob(
      single_mesh(random_lattice_mesh(20, 10, 20, 9, 0, 3), 20, 10, ColorSpace::rgb), core::Method::bilinear);
  std::vector<std::uint8_t> stream = compress_blob(bytes, "small");
  core::RenderParams p;
  Setup() {
    p.format = core::PixelFormat::rgb565_le;
    p.tile_width = 8;
    p.tile_height = 4;
  }
};

bool count_tile(void* context, const core::Tile*) {
  ++*static_cast<int*>(context);
  return true;
}

}  // namespace

TEST_CASE("target strides and combinations that are refused, and the edges that are not") {
  Setup s;
  for (const auto* bytes : {&s.bytes, &s.stream}) {
    const Opened opened(*bytes);
    CAPTURE(opened.compressed);
    // The target mid-buffer: strides of up to 1,000 bytes either way stay inside.
    std::vector<std::uint8_t> fb(22000), work(64 * 1024);
    core::RenderParams p = s.p;
    p.target = fb.data() + 11000;
    core::RenderBuffers b;
    b.workspace = work.data();
    b.workspace_bytes = work.size();
    std::size_t n = 0;
    auto status = [&](const core::RenderParams& q) {
      int tiles = 0;
      const core::Status size = opened.tile_buffer_size(q, &n);
      const core::Status work_size = opened.workspace_size(q, &n);
      const core::Status drawn = opened.render(q, b, count_tile, &tiles);
      CHECK(size == drawn);  // the size calls refuse what render refuses
      CHECK(work_size == drawn);
      if (drawn != core::Status::ok) CHECK(tiles == 0);
      return drawn;
    };
    for (std::int32_t stride : {40, -40, 0, 41, -41, 1000})
      CHECK(status([&] { auto q = p; q.target_stride = stride; return q; }()) == core::Status::ok);
    for (std::int32_t stride : {39, -39, 1, -1, INT32_MIN, INT32_MAX})
      CHECK(status([&] { auto q = p; q.target_stride = stride; return q; }()) == core::Status::bad_params);
    // |stride| at most 2^19 bytes (the size calls only: no such buffer here).
    core::RenderParams edge = p;
    for (std::int32_t stride : {1 << 19, -(1 << 19)}) {
      edge.target_stride = stride;
      CHECK(opened.tile_buffer_size(edge, &n) == core::Status::ok);
      CHECK(n == 0);
    }
    for (std::int32_t stride : {(1 << 19) + 1, -(1 << 19) - 1}) {
      edge.target_stride = stride;
      CHECK(opened.tile_buffer_size(edge, &n) == core::Status::bad_params);
    }
    // The viewport's width counts, not the output's: a stride of 6 pixels for a 5-pixel viewport.
    core::RenderParams narrow = p;
    narrow.viewport = core::Rect{3, 2, 8, 9};
    narrow.target_stride = 12;
    CHECK(status(narrow) == core::Status::ok);
    narrow.target_stride = 9;
    CHECK(status(narrow) == core::Status::bad_params);
    // Packed tiles name the tile buffer's layout: a contradiction with a target.
    core::RenderParams packed = p;
    packed.packed_tiles = true;
    CHECK(status(packed) == core::Status::bad_params);
    // A stride without a target is a forgotten target.
    core::RenderParams no_target = s.p;
    no_target.target_stride = 40;
    std::vector<std::uint8_t> tile(8 * 4 * 2);
    core::RenderBuffers tb = b;
    tb.tile[0] = tile.data();
    tb.tile_bytes = tile.size();
    CHECK(opened.tile_buffer_size(no_target, &n) == core::Status::bad_params);
    int tiles = 0;
    CHECK(opened.render(no_target, tb, count_tile, &tiles) == core::Status::bad_params);
    // Without a target a tile buffer and a sink stay required; with one neither is.
    CHECK(opened.render(s.p, tb, nullptr, nullptr) == core::Status::null_argument);
    CHECK(opened.render(s.p, b, count_tile, &tiles) == core::Status::null_argument);
    CHECK(opened.render(p, b, nullptr, nullptr) == core::Status::ok);
    core::RenderBuffers short_tile = tb;
    short_tile.tile_bytes = 1;
    CHECK(opened.render(s.p, short_tile, count_tile, &tiles) == core::Status::tile_buffer_too_small);
    CHECK(opened.render(p, short_tile, count_tile, &tiles) == core::Status::ok);  // not used
  }
}

TEST_CASE("a sink that stops the frame leaves the target's later tiles untouched") {
  Setup s;
  const Opened opened(s.bytes);
  const int bpp = 2;
  Framebuffer fb(10, 20 * bpp + 4, 0);
  core::RenderParams p = s.p;
  p.target = fb.target();
  p.target_stride = fb.stride;
  std::vector<std::uint8_t> work(64 * 1024);
  core::RenderBuffers b;
  b.workspace = work.data();
  b.workspace_bytes = work.size();
  SinkLog log;
  log.target = fb.target();
  log.stride = fb.stride;
  log.bpp = bpp;
  log.view = core::Rect{0, 0, 20, 10};
  log.format = p.format;
  log.covered.assign(200, 0);
  log.stop_after = 2;  // tiles 8x4: (0..8, 0..4) and (8..16, 0..4) drawn, then stop
  REQUIRE(opened.render(p, b, log_tile, &log) == core::Status::stopped);
  CHECK(log.tiles == 2);
  CHECK(log.misplaced == 0);
  std::size_t drawn_outside = 0, drawn_inside = 0;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x)
      for (int k = 0; k < bpp; ++k) {
        const std::size_t i = fb.row_at(y) + std::size_t(x * bpp + k);
        const bool drawn = y < 4 && x < 16;
        if (!drawn) drawn_outside += fb.bytes[i] != guard_byte(i);
        if (drawn) drawn_inside += fb.bytes[i] != guard_byte(i);
      }
  CHECK(drawn_outside == 0);
  CHECK(drawn_inside > 0);
}

namespace {

struct CFrame {
  std::vector<std::uint8_t> bytes;
  int width = 0, bpp = 0;
};

// The C tile path's frame assembled from its tiles.
void assemble(void* context, const ts_tile* t) {
  CFrame& f = *static_cast<CFrame*>(context);
  for (int y = t->rect.y0; y < t->rect.y1; ++y)
    std::memcpy(&f.bytes[(std::size_t(y) * f.width + std::size_t(t->rect.x0)) * f.bpp],
                t->pixels + std::ptrdiff_t(y - t->rect.y0) * t->stride, std::size_t(t->rect.x1 - t->rect.x0) * f.bpp);
}

struct CLog {
  const std::uint8_t* target;
  std::int32_t stride;
  int tiles = 0, misplaced = 0;
};

int c_frame_sink(void* context, const ts_tile* t) {
  CLog& log = *static_cast<CLog*>(context);
  ++log.tiles;
  log.misplaced +=
      t->pixels != log.target + std::ptrdiff_t(t->rect.y0) * log.stride + t->rect.x0 * 3 || t->stride != log.stride;
  return 1;
}

}  // namespace

TEST_CASE("the C interface renders into a target: ts_render, ts_render_frame, ts_render_compressed") {
  Setup s;
  const int w = 20, h = 10, bpp = 3;
  ts_blob blob;
  ts_compressed_blob stream;
  REQUIRE(ts_open(s.bytes.data(), s.bytes.size(), &blob, nullptr) == TS_OK);
  REQUIRE(ts_open_compressed(s.stream.data(), s.stream.size(), &stream, nullptr) == TS_OK);
  ts_params p = TS_PARAMS_INIT;
  p.format = TS_RGB888;
  p.tile_width = 7;
  p.tile_height = 3;
  p.background[1] = 200;
  std::size_t tile = 0, work = 0;
  REQUIRE(ts_tile_buffer_size(&blob, &p, &tile) == TS_OK);
  REQUIRE(ts_workspace_size(&blob, &p, &work) == TS_OK);
  std::size_t scratch = 0, stream_work = 0;
  REQUIRE(ts_compressed_scratch_size(&stream, &p, &scratch) == TS_OK);
  std::vector<std::uint8_t> scratch_bytes(scratch);
  REQUIRE(ts_compressed_workspace_size(&stream, &p, scratch_bytes.data(), scratch, &stream_work, nullptr) == TS_OK);
  std::vector<std::uint8_t> tb(tile), ws(work > stream_work ? work : stream_work);
  CFrame reference;
  reference.width = w;
  reference.bpp = bpp;
  reference.bytes.assign(std::size_t(w) * h * bpp, 0);
  REQUIRE(ts_render(&blob, &p, tb.data(), tb.size(), ws.data(), ws.size(), assemble, &reference) == TS_OK);

  const std::int32_t stride = w * bpp + 5;
  auto same = [&](const Framebuffer& fb) {
    std::size_t differing = 0, touched = 0;
    for (std::size_t i = 0; i < fb.bytes.size(); ++i) {
      const std::ptrdiff_t from_top = std::ptrdiff_t(i) - std::ptrdiff_t(fb.start);
      const std::ptrdiff_t y = from_top >= 0 ? from_top / stride : -1, col = from_top - y * stride;
      if (y >= 0 && y < h && col < w * bpp)
        differing += fb.bytes[i] != reference.bytes[std::size_t(y * w * bpp + col)];
      else
        touched += fb.bytes[i] != guard_byte(i);
    }
    CHECK(differing == 0);
    CHECK(touched == 0);
  };
  p.target_stride = stride;
  Framebuffer a(h, stride, 1), b(h, stride, 1), c(h, stride, 1);
  p.target = a.target();
  std::size_t none = 7;
  REQUIRE(ts_tile_buffer_size(&blob, &p, &none) == TS_OK);
  CHECK(none == 0);
  REQUIRE(ts_compressed_tile_buffer_size(&stream, &p, &none) == TS_OK);
  CHECK(none == 0);
  REQUIRE(ts_render(&blob, &p, nullptr, 0, ws.data(), ws.size(), nullptr, nullptr) == TS_OK);
  same(a);
  p.target = b.target();
  ts_buffers buffers = {{nullptr, nullptr}, 0, ws.data(), ws.size()};
  CLog log{b.target(), stride};
  REQUIRE(ts_render_frame(&blob, &p, &buffers, c_frame_sink, &log) == TS_OK);
  CHECK(log.tiles == 3 * 4);
  CHECK(log.misplaced == 0);
  same(b);
  p.target = c.target();
  std::uint32_t offset = 0;
  REQUIRE(ts_render_compressed(&stream, &p, &buffers, nullptr, nullptr, &offset) == TS_OK);
  same(c);
  // Refused: a short stride, packed tiles, a stride without a target; a NULL sink without a target.
  p.target_stride = w * bpp - 1;
  CHECK(ts_render_frame(&blob, &p, &buffers, c_frame_sink, &log) == TS_BAD_PARAMS);
  CHECK(ts_render_compressed(&stream, &p, &buffers, c_frame_sink, &log, &offset) == TS_BAD_PARAMS);
  p.target_stride = stride;
  p.packed_tiles = 1;
  CHECK(ts_tile_buffer_size(&blob, &p, &none) == TS_BAD_PARAMS);
  p.packed_tiles = 0;
  p.target = nullptr;
  CHECK(ts_workspace_size(&blob, &p, &none) == TS_BAD_PARAMS);
  p.target_stride = 0;
  CHECK(ts_render(&blob, &p, tb.data(), tb.size(), ws.data(), ws.size(), nullptr, nullptr) == TS_NULL_ARGUMENT);
}
