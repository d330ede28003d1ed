// SPDX-License-Identifier: MIT
// Speed of the patch renderers (bezier, coons: default exact variant) and clough-tocher at
// 512x512 from about 13,000 vertices (issue 5 target for bezier and coons: under 100 ms each
// on one core), beside bilinear, which the patch methods run first as their pre-fill and
// domain. Prints figures; not a test.
//   build*/bin/bench_patches
// Wall and CPU time are noisy on the shared machine; instruction counts are repeatable:
//   valgrind --tool=callgrind '--toggle-collect=tristream::render_coons(*' build*/bin/bench_patches
//     --benchmark_filter='BM_coons_512/1$' --benchmark_min_time=0.000001   (one command line)
// (one render; divide by 512 * 512 for instructions per pixel). Grey, 13,004 vertices:
//   bezier 631.9M (2,410 per pixel) before the bit-identical speedups, 593.0M (2,262) after;
//   coons 1,059.2M (4,041) before, 988.5M (3,771) after. Of coons's, about 1.07M calls of
//   rasterize_micro_triangle cost ~430M with their visits, 1.13M Newton solves ~315M.
//   After the closed-domain rule (patch/raster.h: Newton until its step is below 1e-7, so
//   about one evaluation more per solve) and the Horner form of the Coons solve:
//   bezier 667.2M (2,545 per pixel), coons 987.3M (3,766).
//   After exact coverage by rows (patch/scan.h: no pixel beside a chord missed; every Coons
//   patch's fold bounded by cells, whose boxes widen the rows): bezier 678.4M (2,588),
//   coons 1,187.1M (4,528); rgb: bezier 756.8M, coons 1,291.7M. Coons pays for its folds
//   (half its patches fold; on the 13,000-vertex boat encoding, rendering without the fold
//   cells took 866M against 944M before and 1,116M with them).
#include <benchmark/benchmark.h>

#include <string>

#include "../support/random_mesh.h"
#include "reference/render.h"

using namespace tristream;

namespace {

const Mesh& mesh_512(int values) {
  static const Mesh grey = tristream::testing::random_lattice_mesh(512, 512, 13000, 2026, 0, 1);
  static const Mesh rgb = tristream::testing::random_lattice_mesh(512, 512, 13000, 2026, 0, 3);
  return values == 1 ? grey : rgb;
}

void render_method(benchmark::State& state, const char* name, const char* variant) {
  const MethodInfo* method = find_reference_method(name);
  if (!method) {
    state.SkipWithError("method not registered");
    return;
  }
  const Mesh& mesh = mesh_512(int(state.range(0)));
  RenderOptions options;
  options.variant = variant;
  for (auto _ : state) {
    Field out(512, 512, mesh.value_count);
    method->render(mesh, 512, 512, options, out);
    benchmark::DoNotOptimize(out.v.data());
  }
  state.counters["vertices"] = double(mesh.vertex_count());
  state.counters["Mpixel/s"] = benchmark::Counter(512.0 * 512 / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_bezier_512(benchmark::State& state) { render_method(state, "bezier", ""); }
void BM_coons_512(benchmark::State& state) { render_method(state, "coons", ""); }
void BM_clough_tocher_512(benchmark::State& state) { render_method(state, "clough-tocher", ""); }
void BM_bilinear_512(benchmark::State& state) { render_method(state, "bilinear", ""); }
void BM_bezier_thesis_512(benchmark::State& state) { render_method(state, "bezier", "thesis"); }
void BM_coons_thesis_512(benchmark::State& state) { render_method(state, "coons", "thesis"); }

BENCHMARK(BM_bezier_512)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_coons_512)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_clough_tocher_512)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bilinear_512)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bezier_thesis_512)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_coons_thesis_512)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
