// SPDX-License-Identifier: MIT
// Speed of the metrics on a 768x512 RGB pair (the Kodak size). Prints figures; not a test.
//   build*/bin/bench_metrics
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "metrics/metrics.h"

using namespace tristream;

namespace {

// A smooth pattern plus noise, and a noisier copy: content does not change the cost.
std::pair<Image, Image> kodak_sized_pair() {
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 8.0);
  Image a(768, 512, 3), b(768, 512, 3);
  for (int y = 0; y < 512; ++y)
    for (int x = 0; x < 768; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = 128 + 60 * std::sin(0.03 * x + c) * std::cos(0.05 * y) + noise(rng);
        a.at(x, y, c) = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
        b.at(x, y, c) = static_cast<std::uint8_t>(std::clamp(v + noise(rng), 0.0, 255.0));
      }
  return {a, b};
}

void BM_ssim_gaussian11_768x512_rgb(benchmark::State& state) {
  const auto [a, b] = kodak_sized_pair();
  for (auto _ : state) benchmark::DoNotOptimize(ssim(a, b));
}
BENCHMARK(BM_ssim_gaussian11_768x512_rgb)->Unit(benchmark::kMillisecond);

void BM_ssim_uniform8_768x512_rgb(benchmark::State& state) {
  const auto [a, b] = kodak_sized_pair();
  for (auto _ : state) benchmark::DoNotOptimize(ssim(a, b, {.window = SsimWindow::uniform8}));
}
BENCHMARK(BM_ssim_uniform8_768x512_rgb)->Unit(benchmark::kMillisecond);

void BM_mse_768x512_rgb(benchmark::State& state) {
  const auto [a, b] = kodak_sized_pair();
  for (auto _ : state) benchmark::DoNotOptimize(mse(a, b));
}
BENCHMARK(BM_mse_768x512_rgb)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
