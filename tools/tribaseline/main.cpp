// SPDX-License-Identifier: MIT
// tribaseline: the literature's baselines of mesh-based image representation, written as .tri
// files that every other tool reads (triencode's results are measured against them).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "baselines/gpr.h"
#include "common/cli_validators.h"
#include "common/errors.h"
#include "common/json_name.h"
#include "common/progress_bar.h"
#include "common/tool_main.h"
#include "encoder/encoder.h"
#include "io/image_io.h"
#include "io/limits.h"
#include "io/tri_file.h"

using namespace tristream;

namespace {

struct Command {
  std::string input, output;
  long long vertices = 0;  // signed, so that "-n -5" is refused instead of wrapping
  double percent = 0;
  std::string values = "pixel";
  bool quiet = false, json = false;
};

void add_gpr_options(CLI::App& gpr, Command& c) {
  gpr.add_option("image", c.input, "Input image (PNG, JPEG, BMP, PGM/PPM; grey or RGB)")->required();
  gpr.add_option("-o,--output", c.output, "Output triangulation file (.tri)")->required();
  auto* n = gpr.add_option("-n,--vertices", c.vertices, "Vertices kept, the four corners included")
                ->transform(decimal_in(4, std::int64_t(limits::max_encode_pixels),
                                       "at least 4 vertices (the corners) and at most " +
                                           std::to_string(limits::max_encode_pixels) +
                                           " (the pixels of the largest image encoded)"));
  auto* p = gpr.add_option("-p,--percent", c.percent,
                           "Vertices kept as a share of the pixels, in percent (rounded to the nearest count, "
                           "at least 4)")
                ->check(finite_in(0, false, 100, "a percentage above 0, at most 100"));
  n->excludes(p);
  gpr.add_option("--values", c.values,
                 "Vertex values: the pixel values (GPR), or a least-squares refit over all pixels rounded to 8 "
                 "bits (GPR + LSQ)")
      ->check(CLI::IsMember({"pixel", "lsq"}))
      ->capture_default_str();
  gpr.add_flag("-q,--quiet", c.quiet, "No progress bar");
  gpr.add_flag("--json", c.json, "Print the summary as one JSON object");
}

void print_summary(const Command& c, const baselines::GprResult& r) {
  if (c.json) {
    nlohmann::json j;
    j["method"] = "gpr";
    j["values"] = c.values;
    j["input"] = json_file_name(c.input);
    j["output"] = json_file_name(c.output);
    j["width"] = r.triangulation.width;
    j["height"] = r.triangulation.height;
    j["space"] = std::string(to_string(r.triangulation.space));
    j["vertices"] = r.vertices;
    j["triangles"] = r.triangles;
    j["psnr_linear"] = std::isinf(r.psnr) ? nlohmann::json(nullptr) : nlohmann::json(r.psnr);
    j["seconds"] = r.seconds;
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s: %zu vertices, %zu triangles, PSNR %.2f dB (linear interpolant), %.3f s\n", c.output.c_str(),
                r.vertices, r.triangles, r.psnr, r.seconds);
  }
}

int run_gpr(const CLI::App& gpr, const Command& c) {
  if (!gpr.count("--vertices") && !gpr.count("--percent")) throw UsageError("give --vertices N or --percent P");
  const Image image = read_image(c.input, limits::max_encode_pixels);
  check_encodable(image, c.input);
  baselines::GprOptions o;
  const double pixels = double(image.width) * image.height;
  o.vertices = gpr.count("--percent") ? std::size_t(std::max(4.0, std::round(c.percent / 100.0 * pixels)))
                                      : std::size_t(c.vertices);
  o.values = c.values == "lsq" ? VertexFit::lsq : VertexFit::pixel;
  ProgressBar bar;
  if (!c.quiet && isatty(STDERR_FILENO)) o.progress = [&bar](double f) { bar(f); };
  baselines::GprResult r;
  try {
    r = baselines::greedy_point_removal(image, o);
  } catch (const DataError& e) {
    throw DataError(c.input + ": " + e.what());
  }
  bar.finish();
  write_tri_file(c.output, r.triangulation);
  print_summary(c, r);
  return int(exit_ok);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Baselines of mesh-based image representation, written as triangulation files (.tri)."};
  app.require_subcommand(1);
  CLI::App* gpr = app.add_subcommand(
      "gpr",
      "Greedy point removal (Demaret and Iske's adaptive thinning, Adams' GPR): start from the Delaunay\n"
      "triangulation of every pixel and repeatedly remove the vertex whose removal raises the squared error of\n"
      "the linear interpolant least (the four corners stay), until N vertices remain.");
  Command c;
  add_gpr_options(*gpr, c);
  return run_tool("tribaseline", app, argc, argv, [&] { return run_gpr(*gpr, c); });
}
