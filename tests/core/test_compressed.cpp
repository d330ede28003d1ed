// SPDX-License-Identifier: MIT
// Compressed blobs: the stream round-trips every v1 blob exactly (every vertex and triangle, as
// the core decodes them, equals the v1 blob's, and the renders are bit-identical), and a
// damaged stream ends in a status without reading or writing out of bounds (run under ASan:
// every buffer is exactly sized).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>
#include <tuple>
#include <random>
#include <string>

#include "../support/blob_seal.h"
#include "core_bridge/compress.h"
#include "core_support.h"
#include "io/tri_file.h"
#include "scenes/bench_scenes.h"
#include "tristream/compressed_blob.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

std::uint32_t get16(const std::vector<std::uint8_t>& b, std::size_t at) { return b[at] | (b[at + 1] << 8); }
std::uint32_t get32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return get16(b, at) | (get16(b, at + 2) << 16);
}

struct Expanded {
  core::Status status = core::Status::ok;
  std::uint32_t offset = 0;
  std::vector<std::uint8_t> v1;
};

// Opens and expands `bytes` through exactly sized copies.
Expanded expand(const std::vector<std::uint8_t>& bytes) {
  Expanded r;
  std::vector<std::uint8_t> exact(bytes);
  core::CompressedBlob blob;
  core::BlobError error;
  r.status = core::open_compressed_blob(exact.data(), exact.size(), &blob, &error);
  r.offset = error.offset;
  if (r.status != core::Status::ok) return r;
  r.v1.resize(core::expanded_blob_size(blob));
  std::vector<std::uint8_t> ring(core::expand_workspace_size(blob));
  r.status = core::expand_compressed_blob(blob, r.v1.data(), r.v1.size(), ring.data(), ring.size(), &error);
  r.offset = error.offset;
  return r;
}

// Corner k of triangle t: position, values, gradients and the triangle's flags.
using Corner = std::vector<std::uint32_t>;
Corner corner(const std::vector<std::uint8_t>& b, int layer, std::uint32_t t, int k) {
  const std::size_t e = get32(b, 28) + 32 * layer;
  const int nv = b[19];
  const bool z = b[17] == 1;
  const std::uint32_t v = get16(b, get32(b, e + 20) + 8 * t + 2 * k);
  Corner c{get16(b, get32(b, e + 8) + 4 * v), get16(b, get32(b, e + 8) + 4 * v + 2)};
  for (int i = 0; i < nv; ++i) {
    c.push_back(get16(b, get32(b, e + 12) + 2 * (v * nv + i)));
    if (z) {
      c.push_back(get32(b, get32(b, e + 16) + 8 * (v * nv + i)));
      c.push_back(get32(b, get32(b, e + 16) + 8 * (v * nv + i) + 4));
    }
  }
  c.push_back(get16(b, get32(b, e + 20) + 8 * t + 6));
  return c;
}

std::vector<Corner> vertices(const std::vector<std::uint8_t>& b, int layer) {
  const std::size_t e = get32(b, 28) + 32 * layer;
  const int nv = b[19];
  std::vector<Corner> out;
  for (std::uint32_t v = 0; v < get32(b, e); ++v) {
    Corner c{get16(b, get32(b, e + 8) + 4 * v), get16(b, get32(b, e + 8) + 4 * v + 2)};
    for (int i = 0; i < nv; ++i) c.push_back(get16(b, get32(b, e + 12) + 2 * (v * nv + i)));
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The decoded blob holds the same meshes: header fields, every triangle in order with the data
// of its corners in order, and the same vertices (numbered in raster order).
void check_same_meshes(const std::vector<std::uint8_t>& v1, const std::vector<std::uint8_t>& decoded) {
  REQUIRE(decoded.size() == v1.size());
  CHECK(std::equal(v1.begin() + 12, v1.begin() + 28, decoded.begin() + 12));
  CHECK(get32(v1, 32) == get32(decoded, 32));
  for (int l = 0; l < v1[18]; ++l) {
    const std::size_t e = get32(v1, 28) + 32 * l, d = get32(decoded, 28) + 32 * l;
    REQUIRE(get32(v1, e) == get32(decoded, d));
    REQUIRE(get32(v1, e + 4) == get32(decoded, d + 4));
    std::uint32_t differing = 0;
    for (std::uint32_t t = 0; t < get32(v1, e + 4); ++t)
      for (int k = 0; k < 3; ++k) differing += corner(v1, l, t, k) != corner(decoded, l, t, k);
    CHECK(differing == 0);
    CHECK(vertices(v1, l) == vertices(decoded, l));
  }
}

// Renders of both blobs are identical in every format the blob can be drawn in and every tiling.
void check_same_renders(const std::vector<std::uint8_t>& v1, const std::vector<std::uint8_t>& decoded,
                        const std::vector<Tiling>& tilings) {
  for (core::PixelFormat f : {core::PixelFormat::l8, core::PixelFormat::rgb888, core::PixelFormat::rgb565_le,
                              core::PixelFormat::xrgb8888})
    for (const Tiling& t : tilings) {
      CoreOptions o;
      o.format = f;
      o.dither = f == core::PixelFormat::rgb565_le;
      CAPTURE(int(f), t.w, t.h);
      CHECK(bytes_differing(core_frame(v1, o, t).bytes, core_frame(decoded, o, t).bytes) == 0);
    }
}

void round_trip(const std::vector<std::uint8_t>& v1, const std::vector<Tiling>& tilings = all_tilings()) {
  CompressStats stats;
  const std::vector<std::uint8_t> packed = compress_blob(v1, "test", &stats);
  CHECK(stats.bytes == packed.size());
  CHECK(packed.size() < v1.size());
  const Expanded r = expand(packed);
  REQUIRE(r.status == core::Status::ok);
  check_same_meshes(v1, r.v1);
  check_same_renders(v1, r.v1, tilings);
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

TEST_CASE("compressed blobs of generated meshes decode to the same meshes and renders") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    CAPTURE(int(m));
    SECTION("grey, with flips") { round_trip(pack_blob(single_mesh(random_lattice_mesh(40, 30, 80, 1, 10), 40, 30), m)); }
    SECTION("rgb") {
      round_trip(pack_blob(single_mesh(random_lattice_mesh(37, 23, 60, 2, 0, 3), 37, 23, ColorSpace::rgb), m));
    }
    SECTION("ycbcr, sub-pixel vertices, convex hull domain") {
      round_trip(pack_blob(single_mesh(random_subpixel_mesh(41, 29, 70, 3, false, 3), 41, 29, ColorSpace::ycbcr), m));
    }
    SECTION("three layers") { round_trip(pack_blob(layered_mesh(33, 27, 4), m)); }
  }
}

TEST_CASE("compressed demo meshes decode to the same meshes and renders") {
  for (const char* name : {"kodim23.grey.tri", "kodim23.rgb.tri", "kodim23.ycbcr-layers.tri"}) {
    CAPTURE(name);
    const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/" + name);
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz})
      round_trip(pack_blob(tri, m), {{32, 32}, {0, 16}});
  }
}

// CPU seconds of the fastest of five decodes of `packed`.
double seconds_to_decode(const std::vector<std::uint8_t>& packed) {
  double best = 1e30;
  for (int i = 0; i < 5; ++i) {
    const std::clock_t t0 = std::clock();
    const Expanded r = expand(packed);
    const std::clock_t t1 = std::clock();
    REQUIRE(r.status == core::Status::ok);
    best = std::min(best, double(t1 - t0) / CLOCKS_PER_SEC);
  }
  return best;
}

TEST_CASE("meshes coded far from the first corner (a two-row strip, a thin fan) round-trip, in linear time") {
  // Issue 44 item 4: a third corner coded by its count among the unused vertices after the first
  // corner made the decoder walk every vertex between them, quadratic in the mesh for these; the
  // reach limit (compressed_fresh_reach) bounds the walk. Four times the mesh must take at most
  // about four times the decode (quadratic: sixteen).
  using Scene = Triangulation (*)(int);
  for (auto [name, scene, n] : {std::tuple{"strip", Scene(scenes::two_row_strip), 4000},
                               std::tuple{"fan", Scene(scenes::thin_fan), 8000}}) {
    CAPTURE(name);
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz})
      round_trip(pack_blob(scene(500), m), {{32, 32}, {0, 16}});
    const std::vector<std::uint8_t> small = compress_blob(pack_blob(scene(n), core::Method::bilinear));
    const std::vector<std::uint8_t> large = compress_blob(pack_blob(scene(4 * n), core::Method::bilinear));
    const double ts = seconds_to_decode(small), tl = seconds_to_decode(large);
    std::printf("%s(%d) decoded in %.4f s, %s(%d) in %.4f s (%.1fx)\n", name, n, ts, name, 4 * n, tl, tl / ts);
    CHECK(tl <= 6 * ts);
  }
}

TEST_CASE("any valid v1 blob round-trips: rotated triangles, value fractions, sub-pixel bits, flags") {
  std::vector<std::uint8_t> v1 =
      pack_blob(single_mesh(random_lattice_mesh(30, 20, 40, 7, 0, 3), 30, 20, ColorSpace::rgb), core::Method::zienkiewicz);
  const std::size_t e = get32(v1, 28);
  const std::uint32_t nv = get32(v1, e), nt = get32(v1, e + 4);
  const std::size_t pos = get32(v1, e + 8), val = get32(v1, e + 12), tri = get32(v1, e + 20);
  for (std::uint32_t k = 0; k < 3 * nv; k += 5) v1[val + 2 * k] = std::uint8_t(k * 37 + 1);  // fraction bytes
  for (std::uint32_t v = 0; v < nv; v += 3) {
    // Interior vertices move by a sub-pixel step where the triangles stay positive.
    std::vector<std::uint8_t> moved = v1;
    moved[pos + 4 * v] = std::uint8_t(moved[pos + 4 * v] ^ 5);
    seal_blob(moved.data(), moved.size());
    core::Blob blob;
    if (core::open_blob(moved.data(), moved.size(), &blob) == core::Status::ok) v1 = moved;
  }
  for (std::uint32_t t = 0; t < nt; t += 2) {
    std::uint8_t* p = &v1[tri + 8 * t];
    const std::array<std::uint8_t, 6> old{p[0], p[1], p[2], p[3], p[4], p[5]};
    const int r = 1 + int(t / 2 % 2);  // rotate by one or two
    for (int k = 0; k < 3; ++k) p[2 * k] = old[2 * ((k + r) % 3)], p[2 * k + 1] = old[2 * ((k + r) % 3) + 1];
    p[6] = std::uint8_t(p[6] ^ (t % 7 == 0 ? 0x55 : 0));
    p[7] = std::uint8_t(p[7] ^ (t % 11 == 0 ? 1 : 0));
  }
  seal_blob(v1.data(), v1.size());
  core::Blob blob;
  REQUIRE(core::open_blob(v1.data(), v1.size(), &blob) == core::Status::ok);
  round_trip(v1, {{8, 8}, {0, 0}});
}

TEST_CASE("every damaged byte and every truncation of a compressed blob ends in a status, in bounds") {
  const Triangulation tri = single_mesh(random_lattice_mesh(24, 18, 30, 9, 2, 3), 24, 18, ColorSpace::rgb);
  // The estimated gradients (step 0), and the same rounded to a step of 2^6.
  for (const std::vector<std::uint8_t>& v1 :
       {pack_blob(tri, core::Method::zienkiewicz), stepped_gradient_blob(tri, 6)}) {
    const std::vector<std::uint8_t> good = compress_blob(v1);
    CAPTURE(int(good[64 + 24]));
    REQUIRE(expand(good).status == core::Status::ok);
    std::size_t refused = 0, trials = 0;
    for (std::size_t at = 0; at < good.size(); ++at)
      for (std::uint8_t mask : {std::uint8_t(0x01), std::uint8_t(0x80), std::uint8_t(0xFF)}) {
        std::vector<std::uint8_t> b = good;
        b[at] = std::uint8_t(b[at] ^ mask);
        const Expanded r = expand(b);
        ++trials;
        if (r.status != core::Status::ok) {
          ++refused;
          CHECK(r.offset <= good.size());
        } else {
          core::Blob blob;  // what is accepted is a valid v1 blob
          CHECK(core::open_blob(r.v1.data(), r.v1.size(), &blob) == core::Status::ok);
        }
      }
    // Almost every change of a range-coded stream is caught (the exact end and the checks).
    CHECK(refused > trials * 9 / 10);
    for (std::size_t n = 0; n < good.size(); ++n) {
      std::vector<std::uint8_t> b(good.begin(), good.begin() + std::ptrdiff_t(n));
      CAPTURE(n);
      CHECK(expand(b).status != core::Status::ok);
    }
  }
}

TEST_CASE("gradients on a coarse step are coded in units of it: the layer table's step bits") {
  const Triangulation rgb = single_mesh(random_lattice_mesh(60, 40, 150, 31, 0, 3), 60, 40, ColorSpace::rgb);
  for (const Triangulation& tri : {rgb, layered_mesh(33, 27, 8)}) {
    const std::vector<std::uint8_t> v1 = stepped_gradient_blob(tri, 6);
    CompressStats stats;
    const std::vector<std::uint8_t> packed = compress_blob(v1, "test", &stats);
    REQUIRE(stats.gradient_step_bits.size() == tri.layers.size());
    for (std::size_t l = 0; l < tri.layers.size(); ++l) {
      CHECK(packed[64 + 32 * l + 24] == 6);
      CHECK(stats.gradient_step_bits[l] == 6);
    }
    core::CompressedBlob blob;
    REQUIRE(core::open_compressed_blob(packed.data(), packed.size(), &blob) == core::Status::ok);
    CHECK(blob.layers[0].gradient_shift == 6);
    // Expanded: exactly the v1 blob's gradients (and everything else), and the same renders.
    round_trip(v1, {{32, 32}, {0, 0}});
    // One odd component: step 0, the low 6 bits of every component coded again (a bit each).
    CompressStats odd_stats;
    const std::vector<std::uint8_t> odd = compress_blob(stepped_gradient_blob(tri, 6, true), "test", &odd_stats);
    CHECK(odd[64 + 24] == 0);
    const double components = 2.0 * double(stats.vertices) * tri.layers[0].value_count;
    CAPTURE(packed.size(), odd.size(), components);
    CHECK(packed.size() < odd.size());
    CHECK(odd_stats.gradient_bits - stats.gradient_bits > 5.0 * components);
  }
  // Bilinear blobs and gradients of 0 keep step 0; so do the estimated gradients (odd ones).
  CHECK(compress_blob(pack_blob(rgb, core::Method::bilinear))[64 + 24] == 0);
  CHECK(compress_blob(pack_blob(rgb, core::Method::zienkiewicz))[64 + 24] == 0);
}

TEST_CASE("a layer's gradient step beyond 24, or on a bilinear blob, is refused at its byte") {
  const Triangulation tri = layered_mesh(33, 27, 8);
  const std::vector<std::uint8_t> stepped = compress_blob(stepped_gradient_blob(tri, 6));
  const std::vector<std::uint8_t> bilinear = compress_blob(pack_blob(tri, core::Method::bilinear));
  for (std::size_t l = 0; l < 3; ++l) {
    const std::size_t at = 64 + 32 * l + 24;
    CAPTURE(l);
    for (std::uint8_t step : {std::uint8_t(25), std::uint8_t(0xFF)}) {
      std::vector<std::uint8_t> b = stepped;
      b[at] = step;
      const Expanded r = expand(b);
      CHECK(r.status == core::Status::bad_header);
      CHECK(r.offset == at);
    }
    for (std::uint8_t step : {std::uint8_t(1), std::uint8_t(6), std::uint8_t(24)}) {
      std::vector<std::uint8_t> b = bilinear;
      b[at] = step;
      const Expanded r = expand(b);
      CHECK(r.status == core::Status::bad_header);
      CHECK(r.offset == at);
    }
    // Any step up to 24 opens; one other than the encoder's decodes to other gradients or a
    // status, in bounds (under ASan), and whatever expands is a valid v1 blob.
    for (std::uint8_t step : {std::uint8_t(0), std::uint8_t(5), std::uint8_t(7), std::uint8_t(24)}) {
      std::vector<std::uint8_t> b = stepped;
      b[at] = step;
      core::CompressedBlob blob;
      REQUIRE(core::open_compressed_blob(b.data(), b.size(), &blob) == core::Status::ok);
      CHECK(blob.layers[l].gradient_shift == step);
      const Expanded r = expand(b);
      if (r.status == core::Status::ok) {
        core::Blob v1;
        CHECK(core::open_blob(r.v1.data(), r.v1.size(), &v1) == core::Status::ok);
      } else {
        CHECK(r.offset <= b.size());
      }
    }
  }
}

TEST_CASE("a truncated stream inside a whole blob is refused with its offset") {
  const std::vector<std::uint8_t> v1 = pack_blob(single_mesh(random_lattice_mesh(24, 18, 30, 11), 24, 18), core::Method::bilinear);
  std::vector<std::uint8_t> b = compress_blob(v1);
  // Shorten the stream by its last byte (the header still describes a consistent layout).
  const std::uint32_t stream = get32(b, 64 + 8), bytes = get32(b, 64 + 12);
  b.resize(b.size() - 1);
  for (int k = 0; k < 4; ++k) b[64 + 12 + k] = std::uint8_t((bytes - 1) >> (8 * k)), b[8 + k] = std::uint8_t(b.size() >> (8 * k));
  const Expanded r = expand(b);
  CHECK(r.status == core::Status::truncated);
  CHECK(r.offset == stream + bytes - 1);
}

TEST_CASE("vertices no triangle uses round-trip, early ones leaving the ring and late ones at the end") {
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    Mesh mesh = random_lattice_mesh(60, 50, 150, 13, 0, 3);
    for (auto [x, y] : {std::pair{0.5, 0.25}, {30.25, 1.5}, {17.0, 20.0}, {58.5, 48.75}, {1.0, 49.0}}) {
      mesh.points.push_back({x, y});
      for (int c = 0; c < 3; ++c) mesh.values.push_back(40.0 * c + x);
    }
    const std::vector<std::uint8_t> v1 = pack_blob(single_mesh(mesh, 60, 50, ColorSpace::rgb), m);
    const std::vector<std::uint8_t> c = compress_blob(v1);
    CHECK(get32(c, 64 + 16) < get32(c, 64));  // the window is shorter than the layer
    round_trip(v1, {{16, 16}});
  }
}

TEST_CASE("streams with lifted corners (pinned slots) round-trip and refuse damage in bounds") {
  // Corners at the image's edges make tall triangles: their bottoms are lifted.
  Mesh mesh = random_lattice_mesh(300, 200, 700, 21, 0, 3);
  const std::vector<std::uint8_t> v1 = pack_blob(single_mesh(mesh, 300, 200, ColorSpace::rgb), core::Method::bilinear);
  const std::vector<std::uint8_t> good = compress_blob(v1);
  CAPTURE(get32(good, 64 + 16), get32(good, 64 + 20));
  REQUIRE(get32(good, 64 + 20) > 0);  // pinned slots
  round_trip(v1, {{32, 32}});
  std::size_t refused = 0;
  for (std::size_t at = 64; at < good.size(); ++at) {
    std::vector<std::uint8_t> b = good;
    b[at] = std::uint8_t(b[at] ^ 0xFF);
    const Expanded r = expand(b);
    if (r.status != core::Status::ok) {
      ++refused;
      CHECK(r.offset <= good.size());
    }
  }
  CHECK(refused > (good.size() - 64) * 9 / 10);
  for (std::size_t n = 0; n < good.size(); n += 7) {
    std::vector<std::uint8_t> b(good.begin(), good.begin() + std::ptrdiff_t(n));
    CHECK(expand(b).status != core::Status::ok);
  }
  // Fewer pinned slots than the stream needs is refused, not overrun.
  std::vector<std::uint8_t> b = good;
  const std::uint32_t pinned = get32(b, 64 + 20) - 1;
  for (int k = 0; k < 4; ++k) b[64 + 20 + k] = std::uint8_t(pinned >> (8 * k));
  CHECK(expand(b).status != core::Status::ok);
}

namespace {

// Every point of a w x h lattice: each square's four corners are cocircular, its diagonal random.
Mesh grid_mesh(int w, int h, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Mesh mesh;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      mesh.points.push_back({double(x), double(y)});
      mesh.values.push_back(double((x * 29 + y * 53) % 256));
    }
  auto at = [&](int x, int y) { return std::uint32_t(y * w + x); };
  for (int y = 0; y + 1 < h; ++y)
    for (int x = 0; x + 1 < w; ++x) {
      const std::uint32_t p = at(x, y), q = at(x + 1, y), r = at(x, y + 1), s = at(x + 1, y + 1);
      Triangle t, u;
      if (rng() & 1u) {
        t.v = {p, q, s};
        u.v = {p, s, r};
      } else {
        t.v = {p, q, r};
        u.v = {q, s, r};
      }
      mesh.triangles.push_back(t);
      mesh.triangles.push_back(u);
    }
  mesh.normalize_winding();
  return mesh;
}

double connectivity_bits_per_vertex(const std::vector<std::uint8_t>& v1) {
  CompressStats stats;
  compress_blob(v1, "test", &stats);
  return stats.connectivity_bits / double(stats.vertices);
}

}  // namespace

TEST_CASE("the connectivity of a Delaunay mesh is mostly implied: open edges and the largest angle") {
  const Triangulation tri = read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.grey.tri");
  // 22.4 bits per vertex when the corners were picked from the last triangles or gap-coded.
  CHECK(connectivity_bits_per_vertex(pack_blob(tri, core::Method::bilinear)) < 10.0);
  // The same points with edges flipped away from Delaunay cost more (escapes), and round-trip.
  const Mesh delaunay = random_lattice_mesh(80, 60, 400, 5);
  const Mesh flipped = random_lattice_mesh(80, 60, 400, 5, 300);
  const std::vector<std::uint8_t> d = pack_blob(single_mesh(delaunay, 80, 60), core::Method::bilinear);
  const std::vector<std::uint8_t> f = pack_blob(single_mesh(flipped, 80, 60), core::Method::bilinear);
  CHECK(connectivity_bits_per_vertex(f) > connectivity_bits_per_vertex(d) + 1.0);
  round_trip(f, {{16, 16}});
}

TEST_CASE("cocircular points (a lattice, each square's diagonal at random) round-trip") {
  for (std::uint32_t seed : {1u, 2u}) {
    const std::vector<std::uint8_t> v1 = pack_blob(single_mesh(grid_mesh(17, 13, seed), 17, 13), core::Method::bilinear);
    round_trip(v1, {{8, 8}});
  }
}

TEST_CASE("triangles no triangulation has (repeated, overlapping, far corners) round-trip through the escapes") {
  std::vector<std::uint8_t> v1 = pack_blob(single_mesh(random_lattice_mesh(40, 30, 90, 17), 40, 30), core::Method::bilinear);
  const std::size_t e = get32(v1, 28);
  const std::uint32_t nv = get32(v1, e), nt = get32(v1, e + 4);
  const std::size_t pos = get32(v1, e + 8), tri = get32(v1, e + 20);
  auto y_of = [&](std::uint32_t v) { return get16(v1, pos + 4 * v + 2); };
  auto x_of = [&](std::uint32_t v) { return get16(v1, pos + 4 * v); };
  std::uint32_t changed = 0;
  for (std::uint32_t t = 1; t < nt; ++t) {
    std::vector<std::uint8_t> trial = v1;
    std::uint8_t* p = &trial[tri + 8 * t];
    if (t % 4 == 1) {
      std::copy_n(&trial[tri + 8 * (t - 1)], 8, p);  // the previous triangle again: same top row
    } else if (t % 4 == 3) {
      // The top corner kept, the other two far below it (the top row is kept).
      std::uint32_t top = get16(trial, tri + 8 * t);
      for (int k = 1; k < 3; ++k)
        if (y_of(get16(trial, tri + 8 * t + 2 * k)) < y_of(top)) top = get16(trial, tri + 8 * t + 2 * k);
      std::uint32_t q = (top * 7 + t) % nv, r = (top * 13 + 5 * t) % nv;
      for (std::uint32_t n = 0; n < nv && y_of(q) <= y_of(top); ++n) q = (q + 1) % nv;
      for (std::uint32_t n = 0; n < nv && (y_of(r) <= y_of(top) || r == q); ++n) r = (r + 3) % nv;
      const std::int64_t area = (std::int64_t(x_of(q)) - x_of(top)) * (std::int64_t(y_of(r)) - y_of(top)) -
                                (std::int64_t(y_of(q)) - y_of(top)) * (std::int64_t(x_of(r)) - x_of(top));
      if (area < 0) std::swap(q, r);
      const std::uint32_t v[3] = {top, q, r};
      for (int k = 0; k < 3; ++k) p[2 * k] = std::uint8_t(v[k]), p[2 * k + 1] = std::uint8_t(v[k] >> 8);
    } else {
      continue;
    }
    seal_blob(trial.data(), trial.size());
    core::Blob blob;
    if (core::open_blob(trial.data(), trial.size(), &blob) == core::Status::ok) {
      v1 = trial;
      ++changed;
    }
  }
  REQUIRE(changed > nt / 3);
  round_trip(v1, {{8, 8}, {0, 0}});
}
