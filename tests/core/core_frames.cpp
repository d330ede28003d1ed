// core_frames <triangles> <bilinear|zienkiewicz> <tile, 0 = full frame> <rgb888|rgb565le> <frames>:
// renders the 512 x 512 benchmark scene (bench_support.h) repeatedly, for instruction counts
// under callgrind (tests/core/callgrind_core.sh counts only inside tristream::core::render).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_support.h"
#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"

using namespace tristream;

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: core_frames <triangles> <method> <tile> <format> <frames>\n");
    return 64;
  }
  const auto blob = pack_blob(testing::bench_scene(std::atoi(argv[1])), parse_core_method(argv[2]));
  CoreOptions o;
  o.tile_width = o.tile_height = std::atoi(argv[3]);
  o.format = parse_pixel_format(argv[4]);
  CoreRenderer renderer(blob, o);
  CoreFrame frame;
  const int frames = std::atoi(argv[5]);
  for (int i = 0; i < frames; ++i) renderer.render(frame);
  std::printf("%d frames of %dx%d, RAM %zu bytes\n", frames, frame.width, frame.height,
              renderer.tile_buffer_bytes() + renderer.workspace_bytes());
  return 0;
}
