// SPDX-License-Identifier: MIT
// triencode: turn an image into a triangulation file by greedy insertion.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "common/errors.h"
#include "common/json_name.h"
#include "common/tool_main.h"
#include "encoder/encoder.h"
#include "io/image_io.h"
#include "io/limits.h"
#include "io/tri_file.h"

using namespace tristream;

namespace {

// A one-line bar on stderr, redrawn when the whole percentage changes.
class ProgressBar {
 public:
  void operator()(double fraction) {
    const int percent = int(fraction * 100);
    if (percent == last_) return;
    last_ = percent;
    constexpr int width = 40;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
                 percent);
    std::fflush(stderr);
  }
  void finish() {
    if (last_ >= 0) std::fprintf(stderr, "\n");
  }

 private:
  int last_ = -1;
};

// An image triencode can encode: sides a .tri file can hold (limits::max_image_side) and at most
// limits::max_encode_pixels pixels. Throws DataError naming the limit.
void check_encodable(const std::string& path, const Image& image) {
  const std::string found = std::to_string(image.width) + "x" + std::to_string(image.height);
  if (image.width > limits::max_image_side || image.height > limits::max_image_side)
    throw DataError(path + ": expected an image of at most " + std::to_string(limits::max_image_side) +
                    " pixels a side (the largest a .tri file holds), found " + found);
  if (std::uint64_t(image.width) * std::uint64_t(image.height) > limits::max_encode_pixels)
    throw DataError(path + ": expected an image of at most " + std::to_string(limits::max_encode_pixels) +
                    " pixels (the limit for encoding), found " + found);
}

// A validator of a finite number above `lo` (or at least `lo` when `inclusive`) and at most
// `hi`; NaN and infinities are refused. The message states `expected` (not the bounds in full).
CLI::Validator finite_in(double lo, bool inclusive, double hi, const std::string& expected) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        const bool ok = used == text.size() && std::isfinite(v) && (inclusive ? v >= lo : v > lo) && v <= hi;
        return ok ? std::string() : "expected " + expected + ", found '" + text + "'";
      },
      expected);
}

// Options that would be ignored are usage errors (`grey`: the encoding is grey).
void check_conflicts(const CLI::App& app, bool grey) {
  auto given = [&](const char* name) { return app.count(name) > 0; };
  const bool separate = given("--color") && app.get_option("--color")->as<std::string>() == "separate";
  if (grey)
    for (const char* colour_only : {"--color", "--space", "--cotri"})
      if (given(colour_only))
        throw UsageError(std::string(colour_only) + ": applies to colour encodings only (not a grey image or --grey)");
  if (separate && given("--cotri")) throw UsageError("--cotri: applies to --color co only");
  if (given("--relocate") && app.get_option("--fit")->as<std::string>() == "pixel")
    throw UsageError("--relocate: applies to --fit lsq only");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Encode an image (PNG, JPEG, BMP, PGM/PPM) as a triangulation (.tri) by greedy insertion:\n"
               "start from the four corners, repeatedly insert the pixel of largest error under the\n"
               "linear interpolant (Garland & Heckbert 1995; triangles ranked by total squared error,\n"
               "candidates chosen on a Gaussian-smoothed copy), then move vertices to neighbouring pixels\n"
               "where that lowers the error of the least-squares fit."};
  std::string input, output;
  long long vertices = 0;  // signed, so that "-n -5" is refused instead of wrapping
  double max_rms = 0;
  std::string color = "co", space = "rgb", cotri = "greedy", fit = "lsq", rank = "total";
  double sigma = -1;
  int relocate = EncodeOptions{}.relocate_passes;
  bool grey = false, quiet = false, json = false;
  app.add_option("image", input, "Input image")->required();
  app.add_option("-o,--output", output, "Output triangulation file (.tri)")->required();
  auto* n_opt = app.add_option("-n,--vertices", vertices,
                               "Vertices per triangulation, corners included (with --color separate: per channel)");
  auto* e_opt = app.add_option("-e,--error", max_rms,
                               "Stop when the RMS error of the linear interpolant (0-255 scale, encoding space) "
                               "is at most this")
                    ->check(finite_in(0, false, 255, "a number above 0, at most 255"));
  app.add_option("--color", color, "Colour images: one co-triangulation or one per channel")
      ->check(CLI::IsMember({"co", "separate"}))
      ->capture_default_str();
  app.add_option("--space", space, "Colour space of a colour encoding")
      ->check(CLI::IsMember({"rgb", "ycbcr"}))
      ->capture_default_str();
  app.add_flag("--grey", grey, "Encode a colour image as grey (BT.601 luma)");
  app.add_option("--cotri", cotri,
                 "Co-triangulation: greedy on the error summed over channels, or the thesis's per-channel passes "
                 "(section 2.4)")
      ->check(CLI::IsMember({"greedy", "thesis"}))
      ->capture_default_str();
  app.add_option("--fit", fit, "Vertex values: the pixel values, or a least-squares refit rounded to 8 bits")
      ->check(CLI::IsMember({"pixel", "lsq"}))
      ->capture_default_str();
  app.add_option("--rank", rank, "Triangle priority: total squared error, or the worst pixel (plain G&H)")
      ->check(CLI::IsMember({"total", "worst"}))
      ->capture_default_str();
  app.add_option("--sigma", sigma,
                 "Gaussian sigma of the copy candidates are chosen on (0: the image itself; default 0.5 with "
                 "--fit lsq, 1 with --fit pixel)")
      ->check(finite_in(0, true, 10, "a number in 0..10"));
  app.add_option("--relocate", relocate,
                 "With --fit lsq: passes moving vertices to neighbouring pixels where that lowers the error, "
                 "keeping the mesh Delaunay (0: none)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  app.add_flag("-q,--quiet", quiet, "No progress bar");
  app.add_flag("--json", json, "Print the summary as one JSON object");

  return run_tool("triencode", app, argc, argv, [&] {
    if (!n_opt->count() && !e_opt->count()) throw UsageError("give --vertices N or --error E");
    EncodeOptions o;
    if (n_opt->count() && vertices < 4)
      throw UsageError("--vertices " + std::to_string(vertices) + ": expected at least 4 (the corners)");
    o.vertices = std::size_t(vertices);
    o.max_rms = max_rms;
    o.color = color == "co" ? ColorMode::co : ColorMode::separate;
    o.space = space == "rgb" ? ColorSpace::rgb : ColorSpace::ycbcr;
    o.grey = grey;
    o.cotri = cotri == "greedy" ? CotriMethod::greedy : CotriMethod::thesis;
    o.fit = fit == "pixel" ? VertexFit::pixel : VertexFit::lsq;
    o.rank_by_total_error = rank == "total";
    o.smoothing_sigma = sigma;
    o.relocate_passes = relocate;
    ProgressBar bar;
    if (!quiet && isatty(STDERR_FILENO)) o.progress = [&bar](double f) { bar(f); };

    const Image image = read_image(input, limits::max_encode_pixels);
    check_encodable(input, image);
    check_conflicts(app, grey || image.channels == 1);
    EncodeResult r;
    try {
      r = encode(image, o);
    } catch (const DataError& e) {
      throw DataError(input + ": " + e.what());
    }
    bar.finish();
    write_tri_file(output, r.triangulation);

    if (json) {
      nlohmann::json j;
      j["input"] = json_file_name(input);
      j["output"] = json_file_name(output);
      j["width"] = image.width;
      j["height"] = image.height;
      j["space"] = std::string(to_string(r.triangulation.space));
      j["layers"] = r.triangulation.layers.size();
      j["vertices"] = r.vertices;
      j["triangles"] = r.triangles;
      j["psnr_linear"] = std::isinf(r.psnr) ? nlohmann::json(nullptr) : nlohmann::json(r.psnr);
      j["seconds"] = r.seconds;
      std::printf("%s\n", j.dump().c_str());
    } else {
      std::printf("%s: %zu vertices, %zu triangles, PSNR %.2f dB (linear interpolant), %.3f s\n", output.c_str(),
                  r.vertices, r.triangles, r.psnr, r.seconds);
    }
    return int(exit_ok);
  });
}
