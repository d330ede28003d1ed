// SPDX-License-Identifier: MIT
// trisim: render triangulation files and blobs, compare renders with originals, measure images,
// check golden images (golden.cpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <limits>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/cli_validators.h"
#include "common/errors.h"
#include "common/tool_main.h"
#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "core_bridge/render_core.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "metrics/metrics.h"
#include "reference/fit_names.h"
#include "reference/render.h"

#include "golden.h"
#include "picture.h"

using namespace tristream;
using namespace tristream::trisim;

namespace {

// A command's render settings as the command line gives them: the request, and the texts of the
// options that are parsed after CLI11 (parse_request).
struct CliRequest {
  RenderRequest req;
  const CLI::App* command = nullptr;  // the subcommand, to see which options were given
  std::string background = "0", viewport;
};

void add_render_options(CLI::App* cmd, CliRequest& c) {
  RenderRequest& req = c.req;
  c.command = cmd;
  cmd->add_option("input", req.input,
                  "Triangulation file (.tri) or blob (tripack -o x.bin, v1 or --compress; told apart by its first "
                  "bytes): a blob is rendered by the core with its own method unless --engine reference is given "
                  "(a compressed blob is rendered from its streams)")
      ->required();
  cmd->add_option("-m,--method", req.method, "Interpolation method")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("-e,--engine", req.engine,
                  "Renderer: the double-precision reference, or the fixed-point core (bilinear, zienkiewicz)")
      ->check(CLI::IsMember({"reference", "core"}))
      ->capture_default_str();
  cmd->add_option("--tile", req.tile, "Core: square tile side in pixels, 0 = full frame")
      ->check(CLI::Range(0, 2048))
      ->capture_default_str();
  cmd->add_option("--tile-width", req.tile_width,
                  "Core: tile width (default --tile), 0 = the viewport's width (bands), as RenderParams::tile_width")
      ->check(CLI::Range(0, 2048));
  cmd->add_option("--tile-height", req.tile_height,
                  "Core: tile height (default --tile), 0 = the viewport's height, as RenderParams::tile_height")
      ->check(CLI::Range(0, 2048));
  cmd->add_option("--viewport", c.viewport,
                  "Core: the output pixels to render, X0,Y0,X1,Y1 (half-open, as RenderParams::viewport); the "
                  "output is the viewport's size");
  cmd->add_option("--format", req.format, "Core: pixel format (default l8 for grey, rgb888 for colour)")
      ->check(CLI::IsMember(pixel_format_name_list()));
  cmd->add_flag("--dither", req.dither, "Core: Bayer dithering of RGB565");
  cmd->add_option("--variant", req.variant, "Method variant (e.g. 'thesis' for the patch methods)");
  cmd->add_option("--width", req.width, "Output width (default: the triangulation's; mapped corner to corner)")
      ->check(CLI::Range(1, 65535));
  cmd->add_option("--height", req.height, "Output height (default: the triangulation's)")->check(CLI::Range(1, 65535));
  cmd->add_option("--fit", req.fit,
                  "How the picture meets an output of another shape: stretch (corner to corner), inside (one "
                  "scale, centred, a --background border) or fill (one scale, centred, the excess cropped)")
      ->check(CLI::IsMember(fit_name_list()))
      ->capture_default_str();
  cmd->add_option("--background", c.background,
                  "Pixels outside the triangulation: one value for every channel, or R,G,B (a grey render takes "
                  "the first)")
      ->capture_default_str();
}

// The request once CLI11 has parsed the command line: the options given, background and viewport.
RenderRequest& parse_request(CliRequest& c) {
  RenderRequest& req = c.req;
  for (const CLI::Option* o : c.command->get_options())
    if (o->count() > 0 && !o->get_lnames().empty()) req.given.insert("--" + o->get_lnames().front());
  req.background = parse_background(c.background, "--background");
  if (!c.viewport.empty()) req.viewport = parse_viewport(c.viewport, "--viewport");
  return req;
}

// The original as the render sees it: luma when the triangulation is grey.
Image load_original(const std::string& path, const Triangulation& tri, int width, int height) {
  Image original = read_image(path);
  if (tri.channels() == 1) original = to_grey(original);
  if (original.channels != tri.channels())
    throw DataError(path + ": expected a colour image for a " + std::string(to_string(tri.space)) +
                    " triangulation, found a grey one");
  if (original.width != width || original.height != height)
    throw DataError(path + ": expected an image of " + std::to_string(width) + "x" + std::to_string(height) +
                    " (the render size), found " + std::to_string(original.width) + "x" +
                    std::to_string(original.height));
  return original;
}

nlohmann::json metrics_json(const Metrics& m, const SsimOptions& ssim) {
  nlohmann::json j;
  j["mse"] = m.mse;
  j["psnr"] = is_identical_psnr(m.psnr) ? nlohmann::json(nullptr) : nlohmann::json(m.psnr);
  j["ssim"] = m.ssim;
  j["ssim_window"] = ssim.window == SsimWindow::gaussian11 ? "gaussian11" : "uniform8";
  return j;
}

void print_metrics(const Metrics& m, const SsimOptions& ssim) {
  std::printf("mse    %.6f\n", m.mse);
  if (is_identical_psnr(m.psnr)) std::printf("psnr   inf dB\n");
  else std::printf("psnr   %.4f dB\n", m.psnr);
  std::printf("ssim   %.6f (%s)\n", m.ssim,
              ssim.window == SsimWindow::gaussian11 ? "Gaussian 11x11, sigma 1.5" : "uniform 8x8");
}

SsimOptions ssim_options(const std::string& window) {
  SsimOptions o;
  o.window = window == "8x8" ? SsimWindow::uniform8 : SsimWindow::gaussian11;
  return o;
}

// SSIM's window must fit the images: checked before measuring, so that the message names `files`.
void check_ssim_size(int width, int height, const SsimOptions& so, const std::string& files) {
  const int k = ssim_window_side(so);
  if (width >= k && height >= k) return;
  const std::string window = so.window == SsimWindow::uniform8 ? "8x8" : "gaussian";
  throw DataError(files + ": too small for SSIM: expected images of at least " + std::to_string(k) + " x " +
                  std::to_string(k) + " pixels (the window of --ssim-window " + window + "), found " +
                  std::to_string(width) + " x " + std::to_string(height));
}

struct RenderCommand {
  CliRequest cli;
  std::string output;
  bool raw = false;  // --engine core: the frame's bytes instead of a PNG
};

struct CompareCommand {
  CliRequest cli;
  std::vector<std::string> methods;
  std::string original, window = "gaussian", save;
  bool json = false;
};

struct BenchCommand {
  CliRequest cli;
  bool json = false;
  int runs = 0;  // 0: as many as fit in about 2 s
};

struct MetricsCommand {
  std::string a, b, window = "gaussian";
  bool json = false;
  std::optional<double> max_mse, min_psnr;  // thresholds: exit 1 when one is not met
};

CLI::App* add_render_command(CLI::App& app, RenderCommand& c) {
  auto* cmd = app.add_subcommand("render", "Render a triangulation to a PNG image");
  add_render_options(cmd, c.cli);
  cmd->add_option("-o,--output", c.output, "Output PNG (with --raw: the frame's bytes)")->required();
  cmd->add_flag("--raw", c.raw,
                "Core: write the frame's bytes as they would go to the display (rows packed, in --format) "
                "instead of a PNG");
  return cmd;
}

CLI::App* add_compare_command(CLI::App& app, CompareCommand& c) {
  auto* cmd = app.add_subcommand(
      "compare", "Render a triangulation with one or more methods and compare each render with the original");
  add_render_options(cmd, c.cli);
  cmd->remove_option(cmd->get_option("--method"));
  std::vector<std::string> method_choices = method_names();
  method_choices.push_back("all");
  cmd->add_option("-m,--method", c.methods, "Interpolation methods, or 'all' (default: bilinear)")
      ->check(CLI::IsMember(method_choices));
  cmd->add_option("--save", c.save, "Also write each render as <dir>/<method>.png (the directory is created)");
  cmd->add_option("--original", c.original,
                  "Original image (optional with --engine core: the core's render is then measured against the "
                  "reference's alone)");
  cmd->add_option("--ssim-window", c.window, "SSIM window: 'gaussian' (11x11, sigma 1.5) or '8x8'")
      ->check(CLI::IsMember({"gaussian", "8x8"}))
      ->capture_default_str();
  cmd->add_flag("--json", c.json, "Print one JSON object per method, one per line");
  return cmd;
}

CLI::App* add_bench_command(CLI::App& app, BenchCommand& c) {
  auto* cmd = app.add_subcommand(
      "bench",
      "Render repeatedly after a warm-up; print the median ms per frame (wall and CPU), the fastest, and Mpixel/s");
  add_render_options(cmd, c.cli);
  cmd->add_option("--runs", c.runs, "Timed renders (default: as many as fit in about 2 s, 5 to 200)")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--json", c.json, "Print one JSON object");
  return cmd;
}

CLI::App* add_metrics_command(CLI::App& app, MetricsCommand& c) {
  auto* cmd = app.add_subcommand("metrics", "MSE, PSNR and SSIM of two images of equal size");
  cmd->add_option("a", c.a, "First image")->required();
  cmd->add_option("b", c.b, "Second image")->required();
  cmd->add_option("--ssim-window", c.window, "SSIM window: 'gaussian' (11x11, sigma 1.5) or '8x8'")
      ->check(CLI::IsMember({"gaussian", "8x8"}))
      ->capture_default_str();
  cmd->add_flag("--json", c.json, "Print one JSON object");
  cmd->add_option("--max-mse", c.max_mse, "Exit 1 unless the MSE is at most this")
      ->check(finite_in(0, true, std::numeric_limits<double>::max(), "a finite number of at least 0"));
  cmd->add_option("--min-psnr", c.min_psnr, "Exit 1 unless the PSNR (dB; identical images: infinite) is at least this");
  return cmd;
}

// Writes what the render produces: with the core, the frame in its pixel format (a PNG of the
// decoded values, RGB for every format but l8, or with --raw the bytes themselves).
int run_render(RenderCommand& c) {
  RenderRequest& req = parse_request(c.cli);
  const Input in = read_input(req.input, needs_mesh(req));
  resolve_blob_request(in, req, req.was_given("--method"));
  check_engine_options(req);
  check_render_size(in.tri, req);
  int width = 0, height = 0;
  double ms = 0;
  if (req.engine == "core") {
    const auto t0 = std::chrono::steady_clock::now();
    const CoreFrame frame = core_frame(in, req);
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (c.raw)
      write_file_atomically(c.output,
                            std::string_view(reinterpret_cast<const char*>(frame.bytes.data()), frame.bytes.size()));
    else
      write_png(c.output, frame_to_image(frame));
    width = frame.width, height = frame.height;
  } else {
    const Rendered r = render(in, req);
    write_png(c.output, r.image);
    width = r.image.width, height = r.image.height, ms = r.ms;
  }
  std::fprintf(stderr, "trisim: %s %dx%d with %s (%s) in %.1f ms\n", c.output.c_str(), width, height,
               req.method.c_str(), req.engine.c_str(), ms);
  return exit_ok;
}

// One method's render measured against the original (and, for the core, against the reference).
struct Comparison {
  Rendered render;
  Metrics metrics;
  int max_diff_ref = -1;  // -1: not rendered by the core
  double psnr_ref = 0;
  bool has_metrics = false;  // measured against an original
};

// Without an original (--engine core only) the metrics are left out (has_metrics false).
Comparison compare_method(const Input& in, const RenderRequest& req, const CompareCommand& c,
                          const SsimOptions& so, Image& original) {
  Comparison out;
  out.render = render(in, req);
  const Image& image = out.render.image;
  if (!c.original.empty()) {
    if (original.pixels.empty()) original = load_original(c.original, in.tri, image.width, image.height);
    check_ssim_size(original.width, original.height, so, c.original + " (and the render of its size)");
    out.metrics = compare_images(image, original, so);
    out.has_metrics = true;
  }
  if (req.engine == "core") {
    RenderRequest ref = req;
    ref.engine = "reference";
    const Image reference = render(in, ref).image;
    out.max_diff_ref = 0;
    for (std::size_t i = 0; i < reference.pixels.size(); ++i)
      out.max_diff_ref = std::max(out.max_diff_ref, std::abs(int(reference.pixels[i]) - int(image.pixels[i])));
    out.psnr_ref = psnr(image, reference);
  }
  return out;
}

void print_comparison(const Comparison& cmp, const RenderRequest& req, const SsimOptions& so, bool json,
                      std::size_t vertices, std::size_t triangles) {
  const Image& image = cmp.render.image;
  const Metrics& m = cmp.metrics;
  if (json) {
    nlohmann::json j = metrics_json(m, so);
    if (!cmp.has_metrics) j["mse"] = j["psnr"] = j["ssim"] = nullptr;
    j["method"] = req.method;
    j["engine"] = req.engine;
    j["variant"] = req.variant;
    j["ms"] = cmp.render.ms;
    j["width"] = image.width;
    j["height"] = image.height;
    j["vertices"] = vertices;
    j["triangles"] = triangles;
    if (cmp.max_diff_ref >= 0) {
      j["max_abs_diff_vs_reference"] = cmp.max_diff_ref;
      j["psnr_vs_reference"] = is_identical_psnr(cmp.psnr_ref) ? nlohmann::json(nullptr) : nlohmann::json(cmp.psnr_ref);
    }
    std::printf("%s\n", j.dump().c_str());
  } else {
    if (cmp.has_metrics)
      std::printf("%-14s %-10s %10.4f %10.4f %9.6f %10.3f\n", req.method.c_str(), req.engine.c_str(), m.mse,
                  is_identical_psnr(m.psnr) ? INFINITY : m.psnr, m.ssim, cmp.render.ms);
    else
      std::printf("%-14s %-10s %10s %10s %9s %10.3f\n", req.method.c_str(), req.engine.c_str(), "-", "-", "-",
                  cmp.render.ms);
    if (cmp.max_diff_ref >= 0)
      std::printf("%-14s %-10s max |core - reference| %d, PSNR vs reference %.2f dB\n", "", "", cmp.max_diff_ref,
                  is_identical_psnr(cmp.psnr_ref) ? INFINITY : cmp.psnr_ref);
  }
  std::fflush(stdout);
}

// `--method all` with the core: the methods the core renders for this input (a blob's own, or
// bilinear and zienkiewicz), and a note on stderr naming the ones skipped.
std::vector<std::string> core_methods_of_all(const Input& in) {
  const std::vector<std::string> all = method_names();
  std::vector<std::string> kept = core_method_names(), skipped;
  if (in.is_blob()) kept = {std::string(to_string(in.blob_method))};
  for (const std::string& m : all)
    if (std::find(kept.begin(), kept.end(), m) == kept.end()) skipped.push_back(m);
  std::string text;
  for (const std::string& m : skipped) text += (text.empty() ? "" : ", ") + m;
  std::fprintf(stderr, "trisim: --method all with --engine core: %s %s; skipped: %s\n",
               in.is_blob() ? "the blob is packed for" : "the core renders", kept.size() == 1 ? kept[0].c_str()
                                                                                               : "bilinear and zienkiewicz",
               text.c_str());
  return kept;
}

// Measured by `make methods` (tools/experiments/README.md) on 41 photographs at 0.5 to 2 % vertices.
constexpr const char* equal_bytes_note =
    "equal vertices are not equal bytes: at equal compressed-blob bytes bilinear is ahead of zienkiewicz by "
    "1.06 to 1.58 dB and of clough-tocher by 1.24 to 1.79 dB (means over 41 photographs at 0.5 to 2 %, values "
    "and gradients fitted for each; ahead on every one): bilinear is the recommended method";

// The lines after compare's table about the methods that take vertex gradients: where the gradients
// come from, and that equal vertices are not equal bytes (tools/experiments/README.md, "Methods at
// equal bytes", measured by methods_at_equal_bytes.py).
void print_gradient_notes(const std::vector<std::string>& methods, const Input& in) {
  const auto takes_gradients = [](const std::string& m) {
    return m == "zienkiewicz" || m == "clough-tocher" || m == "voronoi";
  };
  if (std::none_of(methods.begin(), methods.end(), takes_gradients)) return;
  bool stored = true;
  for (const Mesh& mesh : in.tri.layers) stored = stored && mesh.has_gradients();
  // A zienkiewicz blob's unpacked mesh has its gradients; a bilinear blob has none.
  std::printf("# gradients: %s\n", !stored        ? "estimated from the surface (thesis Eq. 3.2)"
                                   : in.is_blob() ? "the blob's"
                                                  : "the file's (triencode -m zienkiewicz|clough-tocher fits them)");
  std::printf("# %s\n", equal_bytes_note);
}

int run_compare(CompareCommand& c) {
  RenderRequest& base = parse_request(c.cli);
  const Input in = read_input(base.input, true);
  const bool methods_given = !c.methods.empty();
  if (in.is_blob() && !base.was_given("--engine")) base.engine = "core";
  if (c.methods.empty()) c.methods = {in.is_blob() ? std::string(to_string(in.blob_method)) : "bilinear"};
  if (std::find(c.methods.begin(), c.methods.end(), "all") != c.methods.end())
    c.methods = base.engine == "core" ? core_methods_of_all(in) : method_names();
  for (const std::string& method : c.methods) {  // every method checked before anything is printed
    RenderRequest one = base;
    one.method = method;
    resolve_blob_request(in, one, methods_given);
    check_engine_options(one);
  }
  if (c.original.empty() && base.engine != "core")
    throw UsageError("--original: required unless --engine core (which is measured against the reference)");
  const Triangulation& tri = in.tri;
  check_render_size(tri, base);
  if (!c.save.empty()) make_directories(c.save, "--save");
  const SsimOptions so = ssim_options(c.window);
  std::size_t vertices = 0, triangles = 0;
  for (const Mesh& mesh : tri.layers) vertices += mesh.vertex_count(), triangles += mesh.triangles.size();
  if (!c.json) std::printf("%-14s %-10s %10s %10s %9s %10s\n", "method", "engine", "mse", "psnr_db", "ssim", "ms");
  Image original;
  for (const std::string& method : c.methods) {
    RenderRequest req = base;
    req.method = method;
    const Comparison cmp = compare_method(in, req, c, so, original);
    if (!c.save.empty()) write_png(c.save + "/" + method + ".png", cmp.render.image);
    print_comparison(cmp, req, so, c.json, vertices, triangles);
  }
  if (!c.json) {
    std::printf("# %zu vertices, %zu triangles; SSIM %s\n", vertices, triangles,
                so.window == SsimWindow::gaussian11 ? "Gaussian 11x11, sigma 1.5" : "uniform 8x8");
    print_gradient_notes(c.methods, in);
  }
  return exit_ok;
}

// Wall and thread CPU milliseconds of each timed frame, and the pixels of one frame.
struct Timings {
  std::vector<double> ms, cpu_ms;
  int pixels = 0;
};

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Two warm-up frames, then `runs` timed frames, or when runs is 0 at least 5 and until 2 s or 200 frames.
// The thread's CPU time is less disturbed by other processes than the wall time.
Timings time_frames(const std::function<int()>& once, int runs) {
  Timings t;
  t.pixels = once();
  t.pixels = once();
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const double c0 = thread_cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    t.pixels = once();
    const auto t1 = std::chrono::steady_clock::now();
    t.cpu_ms.push_back(thread_cpu_ms() - c0);
    t.ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    const double elapsed = std::chrono::duration<double>(t1 - start).count();
    if (runs ? int(t.ms.size()) >= runs : (t.ms.size() >= 200 || (t.ms.size() >= 5 && elapsed > 2.0))) break;
  }
  return t;
}

int run_bench(BenchCommand& c) {
  RenderRequest& req = parse_request(c.cli);
  const Input in = read_input(req.input, needs_mesh(req));
  resolve_blob_request(in, req, req.was_given("--method"));
  check_engine_options(req);
  const Triangulation& tri = in.tri;
  check_render_size(tri, req);
  std::function<int()> once;  // renders one frame, returns its pixel count
  std::optional<CoreRenderer> core_renderer;
  CoreFrame frame;
  std::vector<std::uint8_t> blob;  // read in place by the core: outlives core_renderer
  std::optional<Timings> v1;       // a compressed blob: the same frames from its v1 expansion
  std::size_t v1_ram = 0;
  if (req.engine == "core") {
    blob = in.compressed ? in.compressed_bytes
           : in.is_blob() ? in.blob
                          : pack_blob(tri, parse_core_method(req.method), req.input);
    core_renderer.emplace(blob, core_options(tri, req), req.input);
    if (in.compressed) {
      CoreRenderer expanded(in.blob, core_options(tri, req), req.input);
      CoreFrame v1_frame;
      v1 = time_frames(
          [&] {
            expanded.render(v1_frame);
            return v1_frame.width * v1_frame.height;
          },
          c.runs);
      v1_ram = expanded.tile_buffer_bytes() + expanded.workspace_bytes();
    }
    once = [&] {
      core_renderer->render(frame);  // tiles delivered through the sink into a frame
      return frame.width * frame.height;
    };
  } else {
    once = [&] {
      const Image image = render(in, req).image;
      return image.width * image.height;
    };
  }
  const Timings t = time_frames(once, c.runs);
  const double median = median_of(t.ms), cpu_median = median_of(t.cpu_ms);
  const double fastest = *std::min_element(t.ms.begin(), t.ms.end());
  const double mpix = t.pixels / (median * 1e-3) * 1e-6;
  if (c.json) {
    nlohmann::json j;
    j["method"] = req.method;
    j["engine"] = req.engine;
    j["runs"] = t.ms.size();
    j["pixels"] = t.pixels;
    j["ms_median"] = median;
    j["ms_min"] = fastest;
    j["cpu_ms_median"] = cpu_median;
    j["mpix_per_s"] = mpix;
    if (core_renderer) {
      j["tile"] = req.tile;
      j["format"] = std::string(pixel_format_name(pixel_format_of(tri, req)));
      j["ram_bytes"] = core_renderer->tile_buffer_bytes() + core_renderer->workspace_bytes();
      // A compressed blob renders from its streams; its v1 expansion's frames are timed beside.
      if (v1) {
        j["v1_ms_median"] = median_of(v1->ms);
        j["v1_cpu_ms_median"] = median_of(v1->cpu_ms);
        j["v1_ram_bytes"] = v1_ram;
        j["v1_blob_bytes"] = in.blob.size();
        j["cpu_ratio_to_v1"] = cpu_median / median_of(v1->cpu_ms);
      }
    }
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s %s: median %.3f ms per frame over %zu runs (CPU %.3f ms, fastest %.3f ms), %.1f Mpixel/s\n",
                req.method.c_str(), req.engine.c_str(), median, t.ms.size(), cpu_median, fastest, mpix);
    if (v1)
      std::printf("from the stream: RAM %zu bytes; its v1 blob: median %.3f ms (CPU %.3f ms), RAM %zu bytes + blob %zu "
                  "bytes; CPU ratio %.3f\n",
                  core_renderer->tile_buffer_bytes() + core_renderer->workspace_bytes(), median_of(v1->ms),
                  median_of(v1->cpu_ms), v1_ram, in.blob.size(), cpu_median / median_of(v1->cpu_ms));
  }
  return exit_ok;
}

int run_metrics(const MetricsCommand& c) {
  const Image a = read_image(c.a);
  Image b = read_image(c.b);
  if (a.channels == 1 && b.channels == 3) b = to_grey(b);
  Image a2 = (a.channels == 3 && b.channels == 1) ? to_grey(a) : a;
  if (a2.width != b.width || a2.height != b.height)
    throw DataError(c.b + ": expected an image of " + std::to_string(a2.width) + "x" + std::to_string(a2.height) +
                    " like " + c.a + ", found " + std::to_string(b.width) + "x" + std::to_string(b.height));
  const SsimOptions so = ssim_options(c.window);
  check_ssim_size(b.width, b.height, so, c.a + " and " + c.b);
  const Metrics m = compare_images(a2, b, so);
  if (c.json) std::printf("%s\n", metrics_json(m, so).dump().c_str());
  else print_metrics(m, so);
  bool met = true;
  if (c.max_mse && !(m.mse <= *c.max_mse)) {
    std::fprintf(stderr, "trisim: MSE %.6f is above --max-mse %g\n", m.mse, *c.max_mse);
    met = false;
  }
  if (c.min_psnr && !(m.psnr >= *c.min_psnr)) {
    std::fprintf(stderr, "trisim: PSNR %.4f dB is below --min-psnr %g\n", m.psnr, *c.min_psnr);
    met = false;
  }
  return met ? exit_ok : exit_check_failed;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"trisim: render triangulation-represented images and measure them"};
  app.require_subcommand(1);
  RenderCommand render_c;
  CompareCommand compare_c;
  BenchCommand bench_c;
  MetricsCommand metrics_c;
  GoldenCommand golden_c;
  const CLI::App* render_cmd = add_render_command(app, render_c);
  const CLI::App* compare_cmd = add_compare_command(app, compare_c);
  const CLI::App* bench_cmd = add_bench_command(app, bench_c);
  add_metrics_command(app, metrics_c);
  const CLI::App* golden_cmd = add_golden_command(app, golden_c);
  return run_tool("trisim", app, argc, argv, [&]() -> int {
    if (*render_cmd) return run_render(render_c);
    if (*bench_cmd) return run_bench(bench_c);
    if (*compare_cmd) return run_compare(compare_c);
    if (*golden_cmd) return run_golden(golden_c);
    return run_metrics(metrics_c);
  });
}
