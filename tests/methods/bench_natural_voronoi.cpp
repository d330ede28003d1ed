// SPDX-License-Identifier: MIT
// Speed of the natural and voronoi reference renderers at 512x512 from about 13,000 vertices
// (the issue 5 target: under 100 ms each on one core). Prints figures; not a test.
//   build*/bin/bench_natural_voronoi [more.tri ...] [--benchmark_* flags]
// The built-in case is a random lattice mesh (13,004 vertices, Delaunay); each .tri given on
// the command line (for example an encoder output) is benchmarked as well, at its own size.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "../support/random_mesh.h"
#include "io/tri_file.h"
#include "reference/render.h"

using namespace tristream;

namespace {

void render_method(benchmark::State& state, const char* name, const Triangulation& tri) {
  const MethodInfo* method = find_reference_method(name);
  if (!method) {
    state.SkipWithError("method not registered");
    return;
  }
  std::size_t vertices = 0;
  for (const Mesh& m : tri.layers) vertices += m.vertex_count();
  for (auto _ : state) {
    Field field = render_reference_field(tri, *method, {});
    benchmark::DoNotOptimize(field.v.data());
  }
  state.counters["vertices"] = double(vertices);
  state.counters["Mpixel/s"] =
      benchmark::Counter(double(tri.width) * tri.height / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

Triangulation random_512(ColorSpace space) {
  Triangulation tri;
  tri.width = tri.height = 512;
  tri.space = space;
  tri.layers.push_back(tristream::testing::random_lattice_mesh(512, 512, 13000, 2026, 0, channel_count(space)));
  return tri;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  static std::vector<std::pair<std::string, Triangulation>> cases = {
      {"random13k_512_grey", random_512(ColorSpace::grey)}, {"random13k_512_rgb", random_512(ColorSpace::rgb)}};
  for (int i = 1; i < argc; ++i) cases.push_back({argv[i], read_tri_file(argv[i])});
  for (const auto& [label, tri] : cases)
    for (const char* method : {"natural", "voronoi", "bilinear"})
      benchmark::RegisterBenchmark((std::string(method) + "/" + label).c_str(),
                                   [method, &tri = tri](benchmark::State& s) { render_method(s, method, tri); })
          ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
