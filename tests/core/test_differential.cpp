// SPDX-License-Identifier: MIT
// Differential tests: the fixed-point core against the double-precision reference renderer.
// Tolerances (per pixel and channel): bilinear 1, zienkiewicz 2 (issue 3).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>

#include "core_support.h"
#include "io/tri_file.h"
#include "reference/render.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

struct Diff {
  int max = 0;
  std::size_t over = 0;
};

Diff compare(const Image& a, const Image& b, int tolerance) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.channels == b.channels);
  Diff d;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const int e = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
    d.max = std::max(d.max, e);
    d.over += e > tolerance;
  }
  return d;
}

int tolerance_of(std::string_view method) { return method == "bilinear" ? 1 : 2; }

void check_against_reference(const Triangulation& tri, std::string_view method, const std::string& what, int out_w = 0,
                             int out_h = 0) {
  RenderOptions ro;
  ro.width = out_w;
  ro.height = out_h;
  const Image ref = render_reference(tri, *find_reference_method(method), ro);
  CoreOptions co;
  co.width = out_w;
  co.height = out_h;
  co.format = tri.space == ColorSpace::grey ? core::PixelFormat::l8 : core::PixelFormat::rgb888;
  const Image got = render_core(tri, method, co);
  const Diff d = compare(got, ref, tolerance_of(method));
  INFO(what << " " << method << ": max diff " << d.max << ", pixels over tolerance " << d.over);
  CHECK(d.max <= tolerance_of(method));
}

}  // namespace

TEST_CASE("random lattice triangulations, grey, rgb, ycbcr and layered") {
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    for (std::string_view method : {"bilinear", "zienkiewicz"}) {
      const std::string tag = "seed " + std::to_string(seed);
      check_against_reference(single_mesh(random_lattice_mesh(64, 48, 150, seed, 100), 64, 48), method, "grey " + tag);
      check_against_reference(single_mesh(random_lattice_mesh(64, 48, 150, seed, 0, 3), 64, 48, ColorSpace::rgb),
                              method, "rgb " + tag);
      check_against_reference(single_mesh(random_lattice_mesh(64, 48, 150, seed, 0, 3), 64, 48, ColorSpace::ycbcr),
                              method, "ycbcr " + tag);
      Triangulation layered;
      layered.width = 64;
      layered.height = 48;
      layered.space = seed % 2 ? ColorSpace::rgb : ColorSpace::ycbcr;
      for (int c = 0; c < 3; ++c) {
        layered.layers.push_back(random_lattice_mesh(64, 48, 60 + 40 * c, seed * 10 + c, 20));
        layered.layers.back().name = "channel" + std::to_string(c);
      }
      check_against_reference(layered, method, "layered " + tag);
    }
  }
}

TEST_CASE("sub-pixel vertices and sparse meshes (large triangles, steep gradients)") {
  for (std::uint32_t seed = 1; seed <= 4; ++seed)
    for (std::string_view method : {"bilinear", "zienkiewicz"}) {
      check_against_reference(single_mesh(random_subpixel_mesh(90, 70, 200, seed, true, 3), 90, 70, ColorSpace::rgb),
                              method, "sub-pixel seed " + std::to_string(seed));
      check_against_reference(single_mesh(random_lattice_mesh(300, 200, 6, seed), 300, 200), method,
                              "sparse seed " + std::to_string(seed));
    }
}

TEST_CASE("saturated values: every vertex at 0 or 255 (rounding must never step out of [0, 255])") {
  // Neighbouring vertices at the two ends of the range give the steepest gradients the values
  // allow; the core renders these pixels without clamping (bilinear_shader.h), so a value stepped
  // past 255 or below 0 would wrap and differ from the reference by up to 255.
  auto saturate = [](Mesh m) {
    for (double& v : m.values) v = v >= 128 ? 255.0 : 0.0;
    return m;
  };
  for (std::uint32_t seed = 1; seed <= 4; ++seed)
    for (std::string_view method : {"bilinear", "zienkiewicz"}) {
      const std::string tag = "seed " + std::to_string(seed);
      check_against_reference(single_mesh(saturate(random_subpixel_mesh(90, 70, 300, seed, true, 3)), 90, 70,
                                          ColorSpace::rgb),
                              method, "saturated sub-pixel rgb " + tag);
      check_against_reference(single_mesh(saturate(random_lattice_mesh(64, 48, 150, seed, 100)), 64, 48), method,
                              "saturated grey " + tag);
      check_against_reference(single_mesh(saturate(random_lattice_mesh(33, 25, 60, seed, 0, 3)), 33, 25,
                                          ColorSpace::rgb),
                              method, "saturated 2x " + tag, 65, 49);
    }
}

TEST_CASE("up-scaled output (corner to corner)") {
  // Integer scale factors keep the mapped vertices on the 1/16 grid, so the reference
  // tolerance applies unchanged.
  for (std::uint32_t seed = 1; seed <= 3; ++seed)
    for (std::string_view method : {"bilinear", "zienkiewicz"})
      check_against_reference(single_mesh(random_lattice_mesh(33, 25, 60, seed, 0, 3), 33, 25, ColorSpace::rgb), method,
                              "2x seed " + std::to_string(seed), 65, 49);
}

TEST_CASE("the Kodak demo triangulations in data/demo") {
  const std::filesystem::path dir = std::filesystem::path(TRISTREAM_SOURCE_DIR) / "data" / "demo";
  for (const char* name : {"kodim23.grey.tri", "kodim23.rgb.tri", "kodim23.ycbcr-layers.tri"}) {
    const Triangulation tri = read_tri_file((dir / name).string());
    for (std::string_view method : {"bilinear", "zienkiewicz"}) check_against_reference(tri, method, name);
  }
}
