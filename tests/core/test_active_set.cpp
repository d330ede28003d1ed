// SPDX-License-Identifier: MIT
// The longest window of a layer's active set (firmware_core/src/active_set.h), what
// workspace_size reports and render checks before a frame's first tile: max_window(layer, plan)
// must equal a model that follows every band's window triangle by triangle, and
// max_window(layer, plan, c) (render's check) must exceed c exactly when the window does, for
// every capacity up to the window and a little beyond; for meshes of several densities, bands
// from one row to the whole frame, output sizes that map the domain (not the identity) and
// viewports that start inside it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "active_set.h"
#include "core_bridge/pack.h"
#include "io/tri_file.h"
#include "scenes/bench_scenes.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::core::detail;

namespace {

// The window by its definition: per band, the cursor past every triangle starting at or above
// the band's last row, the base past every triangle not live in the band (ended above, or no rows).
std::uint32_t model_window(const core::BlobLayer& layer, const FramePlan& r) {
  std::uint32_t best = 0, base = 0, cursor = 0;
  for (std::int32_t by = r.view.y0; by < r.view.y1; by += r.tile_h) {
    const std::int32_t y1 = std::min(by + r.tile_h, r.view.y1) - 1;
    std::int32_t top, bottom;
    for (; cursor < layer.triangle_count; ++cursor) {
      row_extent(layer, cursor, r.map, &top, &bottom);
      if (top > y1) break;
    }
    for (; base < cursor; ++base) {
      row_extent(layer, base, r.map, &top, &bottom);
      if (bottom >= by && top <= bottom) break;
    }
    best = std::max(best, cursor - base);
  }
  return best;
}

int check_capacities(const core::Blob& blob, const core::RenderParams& p) {
  FramePlan r;
  REQUIRE(plan_frame(blob, p, &r) == core::Status::ok);
  int checked = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    const core::BlobLayer& layer = blob.layers[l];
    const std::uint32_t window = model_window(layer, r);
    INFO("layer " << l << " of " << layer.triangle_count << " triangles, window " << window << ", bands of "
                  << r.tile_h << " rows, output " << p.output_width << "x" << p.output_height);
    CHECK(max_window(layer, r) == window);
    for (std::uint32_t c = 0; c <= window + 40; c += (c + 40 < window ? 1 + window / 97 : 1)) {
      const std::uint32_t m = max_window(layer, r, c);
      if ((m > c) != (window > c) || m < c || (window > c && m != window)) FAIL_CHECK("capacity " << c << ": " << m);
      ++checked;
    }
  }
  return checked;
}

}  // namespace

TEST_CASE("the measured window and render's check agree with the window's definition") {
  const Triangulation layered = read_tri_file(TRISTREAM_SOURCE_DIR "/data/demo/kodim23.ycbcr-layers.tri");
  const Triangulation sparse = scenes::bench_scene(500, 3), dense = scenes::bench_scene(40000, 4);
  for (const Triangulation* t : {&sparse, &dense, &layered}) {
    const auto bytes = pack_blob(*t, core::Method::bilinear);
    core::Blob blob;
    REQUIRE(core::open_blob(bytes.data(), bytes.size(), &blob) == core::Status::ok);
    int checked = 0;
    for (int rows : {1, 3, 16, 32, 0}) {
      for (auto [w, h] : {std::pair{0, 0}, {320, 240}, {97, 1001}, {40, 30}}) {
        core::RenderParams p;
        p.output_width = std::uint16_t(w);
        p.output_height = std::uint16_t(h);
        p.tile_height = std::uint16_t(rows);
        checked += check_capacities(blob, p);
        // A viewport from inside the frame: the first band starts below the first triangles.
        const int ow = w ? w : blob.width, oh = h ? h : blob.height;
        p.viewport = core::Rect{ow / 5, oh / 3, ow - ow / 7, oh - oh / 4};
        checked += check_capacities(blob, p);
      }
    }
    CHECK(checked > 1000);
  }
}
