// SPDX-License-Identifier: MIT
// Reading a blob back into a mesh (core_bridge/unpack.h): pack -> unpack -> pack gives the same
// bytes for every kind of blob; the mesh read back is the packed one at the blob's precision; a blob
// open_blob refuses, or one whose mesh the reference could not draw, is a DataError with its byte; a
// compressed blob reads back as the v1 blob it was made from, triangle by triangle.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "../support/blob_seal.h"
#include "common/errors.h"
#include "core_bridge/compress.h"
#include "core_bridge/unpack.h"
#include "core_support.h"
#include "io/tri_file.h"
#include "tristream/compressed_blob.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

std::vector<std::uint8_t> repack(const std::vector<std::uint8_t>& blob) {
  const UnpackedBlob u = unpack_blob(blob, "test");
  return pack_blob(u.tri, u.method, "test", u.gradients.empty() ? nullptr : &u.gradients);
}

Triangulation layered(ColorSpace space, std::uint32_t seed) {
  Triangulation t;
  t.width = 48, t.height = 36, t.space = space;
  for (int c = 0; c < 3; ++c) t.layers.push_back(random_subpixel_mesh(48, 36, 30 + 10 * c, seed + c, true, 1));
  return t;
}

std::string message_of(const std::vector<std::uint8_t>& blob) {
  try {
    unpack_blob(blob, "b.bin");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a compressed blob reads back as its v1 blob: the same triangles, corners and gradients") {
  const std::vector<Triangulation> cases = {
      single_mesh(random_subpixel_mesh(64, 40, 120, 7, true, 1), 64, 40, ColorSpace::grey),
      layered(ColorSpace::ycbcr, 21),
      read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.rgb.tri"),
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
      INFO("case " << k << ", " << to_string(m));
      const std::vector<std::uint8_t> v1 = pack_blob(cases[k], m);
      const std::vector<std::uint8_t> tstc = compress_blob(v1);
      REQUIRE(core::is_compressed_blob(tstc.data(), tstc.size()));
      const std::vector<std::uint8_t> expanded = v1_blob_bytes(tstc, "c.bin");
      CHECK(expanded.size() == v1.size());
      CHECK(v1_blob_bytes(v1, "v.bin") == v1);
      CHECK(repack(expanded) == expanded);
      const UnpackedBlob a = unpack_blob(v1, "v.bin"), b = unpack_blob(tstc, "c.bin");
      CHECK(b.method == a.method);
      REQUIRE(b.tri.layers.size() == a.tri.layers.size());
      CHECK(b.tri.space == a.tri.space);
      for (std::size_t l = 0; l < a.tri.layers.size(); ++l) {
        const Mesh &p = a.tri.layers[l], &q = b.tri.layers[l];
        CHECK(q.name == p.name);
        REQUIRE(q.vertex_count() == p.vertex_count());
        REQUIRE(q.triangles.size() == p.triangles.size());
        // Triangles keep the v1 order and first corner; only the vertex numbering changes.
        for (std::size_t t = 0; t < p.triangles.size(); ++t)
          for (int c = 0; c < 3; ++c) {
            const std::uint32_t i = p.triangles[t].v[c], j = q.triangles[t].v[c];
            CHECK(q.points[j].x == p.points[i].x);
            CHECK(q.points[j].y == p.points[i].y);
            for (std::size_t n = 0; n < std::size_t(p.value_count); ++n) {
              CHECK(q.value(j, int(n)) == p.value(i, int(n)));
              if (m == core::Method::zienkiewicz)
                for (int g = 0; g < 2; ++g)
                  CHECK(b.gradients[l][2 * (j * p.value_count + n) + g] ==
                        a.gradients[l][2 * (i * p.value_count + n) + g]);
            }
          }
      }
    }
}

TEST_CASE("a damaged compressed blob is a DataError with the byte offset the decoder reports") {
  const std::vector<std::uint8_t> tstc =
      compress_blob(pack_blob(single_mesh(random_subpixel_mesh(64, 40, 120, 7, true, 1), 64, 40, ColorSpace::grey),
                              core::Method::bilinear));
  std::vector<std::uint8_t> version = tstc;
  version[4] = 9;
  CHECK(message_of(version) == "b.bin: byte 4: unsupported blob version");
  // Version 2 had no reach limit for fresh third corners (compressed_blob.h): say what to do.
  version[4] = 2;
  CHECK(message_of(version) ==
        "b.bin: byte 4: version 2 compressed blob, whose fresh third corners have no reach limit: pack it again "
        "with tripack --compress (this core reads version 3)");
  CHECK(message_of({tstc.begin(), tstc.begin() + 60}) == "b.bin: byte 60: blob truncated");
  // Every byte of the stream flipped: refused with the offset where the decoder stood when a
  // check failed (never before the flipped byte, which it has to read first, never past the end),
  // or read back (a flip the stream's checks cannot see, still a drawable mesh), never out of bounds.
  const std::size_t stream = core::compressed_header_size + core::compressed_layer_entry_size;
  int refused = 0;
  for (std::size_t at = stream; at < tstc.size(); ++at) {
    std::vector<std::uint8_t> bad = tstc;
    bad[at] ^= 0xFF;
    const std::string e = message_of(bad);
    if (e.empty()) continue;
    ++refused;
    INFO("flipped byte " << at << ": " << e);
    REQUIRE(e.rfind("b.bin: byte ", 0) == 0);
    const std::size_t offset = std::stoul(e.substr(12));
    CHECK(offset >= at);
    CHECK(offset <= tstc.size());
  }
  CHECK(refused > 0);
}

TEST_CASE("pack -> unpack -> pack gives the same bytes") {
  std::vector<Triangulation> cases = {
      single_mesh(random_lattice_mesh(40, 30, 60, 5, 10, 3), 40, 30, ColorSpace::rgb),
      single_mesh(random_subpixel_mesh(64, 40, 120, 7, true, 1), 64, 40, ColorSpace::grey),
      single_mesh(random_subpixel_mesh(50, 50, 90, 9, false, 3), 50, 50, ColorSpace::ycbcr),  // hull domain
      layered(ColorSpace::rgb, 11),
      layered(ColorSpace::ycbcr, 21),
      read_tri_file(std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.rgb.tri"),
  };
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
      INFO("case " << k << ", " << to_string(m));
      const std::vector<std::uint8_t> blob = pack_blob(cases[k], m);
      CHECK(repack(blob) == blob);
    }
}

TEST_CASE("the mesh read back is the packed one at the blob's precision") {
  const Triangulation tri = single_mesh(random_subpixel_mesh(64, 40, 120, 3, true, 3), 64, 40, ColorSpace::rgb);
  const UnpackedBlob u = unpack_blob(pack_blob(tri, core::Method::zienkiewicz), "test");
  REQUIRE(u.method == core::Method::zienkiewicz);
  REQUIRE(u.tri.width == 64);
  REQUIRE(u.tri.height == 40);
  REQUIRE(u.tri.space == ColorSpace::rgb);
  REQUIRE(u.tri.layers.size() == 1);
  const Mesh &a = tri.layers[0], &b = u.tri.layers[0];
  REQUIRE(b.vertex_count() == a.vertex_count());
  REQUIRE(b.triangles.size() == a.triangles.size());
  REQUIRE(u.gradients.size() == 1);
  CHECK(u.gradients[0].size() == 2 * 3 * a.vertex_count());
  for (std::size_t v = 0; v < a.vertex_count(); ++v) {
    CHECK(b.points[v].x == a.points[v].x);  // the mesh is on the 1/16-pixel grid
    CHECK(b.points[v].y == a.points[v].y);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(b.value(v, c) - a.value(v, c)) <= 0.5 / 256);
  }
  // Every input triangle is one of the blob's (same vertex set), each positively oriented.
  std::set<std::array<std::uint32_t, 3>> in, out;
  for (const Triangle& t : a.triangles) {
    auto v = t.v;
    std::sort(v.begin(), v.end());
    in.insert(v);
  }
  for (std::size_t t = 0; t < b.triangles.size(); ++t) {
    CHECK(b.doubled_area(t) > 0);
    auto v = b.triangles[t].v;
    std::sort(v.begin(), v.end());
    out.insert(v);
  }
  CHECK(in == out);
  // Layered blobs come back with the .tri layer names.
  const UnpackedBlob l = unpack_blob(pack_blob(layered(ColorSpace::ycbcr, 4), core::Method::bilinear), "test");
  REQUIRE(l.tri.layers.size() == 3);
  CHECK(l.tri.layers[0].name == "y");
  CHECK(l.tri.layers[2].name == "cr");
  CHECK(l.gradients.empty());
}

TEST_CASE("a blob the core or the reference cannot take is a DataError with its byte offset") {
  const Triangulation tri = single_mesh(random_lattice_mesh(40, 30, 60, 5, 0, 1), 40, 30, ColorSpace::grey);
  const std::vector<std::uint8_t> good = pack_blob(tri, core::Method::bilinear);
  {
    auto b = good;
    b[4] = 9;  // version
    CHECK(message_of(b) == "b.bin: byte 4: unsupported blob version");
  }
  {
    auto b = good;
    b.resize(b.size() - 1);
    CHECK(message_of(b) == "b.bin: byte 8: blob truncated");
  }
  const std::uint32_t table = good[28] | good[29] << 8;
  const std::uint32_t positions = good[table + 8] | good[table + 9] << 8;
  {
    // Vertex 1 moved onto vertex 0: the core may accept it (triangles keep positive area only
    // if they do not use both), the reference must not.
    auto b = good;
    for (int k = 0; k < 4; ++k) b[positions + 4 + k] = b[positions + k];
    REQUIRE(seal_blob(b.data(), b.size()));  // sealed: the checksum would refuse it first
    const std::string m = message_of(b);
    CHECK((m.find("b.bin: byte ") == 0));
  }
  {
    // Two copies of one triangle: open_blob accepts it (sorted, positive areas), the mesh check does not.
    auto b = good;
    const std::uint32_t tris = b[table + 20] | b[table + 21] << 8;
    for (int k = 0; k < 8; ++k) b[tris + 8 + k] = b[tris + k];
    REQUIRE(seal_blob(b.data(), b.size()));
    core::Blob opened;
    REQUIRE(core::open_blob(b.data(), b.size(), &opened) == core::Status::ok);
    CHECK(message_of(b) == "b.bin: byte " + std::to_string(tris + 8) +
                               ": expected triangles whose interiors do not overlap, found triangle 1 overlapping "
                               "triangle 0");
  }
}

TEST_CASE("blobs are told from .tri text by their bytes") {
  const std::vector<std::uint8_t> blob =
      pack_blob(single_mesh(random_lattice_mesh(20, 20, 10, 1, 0, 1), 20, 20), core::Method::bilinear);
  CHECK(is_blob(blob));
  CHECK(is_blob(std::vector<std::uint8_t>(blob.begin(), blob.begin() + 4)));  // truncated: still a blob
  const std::string compressed = "TSTC and more";  // a variant this core may not open: refused as a blob
  CHECK(is_blob(std::span(reinterpret_cast<const std::uint8_t*>(compressed.data()), compressed.size())));
  const std::string text = "tri 1\nsize 2 2\nchannels grey\nvertices 3\n0 0 1\n1 0 2\n0 1 3\n";
  CHECK_FALSE(is_blob(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())));
  CHECK_FALSE(is_blob({}));
}

// The damage sealed with a new checksum, to reach the reader behind it (unsealed, the checksum
// refuses every byte: test_blob_checksum.cpp).
TEST_CASE("every damaged byte is read back or refused with a DataError, never out of bounds") {
  const std::vector<std::uint8_t> good =
      pack_blob(single_mesh(random_lattice_mesh(30, 20, 25, 8, 0, 3), 30, 20, ColorSpace::rgb), core::Method::zienkiewicz);
  int refused = 0, read = 0;
  for (std::size_t at = 0; at < good.size(); ++at)
    for (std::uint8_t x : {std::uint8_t(0x01), std::uint8_t(0x80), std::uint8_t(0xFF)}) {
      std::vector<std::uint8_t> b(good);  // exactly sized: ASan sees overreads
      b[at] ^= x;
      seal_blob(b.data(), b.size());
      try {
        const UnpackedBlob u = unpack_blob(b, "b.bin");
        CHECK(u.tri.layers.size() == 1);
        ++read;
      } catch (const DataError& e) {
        CHECK(std::string(e.what()).rfind("b.bin: byte ", 0) == 0);
        ++refused;
      }
    }
  CHECK(refused > 0);
  CHECK(read > 0);  // values, gradients and padding may change without making the blob invalid
}

TEST_CASE("vertices of different triangles that round to one grid point are refused when packed") {
  // An hourglass: two triangles whose tips are 0.01 pixel apart. No triangle collapses, but both
  // tips round to (1, 1): the core would draw that point from two vertices, and unpack_blob refuses
  // the blob, so pack_blob refuses the mesh.
  Mesh m;
  m.points = {{0, 0}, {2, 0}, {1, 1}, {1, 1.01}, {2, 2}, {0, 2}};
  m.values = {10, 20, 30, 200, 40, 50};
  m.triangles = {Triangle{{0, 1, 2}}, Triangle{{3, 4, 5}}};
  for (core::Method method : {core::Method::bilinear, core::Method::zienkiewicz})
    CHECK_THROWS_WITH(pack_blob(single_mesh(m, 3, 3), method, "h"),
                      Catch::StartsWith("h: vertices 2 (1, 1) and 3 (1, 1.01) both round to (1, 1) on the core's "
                                        "1/16-pixel grid"));
  // 1/16 pixel apart in y: distinct on the grid, packed and read back.
  m.points[3].y = 1.0625;
  CHECK_NOTHROW(unpack_blob(pack_blob(single_mesh(m, 3, 3), core::Method::bilinear), "h"));
  // A vertex no triangle uses is never drawn: it may round onto a used one.
  m.points.push_back({1.01, 0.99});
  m.values.push_back(99);
  CHECK_NOTHROW(pack_blob(single_mesh(m, 3, 3), core::Method::bilinear));
}
