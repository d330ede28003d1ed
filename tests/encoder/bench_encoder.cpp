// SPDX-License-Identifier: MIT
// Encoder speed: `bench_encoder` prints the time to encode a 512x512 photograph (grey and
// colour) to 2,621 and 10,000 vertices, with and without the relocation post-pass; the
// issue's target is 10,000 vertices under 1 s. The photographs come from $TRISTREAM_IMAGES
// (tests/support/test_images.h); without them the benchmarks skip and the demo image
// (768 x 512) is encoded instead.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "encoder/encoder.h"
#include "io/image_io.h"

#include "../support/test_images.h"

namespace {

void encode_image(benchmark::State& state, const std::string& file, tristream::VertexFit fit,
                  int relocate_passes = tristream::EncodeOptions{}.relocate_passes,
                  int flip_rounds = tristream::EncodeOptions{}.flip_rounds) {
  const std::string path = file.empty() ? tristream::test::demo_image() : tristream::test::shared_image(file);
  if (path.empty()) {
    state.SkipWithError(tristream::test::skip_message(file).c_str());
    return;
  }
  const tristream::Image img = tristream::read_image(path);
  tristream::EncodeOptions o;
  o.vertices = std::size_t(state.range(0));
  o.fit = fit;
  o.relocate_passes = relocate_passes;
  o.flip_rounds = flip_rounds;
  double psnr = 0;
  for (auto _ : state) psnr = tristream::encode(img, o).psnr;
  state.counters["psnr_db"] = psnr;
}

void grey_pixel(benchmark::State& s) { encode_image(s, "grey/peppers_grey.png", tristream::VertexFit::pixel); }
void grey_lsq(benchmark::State& s) { encode_image(s, "grey/peppers_grey.png", tristream::VertexFit::lsq); }
void colour_pixel(benchmark::State& s) { encode_image(s, "colour/peppers.png", tristream::VertexFit::pixel); }
void colour_lsq(benchmark::State& s) { encode_image(s, "colour/peppers.png", tristream::VertexFit::lsq); }
// Without the edge flips (a Delaunay mesh), and without the relocation either.
void grey_lsq_no_flips(benchmark::State& s) {
  encode_image(s, "grey/peppers_grey.png", tristream::VertexFit::lsq, tristream::EncodeOptions{}.relocate_passes, 0);
}
void colour_lsq_no_flips(benchmark::State& s) {
  encode_image(s, "colour/peppers.png", tristream::VertexFit::lsq, tristream::EncodeOptions{}.relocate_passes, 0);
}
void grey_lsq_no_relocation(benchmark::State& s) {
  encode_image(s, "grey/peppers_grey.png", tristream::VertexFit::lsq, 0, 0);
}
void colour_lsq_no_relocation(benchmark::State& s) {
  encode_image(s, "colour/peppers.png", tristream::VertexFit::lsq, 0, 0);
}
// The shipped demo image, always available.
void demo_lsq(benchmark::State& s) { encode_image(s, "", tristream::VertexFit::lsq); }
BENCHMARK(demo_lsq)->Arg(4000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(grey_pixel)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(grey_lsq)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(colour_pixel)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(colour_lsq)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(grey_lsq_no_flips)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(colour_lsq_no_flips)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(grey_lsq_no_relocation)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(colour_lsq_no_relocation)->Arg(2621)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
