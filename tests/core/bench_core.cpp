// Speed of the fixed-point core on the host: 512 x 512 RGB frames assembled from the tiles the
// sink receives. Prints ms per frame (real time) and Mpixel/s (counter "pixels", per second).
#include <benchmark/benchmark.h>

#include <map>

#include "bench_support.h"
#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"

using namespace tristream;

namespace {

const std::vector<std::uint8_t>& scene_blob(int triangles, core::Method method) {
  static std::map<std::pair<int, int>, std::vector<std::uint8_t>> cache;
  auto& blob = cache[{triangles, int(method)}];
  if (blob.empty()) blob = pack_blob(testing::bench_scene(triangles), method);
  return blob;
}

// Arguments: triangles, method (0 bilinear, 1 zienkiewicz), tile side (0 = full frame), format.
void BM_core(benchmark::State& state) {
  const int triangles = int(state.range(0));
  const auto method = core::Method(state.range(1));
  CoreOptions o;
  o.tile_width = o.tile_height = int(state.range(2));
  o.format = core::PixelFormat(state.range(3));
  CoreRenderer renderer(scene_blob(triangles, method), o);
  CoreFrame frame;
  renderer.render(frame);
  for (auto _ : state) {
    renderer.render(frame);
    benchmark::DoNotOptimize(frame.bytes.data());
  }
  const double pixels = double(frame.width) * frame.height;
  state.counters["Mpix/s"] = benchmark::Counter(pixels * 1e-6 * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ram_bytes"] = double(renderer.tile_buffer_bytes() + renderer.workspace_bytes());
  state.SetLabel(std::string(to_string(method)) + (state.range(2) ? " tiles " + std::to_string(state.range(2)) : " full") +
                 (o.format == core::PixelFormat::rgb888 ? " rgb888" : " rgb565le"));
}

void matrix(benchmark::internal::Benchmark* b) {
  for (int triangles : {2000, 4000, 20000, 40000})
    for (int method : {0, 1})
      for (int tile : {32, 0})
        for (int format : {int(core::PixelFormat::rgb888), int(core::PixelFormat::rgb565_le)})
          b->Args({triangles, method, tile, format});
}

}  // namespace

BENCHMARK(BM_core)->Apply(matrix)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
