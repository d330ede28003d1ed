// SPDX-License-Identifier: MIT
// triencode: turn an image into a triangulation file by greedy insertion.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "common/cli_validators.h"
#include "common/errors.h"
#include "common/json_name.h"
#include "common/name_list.h"
#include "common/progress_bar.h"
#include "common/tool_main.h"
#include "core_bridge/pack.h"
#include "encoder/blob_budget.h"
#include "encoder/encoder.h"
#include "encoder/panel.h"
#include "io/image_io.h"
#include "io/limits.h"
#include "io/tri_file.h"
#include "metrics/metrics.h"
#include "reference/fit_names.h"
#include "reference/render.h"

using namespace tristream;

namespace {

// Options that would be ignored, or that contradict each other, are usage errors (`grey`: the
// encoding is grey).
void check_conflicts(const CLI::App& app, bool grey) {
  auto given = [&](const char* name) { return app.count(name) > 0; };
  const bool separate = given("--color") && app.get_option("--color")->as<std::string>() == "separate";
  if (grey)
    for (const char* colour_only : {"--color", "--space", "--cotri"})
      if (given(colour_only))
        throw UsageError(std::string(colour_only) + ": applies to colour encodings only (not a grey image or --grey)");
  if (separate && given("--cotri")) throw UsageError("--cotri: applies to --color co only");
  const bool pixel_values = app.get_option("--values")->as<std::string>() == "pixel";
  for (const char* lsq_only : {"--relocate", "--flips"})
    if (given(lsq_only) && pixel_values) throw UsageError(std::string(lsq_only) + ": applies to --values lsq only");
  if (pixel_values && app.get_option("--method")->as<std::string>() != "bilinear")
    throw UsageError("--method " + app.get_option("--method")->as<std::string>() +
                     ": fits its values and gradients by least squares, so it takes --values lsq only");
}

void check_usage(const CLI::App& app) {
  auto given = [&](const char* name) { return app.count(name) > 0; };
  if (given("--max-bytes")) {
    if (given("--vertices") || given("--error"))
      throw UsageError("--max-bytes: chooses the vertex count itself; give it without --vertices and --error");
  } else {
    if (!given("--vertices") && !given("--error")) throw UsageError("give --vertices N, --error E or --max-bytes B");
    for (const char* budget_only : {"--blob"})
      if (given(budget_only))
        throw UsageError(std::string(budget_only) + ": applies to --max-bytes only (the blob it measures)");
  }
  if (given("--gradient-step") && app.get_option("--method")->as<std::string>() == "bilinear")
    throw UsageError(
        "--gradient-step: applies to --method zienkiewicz or clough-tocher only (bilinear has no gradients)");
  if (given("--max-bytes") && app.get_option("--method")->as<std::string>() == "clough-tocher")
    throw UsageError(
        "--method clough-tocher: the core does not draw it, so there is no blob for --max-bytes to measure "
        "(its data are zienkiewicz's: measure -m zienkiewicz)");
  if (given("--width") != given("--height"))
    throw UsageError(std::string(given("--width") ? "--width" : "--height") +
                     ": give the panel's --width and --height together");
  if (!given("--width"))
    for (const char* panel_only : {"--fit", "--resampled"})
      if (given(panel_only)) throw UsageError(std::string(panel_only) + ": applies with --width and --height only");
}

// --fit names how the picture meets the panel; the vertex values were --fit before they were
// --values, and that spelling gets a pointer instead of a bare "not a member".
CLI::Validator panel_fit() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (find_fit(text)) return {};
        const std::string expected = "expected " + name_list(fit_names()) + ", found '" + text + "'";
        if (text == "pixel" || text == "lsq") return expected + " (the vertex values are --values " + text + ")";
        return expected;
      },
      name_list(fit_names(), "|", "|"));
}

// The command line's values (the defaults are triencode's).
struct Command {
  std::string input, output;
  long long vertices = 0;  // signed, so that "-n -5" is refused instead of wrapping
  double max_rms = 0;
  std::string color = "co", space = "rgb", cotri = "greedy", values = "lsq", rank = "total";
  int panel_width = 0, panel_height = 0;
  std::string fit = std::string(fit_name(Fit::stretch)), resampled, method = "bilinear", blob = "compressed";
  long long max_bytes = 0;
  double sigma = -1;
  int relocate = EncodeOptions{}.relocate_passes;
  int flips = EncodeOptions{}.flip_rounds;
  int gradient_step = EncodeOptions{}.gradient_step_bits;
  bool grey = false, quiet = false, json = false;
};

void add_options(CLI::App& app, Command& c) {
  app.add_option("image", c.input, "Input image")->required();
  app.add_option("-o,--output", c.output, "Output triangulation file (.tri)")->required();
  app.add_option("-n,--vertices", c.vertices,
                 "Vertices per triangulation, corners included (with --color separate: per channel)")
      ->transform(decimal_in(4, std::int64_t(limits::max_encode_pixels),
                             "at least 4 vertices (the corners) and at most " +
                                 std::to_string(limits::max_encode_pixels) +
                                 " (the pixels of the largest image encoded)"));
  app.add_option("-e,--error", c.max_rms,
                 "Stop when the RMS error of the linear interpolant (0-255 scale, encoding space) "
                 "is at most this")
      ->check(finite_in(0, false, 255, "a number above 0, at most 255"));
  app.add_option("--color", c.color, "Colour images: one co-triangulation or one per channel")
      ->check(CLI::IsMember({"co", "separate"}))
      ->capture_default_str();
  app.add_option("--space", c.space, "Colour space of a colour encoding")
      ->check(CLI::IsMember({"rgb", "ycbcr"}))
      ->capture_default_str();
  app.add_flag("--grey", c.grey, "Encode a colour image as grey (BT.601 luma)");
  app.add_option("--cotri", c.cotri,
                 "Co-triangulation: greedy on the error summed over channels, or the thesis's per-channel passes "
                 "(section 2.4)")
      ->check(CLI::IsMember({"greedy", "thesis"}))
      ->capture_default_str();
  app.add_option("--values", c.values, "Vertex values: the pixel values, or a least-squares refit rounded to 8 bits")
      ->check(CLI::IsMember({"pixel", "lsq"}))
      ->capture_default_str();
  app.add_option("--rank", c.rank, "Triangle priority: total squared error, or the worst pixel (plain G&H)")
      ->check(CLI::IsMember({"total", "worst"}))
      ->capture_default_str();
  app.add_option("--sigma", c.sigma,
                 "Gaussian sigma of the copy candidates are chosen on (0: the image itself; default 0.5 with "
                 "--values lsq, 1 with --values pixel)")
      ->check(finite_in(0, true, 10, "a number in 0..10"));
  app.add_option("--relocate", c.relocate,
                 "With --values lsq: passes moving vertices to neighbouring pixels where that lowers the error, "
                 "keeping the mesh Delaunay (0: none)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  app.add_option("--flips", c.flips,
                 "With --values lsq: rounds of data-dependent triangulation after the relocation: edges flip where "
                 "that lowers the error, then vertices move again without the Delaunay condition (0: the mesh stays "
                 "Delaunay)")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  app.add_option("--width", c.panel_width,
                 "Encode for a panel this wide: the image is resampled (Mitchell filter in linear light to shrink, "
                 "Catmull-Rom to grow) and the .tri is --width x --height, drawn on the panel at its own size")
      ->check(CLI::Range(2, int(limits::max_image_side)));
  app.add_option("--height", c.panel_height, "The panel's height (with --width)")
      ->check(CLI::Range(2, int(limits::max_image_side)));
  app.add_option("--fit", c.fit,
                 "How the picture meets the panel, as trisim --fit and ts_params.fit place it: stretch (corner to "
                 "corner), inside (one scale, centred; the border is left outside the triangulation, so the "
                 "renderer draws it in its background), fill (one scale, centred, the excess cropped)")
      ->check(panel_fit())
      ->capture_default_str();
  app.add_option("--resampled", c.resampled,
                 "Also write the resampled image as PNG, the panel's size (the border of --fit inside black, the "
                 "renderers' default background): what the PSNR is measured against");
  app.add_option("--max-bytes", c.max_bytes,
                 "Choose the vertex count: the most found whose blob (--blob, as tripack -m METHOD writes it) is at "
                 "most this many bytes, and at least 0.85 times as many; prints the bytes and the PSNR reached")
      ->transform(decimal_in(1, 1LL << 40, "a number of bytes from 1 to " + std::to_string(1LL << 40)));
  app.add_option("-m,--method", c.method,
                 "The interpolation method the picture will be shown with: zienkiewicz and clough-tocher fit values "
                 "and gradients by least squares on their own basis and store the gradients in the .tri (the mesh is "
                 "chosen for bilinear). With --max-bytes the blob is packed for it (tripack -m) and the PSNR is of "
                 "its render. Bilinear is recommended: at equal compressed bytes it is ahead of both on photographs "
                 "(tools/experiments/README.md, methods at equal bytes)")
      ->check(CLI::IsMember({"bilinear", "zienkiewicz", "clough-tocher"}))
      ->capture_default_str();
  app.add_option("--gradient-step", c.gradient_step,
                 "With --method zienkiewicz or clough-tocher: gradients in steps of 2^(BITS-12) values per pixel (the "
                 "core keeps 12 fraction bits; the compressed blob codes whole steps)")
      ->check(CLI::Range(0, 12))
      ->capture_default_str();
  app.add_option("--blob", c.blob,
                 "With --max-bytes: the blob measured, compressed (tripack --compress, rendered from its streams) "
                 "or v1 (tripack without --compress, what ts_open reads in place)")
      ->check(CLI::IsMember({"compressed", "v1"}))
      ->capture_default_str();
  app.add_flag("-q,--quiet", c.quiet, "No progress bar");
  app.add_flag("--json", c.json, "Print the summary as one JSON object");
  app.footer(
      "How many vertices: --max-bytes finds the count for a flash budget in a few encodes. As a guide (the demo\n"
      "picture at 2,000 to 6,600 vertices), bytes per vertex: compressed bilinear 4.7 to 5.2 in colour, 3.4 to 3.7\n"
      "in grey, zienkiewicz 11.0 to 11.3 and 5.5 to 5.8; v1 bilinear 26 and 22, zienkiewicz 50 and 30; plus 120 to\n"
      "250 a blob. Bilinear is the recommended method: at equal bytes it is ahead of zienkiewicz and clough-tocher.");
}

// The encoder's options; throws UsageError for a vertex count below 4 or a panel too large.
EncodeOptions encode_options(const CLI::App& app, const Command& c) {
  EncodeOptions o;
  if (app.count("--vertices") && c.vertices < 4)
    throw UsageError("--vertices " + std::to_string(c.vertices) + ": expected at least 4 (the corners)");
  o.vertices = std::size_t(c.vertices);
  o.max_rms = c.max_rms;
  o.color = c.color == "co" ? ColorMode::co : ColorMode::separate;
  o.space = c.space == "rgb" ? ColorSpace::rgb : ColorSpace::ycbcr;
  o.grey = c.grey;
  o.cotri = c.cotri == "greedy" ? CotriMethod::greedy : CotriMethod::thesis;
  o.fit = c.values == "pixel" ? VertexFit::pixel : VertexFit::lsq;
  o.rank_by_total_error = c.rank == "total";
  o.smoothing_sigma = c.sigma;
  o.relocate_passes = c.relocate;
  o.flip_rounds = c.flips;
  o.method = parse_fit_method(c.method);
  o.gradient_step_bits = c.gradient_step;
  if (c.panel_width && std::uint64_t(c.panel_width) * std::uint64_t(c.panel_height) > limits::max_encode_pixels)
    throw UsageError("--width/--height: expected a panel of at most " + std::to_string(limits::max_encode_pixels) +
                     " pixels (the limit for encoding), found " + std::to_string(c.panel_width) + "x" +
                     std::to_string(c.panel_height));
  return o;
}

// An encoding of the picture: the encoder's result and its triangulation placed on the panel (with
// --max-bytes also the search that chose it).
using Encoded = BudgetEncoding;

// --max-bytes: the budget as the options name it.
BlobBudget blob_budget(const Command& c) {
  BlobBudget b;
  b.max_bytes = std::size_t(c.max_bytes);
  b.method = parse_core_method(c.method);
  b.compressed = c.blob == "compressed";
  return b;
}

// The summary line, or with --json one object. `psnr_method` is the PSNR of the --method render
// (with --max-bytes).
void print_summary(const Command& c, const PanelPicture& panel, const Encoded& e, double psnr_method) {
  const EncodeResult& r = e.result;
  const Triangulation& tri = e.tri;
  const Image& picture = panel.picture;
  auto json_db = [](double db) { return std::isinf(db) ? nlohmann::json(nullptr) : nlohmann::json(db); };
  if (c.json) {
    nlohmann::json j;
    j["input"] = json_file_name(c.input);
    j["output"] = json_file_name(c.output);
    j["width"] = tri.width;
    j["height"] = tri.height;
    if (c.panel_width)
      j["panel"] = {
          {"fit", c.fit},
          {"picture", {{"x", panel.x0}, {"y", panel.y0}, {"width", picture.width}, {"height", picture.height}}}};
    j["space"] = std::string(to_string(tri.space));
    j["layers"] = tri.layers.size();
    j["vertices"] = r.vertices;
    j["triangles"] = r.triangles;
    if (c.method == "bilinear") j["psnr_linear"] = json_db(r.psnr);
    j["method"] = c.method;
    j["psnr"] = json_db(psnr_method);
    if (c.method != "bilinear") j["gradient_step_bits"] = c.gradient_step;
    if (c.max_bytes) {
      j["max_bytes"] = c.max_bytes;
      j["blob"] = c.blob;
      j["blob_bytes"] = e.search.chosen.bytes;
      nlohmann::json trials = nlohmann::json::array();
      for (const BudgetTrial& t : e.search.trials) trials.push_back({{"vertices", t.vertices}, {"bytes", t.bytes}});
      j["trials"] = trials;
    }
    j["seconds"] = e.seconds;
    std::printf("%s\n", j.dump().c_str());
  } else if (c.max_bytes) {
    const BudgetTrial& t = e.search.chosen;
    const bool complete = double(t.bytes) < 0.85 * double(c.max_bytes);
    std::printf(
        "%s: %zu vertices, %zu triangles; %s blob %zu bytes of %lld (%.1f %%, tripack%s -m %s)%s; PSNR %.2f "
        "dB (%s render of the %dx%d picture); %zu encodes, %.3f s\n",
        c.output.c_str(), r.vertices, r.triangles, c.blob.c_str(), t.bytes, c.max_bytes,
        100.0 * double(t.bytes) / double(c.max_bytes), c.blob == "compressed" ? " --compress" : "", c.method.c_str(),
        complete ? (t.exhausted || t.vertices == std::size_t(picture.width) * picture.height
                        ? "; the picture needs no more"
                        : "; the core's vertex limit")
                 : "",
        psnr_method, c.method.c_str(), picture.width, picture.height, e.search.trials.size(), e.seconds);
  } else {
    std::printf("%s: %zu vertices, %zu triangles, PSNR %.2f dB (%s), %.3f s\n", c.output.c_str(), r.vertices,
                r.triangles, r.psnr, c.method == "bilinear" ? "linear interpolant" : (c.method + " render").c_str(),
                e.seconds);
  }
}

int encode_image(const CLI::App& app, const Command& c) {
  check_usage(app);
  EncodeOptions o = encode_options(app, c);
  ProgressBar bar;
  if (!c.quiet && isatty(STDERR_FILENO)) o.progress = [&bar](double f) { bar(f); };
  const Image image = read_image(c.input, limits::max_encode_pixels);
  check_encodable(image, c.input);
  check_conflicts(app, c.grey || image.channels == 1);
  const PanelPicture panel = picture_for_panel(image, c.panel_width, c.panel_height, parse_fit(c.fit), c.input);
  Encoded e;
  if (c.max_bytes) {
    e = encode_to_budget(panel, o, blob_budget(c), c.input);
  } else {
    e.result = encode(panel.picture, o, c.input);
    e.seconds = e.result.seconds;
    e.tri = on_panel(e.result.triangulation, panel);
  }
  bar.finish();
  write_tri_file(c.output, e.tri);
  if (!c.resampled.empty()) write_png(c.resampled, panel_image(panel));
  // With --max-bytes the PSNR is of the render the blob gives (the reference of --method), over
  // the picture's pixels (an inside border is the renderer's background, not encoded).
  double psnr_method = e.result.psnr;
  if (c.max_bytes) {
    const MethodInfo* m = find_reference_method(c.method);
    const Image render = render_reference(e.result.triangulation, *m, RenderOptions{});
    psnr_method = psnr(render, encoded_original(panel.picture, e.result.triangulation));
  }
  print_summary(c, panel, e, psnr_method);
  return int(exit_ok);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Encode an image (PNG, JPEG, BMP, PGM/PPM) as a triangulation (.tri) by greedy insertion:\n"
               "start from the four corners, repeatedly insert the pixel of largest error under the\n"
               "linear interpolant (Garland & Heckbert 1995; triangles ranked by total squared error,\n"
               "candidates chosen on a Gaussian-smoothed copy), then move vertices to neighbouring pixels\n"
               "where that lowers the error of the least-squares fit."};
  Command c;
  add_options(app, c);
  return run_tool("triencode", app, argc, argv, [&] { return encode_image(app, c); });
}
