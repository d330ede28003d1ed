// SPDX-License-Identifier: MIT
// Zienkiewicz rows long enough for forward differencing and its restarts every 32 pixels (large
// triangles of sparse meshes): the output must be bit-identical for every tiling, whatever tile
// edge cuts a row inside a restart chunk.
#include <catch2/catch.hpp>

#include <vector>

#include "core_support.h"

using namespace tristream;
using namespace tristream::testing;

TEST_CASE("zienkiewicz: long forward-differenced rows are identical for every tiling") {
  std::vector<Tiling> tilings = all_tilings();
  for (Tiling t : {Tiling{63, 5}, Tiling{65, 3}, Tiling{100, 0}, Tiling{7, 0}, Tiling{129, 17}, Tiling{31, 0}})
    tilings.push_back(t);
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    const Triangulation rgb = single_mesh(random_lattice_mesh(300, 200, 6, seed, 0, 3), 300, 200, ColorSpace::rgb);
    const Triangulation ycbcr =
        single_mesh(random_subpixel_mesh(260, 90, 12, seed, true, 3), 260, 90, ColorSpace::ycbcr);
    const Triangulation grey = single_mesh(random_lattice_mesh(300, 200, 10, seed), 300, 200);
    for (const Triangulation* tri : {&rgb, &ycbcr, &grey}) {
      const auto blob = pack_blob(*tri, core::Method::zienkiewicz);
      for (core::PixelFormat f : {core::PixelFormat::rgb888, core::PixelFormat::xrgb8888, core::PixelFormat::l8}) {
        for (int out : {0, 1}) {
          CoreOptions o;
          o.format = f;
          if (out) o.width = tri->width * 2 - 1, o.height = tri->height * 2 - 1;
          const CoreFrame full = core_frame(blob, o, {0, 0});
          for (const Tiling& t : tilings) {
            INFO("seed " << seed << " space " << int(tri->space) << " format " << int(f) << " resized " << out
                         << " tiles " << t.w << "x" << t.h);
            CHECK(bytes_differing(core_frame(blob, o, t).bytes, full.bytes) == 0);
          }
        }
      }
    }
  }
}
