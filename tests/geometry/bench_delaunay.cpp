// SPDX-License-Identifier: MIT
// Delaunay construction speed: `bench_delaunay` prints the time per triangulation.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "geometry/delaunay.h"

namespace {

void random_points(benchmark::State& state) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<tristream::Point> pts(std::size_t(state.range(0)));
  for (auto& p : pts) p = {u(rng), u(rng)};
  for (auto _ : state) benchmark::DoNotOptimize(tristream::delaunay_triangulation(pts));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(random_points)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void pixel_lattice(benchmark::State& state) {  // fully cocircular: every incircle test is exact
  const int side = int(state.range(0));
  std::vector<tristream::Point> pts;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) pts.push_back({double(x), double(y)});
  for (auto _ : state) benchmark::DoNotOptimize(tristream::delaunay_triangulation(pts));
  state.SetItemsProcessed(state.iterations() * side * side);
}
BENCHMARK(pixel_lattice)->Arg(100)->Arg(316)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
