// SPDX-License-Identifier: MIT
// Speed of the fixed-point core on the host: 512 x 512 RGB frames assembled from the tiles the
// sink receives. Prints ms per frame (real and CPU time) and Mpixel/s (counter "Mpix/s"), then a summary
// table from CPU time: bilinear and zienkiewicz side by side with their ratio, and the targets of issue 3.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"
#include "scenes/bench_scenes.h"

using namespace tristream;

namespace {

const std::vector<std::uint8_t>& scene_blob(int triangles, core::Method method) {
  static std::map<std::pair<int, int>, std::vector<std::uint8_t>> cache;
  auto& blob = cache[{triangles, int(method)}];
  if (blob.empty()) blob = pack_blob(scenes::bench_scene(triangles), method);
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
  state.counters["Mpix/s"] =
      benchmark::Counter(pixels * 1e-6 * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ram_bytes"] = double(renderer.tile_buffer_bytes() + renderer.workspace_bytes());
  state.SetLabel(std::string(to_string(method)) +
                 (state.range(2) ? " tiles " + std::to_string(state.range(2)) : " full") +
                 (o.format == core::PixelFormat::rgb888 ? " rgb888" : " rgb565le"));
}

void matrix(benchmark::internal::Benchmark* b) {
  for (int triangles : {2000, 4000, 20000, 40000})
    for (int method : {0, 1})
      for (int tile : {32, 0})
        for (int format : {int(core::PixelFormat::rgb888), int(core::PixelFormat::rgb565_le)})
          b->Args({triangles, method, tile, format});
}

// The console output as usual, and every run's ms per frame kept for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  // (triangles, tile, format) -> ms per frame of method 0 and 1 (0 when not run).
  std::map<std::tuple<int, int, int>, std::pair<double, double>> ms;

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      std::istringstream args(run.run_name.args);
      int triangles = 0, method = 0, tile = 0, format = 0;
      char slash = 0;
      args >> triangles >> slash >> method >> slash >> tile >> slash >> format;
      auto& entry = ms[{triangles, tile, format}];
      (method == 0 ? entry.first : entry.second) = run.GetAdjustedCPUTime();
    }
  }
};

void print_summary(const SummaryReporter& r) {
  constexpr double pixels = 512.0 * 512.0;
  auto mpix = [&](double ms) { return ms > 0 ? pixels / (ms * 1e3) : 0.0; };
  std::printf(
      "\nSummary, 512x512, CPU ms per frame (less disturbed than real time on a shared machine) and Mpixel/s:\n");
  std::printf("%9s %5s %-9s | %9s %8s | %9s %8s | %6s\n", "triangles", "tile", "format", "bilinear", "Mpix/s",
              "zienkiew.", "Mpix/s", "z / b");
  for (const auto& [key, t] : r.ms) {
    const auto [triangles, tile, format] = key;
    const std::string tiling = tile ? std::to_string(tile) : "full";
    const char* fmt = format == int(core::PixelFormat::rgb888) ? "rgb888" : "rgb565le";
    std::printf("%9d %5s %-9s | %9.3f %8.1f | %9.3f %8.1f | %6.2f\n", triangles, tiling.c_str(), fmt, t.first,
                mpix(t.first), t.second, mpix(t.second), t.first > 0 ? t.second / t.first : 0.0);
  }
  std::printf("\nTargets of issue 3 (one core):\n");
  for (const auto& [key, t] : r.ms) {
    const auto [triangles, tile, format] = key;
    const char* fmt = format == int(core::PixelFormat::rgb888) ? "rgb888" : "rgb565le";
    if (triangles == 4000 && tile == 32 && t.first > 0)
      std::printf("  bilinear, 32x32 tiles, 4,000 triangles, %s: %.1f Mpixel/s (target >= 500: %s)\n", fmt,
                  mpix(t.first), mpix(t.first) >= 500 ? "met" : "NOT met");
    if (triangles == 40000 && t.first > 0)
      std::printf("  bilinear, 40,000 triangles, %s, %s: %.2f ms (target <= 2.5 ms: %s)\n",
                  tile ? "32x32 tiles" : "full frame", fmt, t.first, t.first <= 2.5 ? "met" : "NOT met");
    if (t.first > 0 && t.second > 0 && t.second > 2 * t.first)
      std::printf("  zienkiewicz over twice bilinear: %d triangles, %s, %s: %.2fx\n", triangles,
                  tile ? "32x32 tiles" : "full frame", fmt, t.second / t.first);
  }
}

}  // namespace

BENCHMARK(BM_core)->Apply(matrix)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  print_summary(reporter);
  return 0;
}
