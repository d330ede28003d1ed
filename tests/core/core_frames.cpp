// SPDX-License-Identifier: MIT
// core_frames <triangles> <bilinear|zienkiewicz> <tile, 0 = full frame> <rgb888|rgb565le> <frames>:
// renders the 512 x 512 benchmark scene (scenes/bench_scenes.h) repeatedly, for instruction counts
// under callgrind (tests/core/callgrind_core.sh counts only inside tristream::core::render).
// Also prints the fastest and the median frame's wall time (the fastest is the least disturbed
// by other processes: a quick check on a busy machine; bench_core is the benchmark). With
// TS_FRAME_TIMES set in the environment it first prints every frame's time in order (on this
// virtual machine they come in fast and slow phases, about 1.5x apart, whatever else runs).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "core_bridge/render_core.h"
#include "scenes/bench_scenes.h"

using namespace tristream;

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: core_frames <triangles> <method> <tile> <format> <frames>\n");
    return 64;
  }
  const auto blob = pack_blob(scenes::bench_scene(std::atoi(argv[1])), parse_core_method(argv[2]));
  CoreOptions o;
  o.tile_width = o.tile_height = std::atoi(argv[3]);
  o.format = parse_pixel_format(argv[4]);
  CoreRenderer renderer(blob, o);
  CoreFrame frame;
  const int frames = std::atoi(argv[5]);
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(frame);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  if (std::getenv("TS_FRAME_TIMES"))
    for (double m : ms) std::printf("%.3f\n", m);
  std::sort(ms.begin(), ms.end());
  std::printf("%d frames of %dx%d, RAM %zu bytes, ms per frame: fastest %.3f, median %.3f\n", frames, frame.width,
              frame.height, renderer.tile_buffer_bytes() + renderer.workspace_bytes(), ms.front(), ms[ms.size() / 2]);
  return 0;
}
