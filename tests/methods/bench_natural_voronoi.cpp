// Speed of the natural and voronoi reference renderers at 512x512 from about 13,000 vertices
// (the issue 5 target: under 100 ms each on one core). Prints figures; not a test.
//   build*/bin/bench_natural_voronoi
#include <benchmark/benchmark.h>

#include "../support/random_mesh.h"
#include "reference/render.h"

using namespace tristream;

namespace {

const Mesh& mesh_512(int values) {
  static const Mesh grey = tristream::testing::random_lattice_mesh(512, 512, 13000, 2026, 0, 1);
  static const Mesh rgb = tristream::testing::random_lattice_mesh(512, 512, 13000, 2026, 0, 3);
  return values == 1 ? grey : rgb;
}

void render_method(benchmark::State& state, const char* name) {
  const MethodInfo* method = find_reference_method(name);
  if (!method) {
    state.SkipWithError("method not registered");
    return;
  }
  const Mesh& mesh = mesh_512(int(state.range(0)));
  for (auto _ : state) {
    Field out(512, 512, mesh.value_count);
    method->render(mesh, 512, 512, {}, out);
    benchmark::DoNotOptimize(out.v.data());
  }
  state.counters["vertices"] = double(mesh.vertex_count());
  state.counters["Mpixel/s"] = benchmark::Counter(512.0 * 512 / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_natural_512(benchmark::State& state) { render_method(state, "natural"); }
void BM_voronoi_512(benchmark::State& state) { render_method(state, "voronoi"); }
void BM_bilinear_512(benchmark::State& state) { render_method(state, "bilinear"); }

BENCHMARK(BM_natural_512)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_voronoi_512)->Arg(1)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_bilinear_512)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
