// SPDX-License-Identifier: MIT
// The render of a compressed blob from its streams, band by band (render.h): bit-identical to the
// render of the v1 blob it was made from in every format, tiling, output size and fit; its
// workspace_size exact; a damaged stream ends in a status in bounds (run under ASan: every buffer
// is exactly sized).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <set>
#include <string>

#include "core_bridge/compress.h"
#include "core_support.h"
#include "io/tri_file.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

struct Sizes {
  core::Status status = core::Status::ok;
  std::uint32_t offset = 0;
  std::size_t scratch = 0, workspace = 0, tile = 0;
};

// measure_scratch_size, then workspace_size with exactly that scratch.
Sizes sizes_of(const core::CompressedBlob& blob, const core::RenderParams& p) {
  Sizes s;
  s.status = core::tile_buffer_size(blob, p, &s.tile);
  if (s.status == core::Status::ok) s.status = core::measure_scratch_size(blob, p, &s.scratch);
  if (s.status != core::Status::ok) return s;
  std::vector<std::uint8_t> scratch(s.scratch);
  core::BlobError error;
  s.status = core::workspace_size(blob, p, scratch.data(), scratch.size(), &s.workspace, &error);
  s.offset = error.offset;
  return s;
}

struct Counted {
  int tiles = 0;
};

// Renders with a workspace of exactly `bytes` (new[] storage: 16-aligned on the test hosts).
core::Status render_with(const core::CompressedBlob& blob, const core::RenderParams& p, std::size_t tile,
                         std::size_t bytes, int* tiles = nullptr, core::BlobError* error = nullptr) {
  std::vector<std::uint8_t> tiles_buffer(tile), work(bytes);
  Counted c;
  core::RenderBuffers b;
  b.tile[0] = tiles_buffer.data();
  b.tile_bytes = tile;
  b.workspace = bytes ? work.data() : nullptr;
  b.workspace_bytes = bytes;
  auto sink = [](void* context, const core::Tile*) {
    ++static_cast<Counted*>(context)->tiles;
    return true;
  };
  const core::Status s = core::render(blob, p, b, sink, &c, error);
  if (tiles) *tiles = c.tiles;
  return s;
}

void check_same_renders(const std::vector<std::uint8_t>& v1, const std::vector<std::uint8_t>& packed,
                        const std::vector<CoreOptions>& options, const std::vector<Tiling>& tilings) {
  for (const CoreOptions& o : options)
    for (const Tiling& t : tilings) {
      CAPTURE(int(o.format), o.width, o.height, int(o.fit), t.w, t.h);
      const CoreFrame a = core_frame(v1, o, t), b = core_frame(packed, o, t);
      CHECK(a.tiles == b.tiles);
      CHECK(bytes_differing(a.bytes, b.bytes) == 0);
    }
}

std::vector<CoreOptions> every_format() {
  std::vector<CoreOptions> out;
  for (core::PixelFormat f : {core::PixelFormat::l8, core::PixelFormat::rgb888, core::PixelFormat::rgb565_le,
                              core::PixelFormat::rgb565_be, core::PixelFormat::xrgb8888}) {
    CoreOptions o;
    o.format = f;
    o.dither = f == core::PixelFormat::rgb565_le;
    out.push_back(o);
  }
  return out;
}

// Output sizes other than the blob's, with each fit, and a viewport.
std::vector<CoreOptions> other_outputs(int w, int h) {
  std::vector<CoreOptions> out;
  for (core::Fit fit : {core::Fit::stretch, core::Fit::inside, core::Fit::fill})
    for (auto [ow, oh] : {std::pair{w * 2 + 3, h + 5}, {w / 2 + 1, h * 3 / 2}}) {
      CoreOptions o;
      o.width = ow;
      o.height = oh;
      o.fit = fit;
      o.format = core::PixelFormat::rgb565_be;
      out.push_back(o);
    }
  CoreOptions v;
  v.viewport = core::Rect{w / 5, h / 3, w - w / 4, h - 2};
  out.push_back(v);
  return out;
}

// workspace_size is exact: with it the frame renders whole, with a byte less (also the scratch
// of the measure) it is workspace_too_small.
void check_exact_workspace(const std::vector<std::uint8_t>& packed, const Tiling& t, const CoreOptions& o = {}) {
  core::CompressedBlob blob;
  REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &blob) == core::Status::ok);
  const core::RenderParams p = params_of(o, t);
  const Sizes s = sizes_of(blob, p);
  REQUIRE(s.status == core::Status::ok);
  CAPTURE(t.w, t.h, s.workspace);
  std::vector<std::uint8_t> short_scratch(s.scratch - 1);
  std::size_t ignored = 0;
  CHECK(core::workspace_size(blob, p, short_scratch.data(), short_scratch.size(), &ignored) ==
        core::Status::workspace_too_small);
  int tiles = 0;
  CHECK(render_with(blob, p, s.tile, s.workspace, &tiles) == core::Status::ok);
  CHECK(tiles > 0);
  CHECK(render_with(blob, p, s.tile, s.workspace - 1) == core::Status::workspace_too_small);
  CHECK(render_with(blob, p, s.tile, 0) == core::Status::workspace_too_small);
}

void round_trip(const std::vector<std::uint8_t>& v1, const std::vector<Tiling>& tilings, int w, int h) {
  const std::vector<std::uint8_t> packed = compress_blob(v1, "test");
  check_same_renders(v1, packed, every_format(), tilings);
  check_same_renders(v1, packed, other_outputs(w, h), {{32, 32}, {13, 7}, {0, 0}});
  for (const Tiling& t : tilings) check_exact_workspace(packed, t);
}

Triangulation layered_mesh(int w, int h, std::uint32_t seed) {
  Triangulation t;
  t.width = w;
  t.height = h;
  t.space = ColorSpace::ycbcr;
  for (int l = 0; l < 3; ++l) t.layers.push_back(random_lattice_mesh(w, h, 30 + 20 * l, seed + l, 3));
  return t;
}

}  // namespace

TEST_CASE("a compressed blob renders from its streams as its v1 blob does: generated meshes") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    CAPTURE(int(m));
    SECTION("grey, with flips") {
      round_trip(pack_blob(single_mesh(random_lattice_mesh(40, 30, 80, 1, 10), 40, 30), m), all_tilings(), 40, 30);
    }
    SECTION("rgb") {
      round_trip(pack_blob(single_mesh(random_lattice_mesh(37, 23, 60, 2, 0, 3), 37, 23, ColorSpace::rgb), m),
                 all_tilings(), 37, 23);
    }
    SECTION("ycbcr, sub-pixel vertices, convex hull domain") {
      round_trip(pack_blob(single_mesh(random_subpixel_mesh(41, 29, 70, 3, false, 3), 41, 29, ColorSpace::ycbcr), m),
                 all_tilings(), 41, 29);
    }
    SECTION("three layers") { round_trip(pack_blob(layered_mesh(33, 27, 4), m), all_tilings(), 33, 27); }
    SECTION("tall triangles and lifted corners") {
      round_trip(pack_blob(single_mesh(random_lattice_mesh(300, 200, 700, 21, 0, 3), 300, 200, ColorSpace::rgb), m),
                 {{32, 32}, {0, 16}, {0, 1}, {0, 0}}, 300, 200);
    }
  }
}

TEST_CASE("a compressed blob renders from its streams as its v1 blob does: gradients on a step of 2^6") {
  SECTION("rgb") {
    const std::vector<std::uint8_t> v1 =
        stepped_gradient_blob(single_mesh(random_lattice_mesh(37, 23, 60, 2, 0, 3), 37, 23, ColorSpace::rgb), 6);
    REQUIRE(compress_blob(v1)[64 + 24] == 6);
    round_trip(v1, all_tilings(), 37, 23);
  }
  SECTION("three layers") {
    const std::vector<std::uint8_t> v1 = stepped_gradient_blob(layered_mesh(33, 27, 4), 6);
    const std::vector<std::uint8_t> packed = compress_blob(v1);
    for (int l = 0; l < 3; ++l) CHECK(packed[64 + 32 * l + 24] == 6);
    round_trip(v1, all_tilings(), 33, 27);
  }
}

TEST_CASE("a compressed blob renders from its streams as its v1 blob does: demo meshes") {
  for (const char* name : {"kodim23.grey.tri", "kodim23.rgb.tri", "kodim23.ycbcr-layers.tri"}) {
    CAPTURE(name);
    const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/" + name);
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
      CAPTURE(int(m));
      const std::vector<std::uint8_t> v1 = pack_blob(tri, m), packed = compress_blob(v1, name);
      CoreOptions o;
      o.format = core::PixelFormat::rgb565_le;
      o.dither = true;
      check_same_renders(v1, packed, {o}, {{32, 32}, {0, 16}, {0, 0}, {29, 19}});
      CoreOptions half;
      half.width = tri.width / 2 + 7;
      half.height = tri.height / 3;
      half.fit = core::Fit::inside;
      check_same_renders(v1, packed, {half}, {{32, 32}});
      for (const Tiling& t : {Tiling{32, 32}, Tiling{0, 16}}) check_exact_workspace(packed, t);
    }
  }
}

TEST_CASE("a compressed render stops at the workspace's end only in the band that overflows it") {
  const std::vector<std::uint8_t> packed =
      compress_blob(pack_blob(single_mesh(random_lattice_mesh(60, 60, 200, 5), 60, 60), core::Method::bilinear));
  core::CompressedBlob blob;
  REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &blob) == core::Status::ok);
  const core::RenderParams p = params_of(CoreOptions{}, {8, 8});
  const Sizes s = sizes_of(blob, p);
  REQUIRE(s.status == core::Status::ok);
  // Short of the decoders and rings: refused before any tile; short of a band's live triangles:
  // the tiles of the bands before it went out.
  int refused_before = 0, stopped_late = 0;
  for (std::size_t n = 0; n < s.workspace; ++n) {
    int tiles = -1;
    const core::Status st = render_with(blob, p, s.tile, n, &tiles);
    if (st != core::Status::workspace_too_small) FAIL_CHECK("workspace of " << n << " bytes: status " << int(st));
    (tiles == 0 ? refused_before : stopped_late)++;
  }
  CHECK(refused_before > 0);
  CHECK(stopped_late > 0);
}

TEST_CASE("every damaged byte and every truncation of a compressed blob renders to a status, in bounds") {
  const Triangulation tri = single_mesh(random_lattice_mesh(24, 18, 30, 9, 2, 3), 24, 18, ColorSpace::rgb);
  // Both methods, and zienkiewicz with its gradients on a step of 2^6 (coded in units of it).
  for (const std::vector<std::uint8_t>& v1 :
       {pack_blob(tri, core::Method::bilinear), pack_blob(tri, core::Method::zienkiewicz),
        stepped_gradient_blob(tri, 6)}) {
    const std::vector<std::uint8_t> good = compress_blob(v1);
    CAPTURE(int(good[17]), int(good[64 + 24]));
    const core::RenderParams p = params_of(CoreOptions{}, {8, 4});
    std::size_t big = 0;
    {
      core::CompressedBlob blob;
      REQUIRE(core::open_compressed_blob(good.data(), good.size(), &blob) == core::Status::ok);
      const Sizes s = sizes_of(blob, p);
      REQUIRE(s.status == core::Status::ok);
      big = s.workspace * 4;  // room for the live triangles of a damaged stream
    }
    std::size_t refused = 0, trials = 0;
    auto attempt = [&](const std::vector<std::uint8_t>& bytes) {
      std::vector<std::uint8_t> exact(bytes);
      core::CompressedBlob blob;
      core::BlobError error;
      core::Status st = core::open_compressed_blob(exact.data(), exact.size(), &blob, &error);
      if (st != core::Status::ok) return st;
      const Sizes s = sizes_of(blob, p);
      // The render without the measure meets the damage while drawing (its own checks); with the
      // measure's size it renders whole whenever the measure accepted.
      std::size_t tile = 0;
      REQUIRE(core::tile_buffer_size(blob, p, &tile) == core::Status::ok);
      const core::Status drawn = render_with(blob, p, tile, big, nullptr, &error);
      if (drawn != core::Status::ok && drawn != core::Status::workspace_too_small) CHECK(error.offset <= good.size());
      if (s.status != core::Status::ok) {
        CHECK(s.offset <= good.size());
        return s.status;
      }
      CHECK(render_with(blob, p, s.tile, s.workspace) == core::Status::ok);
      return core::Status::ok;
    };
    for (std::size_t at = 0; at < good.size(); ++at)
      for (std::uint8_t mask : {std::uint8_t(0x01), std::uint8_t(0x80), std::uint8_t(0xFF)}) {
        std::vector<std::uint8_t> b = good;
        b[at] = std::uint8_t(b[at] ^ mask);
        ++trials;
        refused += attempt(b) != core::Status::ok;
      }
    CHECK(refused > trials * 9 / 10);
    for (std::size_t n = 0; n < good.size(); ++n) {
      CAPTURE(n);
      CHECK(attempt(std::vector<std::uint8_t>(good.begin(), good.begin() + std::ptrdiff_t(n))) != core::Status::ok);
    }
  }
}

namespace {

// The store's need for V vertices and C triangles of which F have flags (render.h's formula, for a
// blob of one layer): vertex slots (4 bytes of position, 2 per value, 8 per gradient pair, each
// array 4-aligned); per triangle and per flag record 4 bytes and a u32 guard with at most 1,024
// vertices, else 6 bytes and a u16 guard (4-aligned); and the larger of the renumbering table
// (align4(6 ceil(V / 32)): a bit and, per 32, a u16) and the bitmap (a bit per record,
// 4 ceil((C + F) / 32)).
std::size_t store_formula(std::size_t v, std::size_t c, std::size_t f, std::size_t per_vertex, bool gradients) {
  auto a4 = [](std::size_t n) { return (n + 3) / 4 * 4; };
  const std::size_t renumber = a4(6 * ((v + 31) / 32)), bits = 4 * ((c + f + 31) / 32);
  const std::size_t records = !c ? 0 : (v <= 1024 ? 4 * (c + f) + 4 : a4(6 * (c + f) + 2));
  return 4 * v + a4(2 * v * per_vertex) + (gradients ? 8 * v * per_vertex : 0) + records +
         (renumber > bits ? renumber : bits);
}

// A mesh of the four corners of a w x h frame, with `value_count` values per vertex; the corners
// go into `taken` (the tests add points where none is yet).
Mesh corner_mesh(int w, int h, int value_count, std::set<std::pair<int, int>>* taken) {
  Mesh mesh;
  mesh.value_count = value_count;
  for (auto [x, y] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}}) {
    taken->insert({x, y});
    mesh.points.push_back({double(x), double(y)});
  }
  return mesh;
}

// Triangles of the v1 blob with flags (the one layer's).
std::size_t flagged_triangles(const std::vector<std::uint8_t>& v1) {
  core::Blob blob;
  REQUIRE(core::open_blob(v1.data(), v1.size(), &blob) == core::Status::ok);
  std::size_t n = 0;
  for (std::uint32_t t = 0; t < blob.layers[0].triangle_count; ++t) {
    const std::uint8_t* p = blob.layers[0].triangles + core::blob_triangle_size * t;
    n += (p[6] | p[7]) != 0;
  }
  return n;
}

core::CompressedWorkspace figures_of(const std::vector<std::uint8_t>& packed, const core::RenderParams& p) {
  core::CompressedBlob blob;
  REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &blob) == core::Status::ok);
  std::size_t scratch_bytes = 0;
  REQUIRE(core::measure_scratch_size(blob, p, &scratch_bytes) == core::Status::ok);
  std::vector<std::uint8_t> scratch(scratch_bytes);
  core::CompressedWorkspace f;
  REQUIRE(core::workspace_size(blob, p, scratch.data(), scratch.size(), &f) == core::Status::ok);
  return f;
}

// One band over the whole frame: every triangle of a lattice mesh has rows (its corners are on
// pixel rows), so the band holds all of them and every vertex once.
void check_one_band_store(const std::vector<std::uint8_t>& v1, const std::vector<std::uint8_t>& packed,
                          const Mesh& mesh, core::Method m) {
  const core::CompressedWorkspace f = figures_of(packed, params_of(CoreOptions{}, {0, 0}));
  CHECK(f.live_vertices == mesh.points.size());
  CHECK(f.live_triangles == mesh.triangles.size());
  const std::size_t flagged = flagged_triangles(v1);
  CHECK(flagged > 0);  // the boundary's triangles: flag records are in the store
  CHECK(f.band_store == store_formula(mesh.points.size(), mesh.triangles.size(), flagged, std::size_t(mesh.value_count),
                                      m == core::Method::zienkiewicz));
}

}  // namespace

TEST_CASE("the band store keeps each live vertex once") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    CAPTURE(int(m));
    DYNAMIC_SECTION("a band whose vertices are shared by many triangles: fans, method " << int(m)) {
      // Two centres each with a ring of 48 points around it: a fan of 32 or more triangles on one
      // vertex (the rounded ring is not quite a circle), all in the bands of 64 or more rows.
      Mesh mesh;
      mesh.value_count = 3;
      for (auto [x, y] : {std::pair{0, 0}, {199, 0}, {0, 99}, {199, 99}}) mesh.points.push_back({double(x), double(y)});
      for (int c = 0; c < 2; ++c) {
        const double cx = 50 + 100 * c, cy = 50;
        mesh.points.push_back({cx, cy});
        for (int k = 0; k < 48; ++k) {
          const double a = 2 * 3.14159265358979 * (k + 0.5 * c) / 48;
          mesh.points.push_back({std::round(cx + 40 * std::cos(a)), std::round(cy + 40 * std::sin(a))});
        }
      }
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> rv(0, 255);
      for (std::size_t i = 0; i < mesh.points.size() * 3; ++i) mesh.values.push_back(rv(rng));
      mesh.triangles = delaunay_triangulation(mesh.points);
      int most = 0;  // the largest vertex degree
      for (std::size_t v = 0; v < mesh.points.size(); ++v) {
        int d = 0;
        for (const auto& t : mesh.triangles) d += t.v[0] == v || t.v[1] == v || t.v[2] == v;
        most = d > most ? d : most;
      }
      CHECK(most >= 32);
      const Triangulation tri = single_mesh(mesh, 200, 100, ColorSpace::rgb);
      const std::vector<std::uint8_t> v1 = pack_blob(tri, m), packed = compress_blob(v1, "fans");
      check_same_renders(v1, packed, every_format(), {{0, 0}, {0, 64}, {32, 32}, {0, 7}, {200, 100}});
      for (const Tiling& t : {Tiling{0, 0}, Tiling{0, 64}, Tiling{16, 16}}) check_exact_workspace(packed, t);
      check_one_band_store(v1, packed, mesh, m);
    }
    DYNAMIC_SECTION("vertices carried across many bands: tall triangles, bands of one row, method " << int(m)) {
      // Vertices only near the top and the bottom rows (and the corners): most triangles reach
      // from the top to the bottom, so their corners stay in the store for 300 one-row bands,
      // renumbered at every band as the triangles beside them end.
      std::set<std::pair<int, int>> taken;
      Mesh mesh = corner_mesh(100, 300, 1, &taken);
      std::mt19937 rng(11);
      std::uniform_int_distribution<int> rx(0, 99), ry(0, 9);
      while (mesh.points.size() < 120) {
        const int x = rx(rng), y = mesh.points.size() % 2 ? ry(rng) : 299 - ry(rng);
        if (taken.insert({x, y}).second) mesh.points.push_back({double(x), double(y)});
      }
      std::uniform_real_distribution<double> rv(0, 255);
      for (std::size_t i = 0; i < mesh.points.size(); ++i) mesh.values.push_back(rv(rng));
      mesh.triangles = delaunay_triangulation(mesh.points);
      const Triangulation tri = single_mesh(mesh, 100, 300);
      const std::vector<std::uint8_t> v1 = pack_blob(tri, m), packed = compress_blob(v1, "tall");
      check_same_renders(v1, packed, every_format(), {{0, 1}, {7, 1}, {0, 3}, {32, 32}});
      for (const Tiling& t : {Tiling{0, 1}, Tiling{9, 2}}) check_exact_workspace(packed, t);
      // The band across the middle rows holds the tall triangles and only their corners.
      const core::CompressedWorkspace f = figures_of(packed, params_of(CoreOptions{}, {0, 1}));
      CHECK(f.live_vertices < 3 * f.live_triangles / 2);
      check_one_band_store(v1, packed, mesh, m);
    }
  }
}

TEST_CASE("a band at the store's index limit: a layer of 65,535 vertices in one band") {
  // Every vertex live at once: the u16 slots are all used (slot 65,534 the last), and the
  // triangles (about 131,000) are bounded only by the workspace.
  const Mesh mesh = random_lattice_mesh(320, 256, int(core::blob_max_vertices) - 4, 13);
  REQUIRE(mesh.points.size() == core::blob_max_vertices);
  const Triangulation tri = single_mesh(mesh, 320, 256);
  const std::vector<std::uint8_t> v1 = pack_blob(tri, core::Method::bilinear), packed = compress_blob(v1, "limit");
  CoreOptions o;
  o.format = core::PixelFormat::l8;
  check_same_renders(v1, packed, {o}, {{0, 0}, {0, 128}});
  check_exact_workspace(packed, {0, 0}, o);
  check_one_band_store(v1, packed, mesh, core::Method::bilinear);
}

TEST_CASE("the band store's records change layout where its vertices pass 1,024, both ways") {
  // Dense at the top, sparse below: the first band's store passes 1,024 vertices while it takes
  // triangles (its records unpacked as they move up), a later band's falls back under it (packed
  // again as they move down), and one band over the frame holds them all unpacked; 1,024 and
  // 1,025 vertices in one band meet the limit exactly. (test_band_store.cpp checks the store's
  // records and guard after every band against a model.)
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    CAPTURE(int(m));
    std::set<std::pair<int, int>> taken;
    Mesh mesh = corner_mesh(120, 200, 3, &taken);
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> rx(0, 119), top(0, 47), rest(48, 199);
    while (mesh.points.size() < 1500) {
      const std::pair<int, int> p{rx(rng), mesh.points.size() < 1400 ? top(rng) : rest(rng)};
      if (taken.insert(p).second) mesh.points.push_back({double(p.first), double(p.second)});
    }
    std::uniform_real_distribution<double> rv(0, 255);
    for (std::size_t i = 0; i < mesh.points.size() * 3; ++i) mesh.values.push_back(rv(rng));
    mesh.triangles = delaunay_triangulation(mesh.points);
    const Triangulation tri = single_mesh(mesh, 120, 200, ColorSpace::rgb);
    const std::vector<std::uint8_t> v1 = pack_blob(tri, m), packed = compress_blob(v1, "dense top");
    const std::vector<Tiling> tilings = {{0, 0}, {0, 50}, {0, 40}, {32, 32}, {0, 9}};
    CHECK(figures_of(packed, params_of(CoreOptions{}, {0, 50})).live_vertices > 1024);
    CHECK(figures_of(packed, params_of(CoreOptions{}, {0, 9})).live_vertices <= 1024);
    check_same_renders(v1, packed, every_format(), tilings);
    for (const Tiling& t : tilings) check_exact_workspace(packed, t);
    check_one_band_store(v1, packed, mesh, m);
    for (int n : {1020, 1021}) {  // 1,024 and 1,025 vertices with the corners
      const Mesh edge = random_lattice_mesh(64, 48, n, 19, 0, 3);
      const std::vector<std::uint8_t> e1 = pack_blob(single_mesh(edge, 64, 48, ColorSpace::rgb), m),
                                      e2 = compress_blob(e1, "limit");
      check_same_renders(e1, e2, every_format(), {{0, 0}, {16, 16}});
      check_exact_workspace(e2, {0, 0});
      check_one_band_store(e1, e2, edge, m);
    }
  }
}
