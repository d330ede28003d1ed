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
#include "common/tool_main.h"
#include "core_bridge/compress.h"
#include "core_bridge/pack.h"
#include "encoder/budget.h"
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
  if (given("--relocate") && app.get_option("--values")->as<std::string>() == "pixel")
    throw UsageError("--relocate: applies to --values lsq only");
}

void check_usage(const CLI::App& app) {
  auto given = [&](const char* name) { return app.count(name) > 0; };
  if (given("--max-bytes")) {
    if (given("--vertices") || given("--error"))
      throw UsageError("--max-bytes: chooses the vertex count itself; give it without --vertices and --error");
  } else {
    if (!given("--vertices") && !given("--error")) throw UsageError("give --vertices N, --error E or --max-bytes B");
    for (const char* budget_only : {"--method", "--blob"})
      if (given(budget_only))
        throw UsageError(std::string(budget_only) + ": applies to --max-bytes only (the blob it measures)");
  }
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

// The triangulation of the picture on the panel: positions moved by the picture's offset, the size
// the panel's (with --fit inside the border stays outside every triangle: the renderer's background).
Triangulation on_panel(Triangulation tri, const PanelPicture& p) {
  tri.width = p.panel_width;
  tri.height = p.panel_height;
  for (Mesh& m : tri.layers)
    for (Point& q : m.points) {
      q.x += p.x0;
      q.y += p.y0;
    }
  return tri;
}

// What --max-bytes measures: the blob tripack -m <method> writes for `tri`, with --compress or
// without (v1).
std::size_t blob_bytes(const Triangulation& tri, core::Method method, bool compressed, const std::string& name) {
  const std::vector<std::uint8_t> v1 = pack_blob(tri, method, name);
  return compressed ? compress_blob(v1, name).size() : v1.size();
}

// A first guess of the bytes per vertex; the search measures the real slope after one step.
// Compressed (docs/COMPRESSED_BLOB.md, measured on the demo): about 17 bits of positions,
// connectivity and flags, 6.5 of values per channel and 32 of zienkiewicz gradients per channel.
// v1 (tristream/blob.h): a vertex's position 4 bytes and 2 per value, about two triangles of 8 bytes,
// zienkiewicz gradients 8 bytes per value.
double bytes_per_vertex_guess(int channels, core::Method method, bool compressed) {
  const bool z = method == core::Method::zienkiewicz;
  if (compressed) return (17.0 + channels * (6.5 + (z ? 32.0 : 0.0))) / 8.0;
  return 4.0 + 16.0 + channels * (2.0 + (z ? 8.0 : 0.0));
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
                 "With --max-bytes: the interpolation method the blob is packed for (tripack -m; zienkiewicz adds "
                 "gradients, about 3.6 times the compressed bytes of bilinear) and the PSNR is of")
      ->check(CLI::IsMember({"bilinear", "zienkiewicz"}))
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
      "picture at 2,000 to 6,600 vertices), bytes per vertex: compressed bilinear 4.5 to 4.9 in colour, 2.9 to 3.3\n"
      "in grey, zienkiewicz 16.5 and 7.3; v1 bilinear 26 and 22, zienkiewicz 50 and 30; plus 120 to 250 a blob.");
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
  if (c.panel_width && std::uint64_t(c.panel_width) * std::uint64_t(c.panel_height) > limits::max_encode_pixels)
    throw UsageError("--width/--height: expected a panel of at most " + std::to_string(limits::max_encode_pixels) +
                     " pixels (the limit for encoding), found " + std::to_string(c.panel_width) + "x" +
                     std::to_string(c.panel_height));
  return o;
}

// The picture encoded: the image itself, or with --width and --height resampled for the panel.
PanelPicture panel_picture(const Command& c, const Image& image) {
  PanelPicture panel;
  if (!c.panel_width) {
    panel.panel_width = image.width;
    panel.panel_height = image.height;
    panel.picture = image;
    return panel;
  }
  if (image.width < 2 || image.height < 2)
    throw DataError(c.input + ": expected an image of at least 2x2 pixels to resample, found " +
                    std::to_string(image.width) + "x" + std::to_string(image.height));
  return fit_to_panel(image, c.panel_width, c.panel_height, parse_fit(c.fit));
}

// An encoding of the picture: the encoder's result and its triangulation placed on the panel.
struct Encoded {
  EncodeResult result;
  Triangulation tri;
  BudgetSearch search;  // --max-bytes: the trials and the one chosen
  double seconds = 0;   // all encodes
};

// Encodes with the options' vertex count or error; a data error names the input.
EncodeResult encode_picture(const Command& c, const Image& picture, const EncodeOptions& options) {
  try {
    return encode(picture, options);
  } catch (const DataError& e) {
    throw DataError(c.input + ": " + e.what());
  }
}

// --max-bytes: the most vertices found whose blob fits, one encode per trial (the progress bar
// shows the trial under way).
Encoded encode_to_budget(const Command& c, const PanelPicture& panel, const EncodeOptions& o) {
  const Image& picture = panel.picture;
  const core::Method pack_method = parse_core_method(c.method);
  const bool compressed = c.blob == "compressed";
  if (panel.panel_width > core::config::max_dimension || panel.panel_height > core::config::max_dimension)
    throw DataError(c.input + ": --max-bytes measures a blob for the core, which takes at most " +
                    std::to_string(core::config::max_dimension) + " pixels a side, found " +
                    std::to_string(panel.panel_width) + "x" + std::to_string(panel.panel_height) +
                    " (--width and --height encode for a smaller panel)");
  Encoded out;
  BudgetOptions b;
  b.max_bytes = std::size_t(c.max_bytes);
  b.max_vertices =
      std::min<std::size_t>(std::size_t(picture.width) * std::size_t(picture.height), core::blob_max_vertices);
  b.bytes_per_vertex = bytes_per_vertex_guess(c.grey ? 1 : picture.channels, pack_method, compressed);
  if (o.color == ColorMode::separate && !c.grey && picture.channels == 3) b.bytes_per_vertex *= 3;
  std::size_t kept_vertices = 0;
  out.search = search_vertex_budget(
      [&](std::size_t n) {
        EncodeOptions trial = o;
        trial.vertices = n;
        EncodeResult e = encode_picture(c, picture, trial);
        out.seconds += e.seconds;
        Triangulation placed = on_panel(e.triangulation, panel);
        const std::size_t bytes = blob_bytes(placed, pack_method, compressed, c.input);
        // Exhausted: the linear interpolant is exact, or every mesh stopped short of n; more
        // vertices would only cost bytes.
        bool exhausted = true;
        for (const Mesh& m : e.triangulation.layers) exhausted = exhausted && m.vertex_count() < n;
        exhausted = exhausted || std::isinf(e.psnr);
        // The most vertices fitting the budget so far is the one kept (the search ends on it).
        if (bytes <= b.max_bytes && (out.tri.layers.empty() || n > kept_vertices)) {
          kept_vertices = n;
          out.result = std::move(e);
          out.tri = std::move(placed);
        }
        return BudgetTrial{n, bytes, exhausted};
      },
      b);
  const BudgetSearch& search = out.search;
  if (!search.found)
    throw UsageError("--max-bytes " + std::to_string(c.max_bytes) + ": expected at least " +
                     std::to_string(search.chosen.bytes) + " bytes, the smallest " + c.blob +
                     " blob of this picture (its 4 corners, " + c.method + ")");
  const bool complete = search.chosen.exhausted || search.chosen.vertices >= b.max_vertices;
  if (double(search.chosen.bytes) < 0.85 * double(b.max_bytes) && !complete)
    throw DataError(c.input + ": no vertex count found whose blob is within 0.85 to 1 times " +
                    std::to_string(c.max_bytes) + " bytes in " + std::to_string(search.trials.size()) +
                    " encodes (the largest that fits: " + std::to_string(search.chosen.vertices) + " vertices, " +
                    std::to_string(search.chosen.bytes) + " bytes)");
  return out;
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
    j["psnr_linear"] = json_db(r.psnr);
    if (c.max_bytes) {
      j["method"] = c.method;
      j["psnr"] = json_db(psnr_method);
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
    std::printf("%s: %zu vertices, %zu triangles, PSNR %.2f dB (linear interpolant), %.3f s\n", c.output.c_str(),
                r.vertices, r.triangles, r.psnr, e.seconds);
  }
}

int encode_image(const CLI::App& app, const Command& c) {
  check_usage(app);
  EncodeOptions o = encode_options(app, c);
  ProgressBar bar;
  if (!c.quiet && isatty(STDERR_FILENO)) o.progress = [&bar](double f) { bar(f); };
  const Image image = read_image(c.input, limits::max_encode_pixels);
  check_encodable(c.input, image);
  check_conflicts(app, c.grey || image.channels == 1);
  const PanelPicture panel = panel_picture(c, image);
  Encoded e;
  if (c.max_bytes) {
    e = encode_to_budget(c, panel, o);
  } else {
    e.result = encode_picture(c, panel.picture, o);
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
