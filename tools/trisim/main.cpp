// SPDX-License-Identifier: MIT
// trisim: render triangulation files and blobs, compare renders with originals, measure images.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <optional>
#include <span>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/tool_main.h"
#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"
#include "core_bridge/unpack.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/limits.h"
#include "io/tri_file.h"
#include "metrics/metrics.h"
#include "reference/render.h"
#include "tristream/compressed_blob.h"

using namespace tristream;

namespace {

struct RenderRequest {
  std::string input;
  std::string method = "bilinear";
  std::string engine = "reference";
  std::string variant;
  int width = 0;
  int height = 0;
  std::string fit = "stretch";  // --fit: stretch, inside or fill
  int background = 0;
  int tile = 32;       // --engine core: square tile side, 0 = full frame
  std::string format;  // --engine core: pixel format ("" = l8 for grey, rgb888 for colour)
  bool dither = false;
  const CLI::App* command = nullptr;  // the subcommand, to see which options were given
};

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : reference_methods()) names.emplace_back(m.name);
  return names;
}

void add_render_options(CLI::App* cmd, RenderRequest& req) {
  req.command = cmd;
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
  cmd->add_option("--format", req.format, "Core: pixel format (default l8 for grey, rgb888 for colour)")
      ->check(CLI::IsMember({"l8", "rgb888", "rgb565le", "rgb565be", "xrgb8888"}));
  cmd->add_flag("--dither", req.dither, "Core: Bayer dithering of RGB565");
  cmd->add_option("--variant", req.variant, "Method variant (e.g. 'thesis' for the patch methods)");
  cmd->add_option("--width", req.width, "Output width (default: the triangulation's; mapped corner to corner)")
      ->check(CLI::Range(1, 65535));
  cmd->add_option("--height", req.height, "Output height (default: the triangulation's)")->check(CLI::Range(1, 65535));
  cmd->add_option("--fit", req.fit,
                  "How the picture meets an output of another shape: stretch (corner to corner), inside (one "
                  "scale, centred, a --background border) or fill (one scale, centred, the excess cropped)")
      ->check(CLI::IsMember({"stretch", "inside", "fill"}))
      ->capture_default_str();
  cmd->add_option("--background", req.background, "Value of pixels outside the triangulation")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();
}

// Refuses a render of more than limits::max_image_pixels before anything is allocated: a usage
// error when --width/--height ask for it, a data error when the file's size does.
void check_render_size(const Triangulation& tri, const RenderRequest& req) {
  const std::uint64_t w = req.width ? req.width : tri.width, h = req.height ? req.height : tri.height;
  if (w * h <= limits::max_image_pixels) return;
  const std::string what = "a render of at most " + std::to_string(limits::max_image_pixels) +
                           " pixels (the limit for a render), found " + std::to_string(w) + "x" + std::to_string(h);
  if (req.width || req.height) throw UsageError("--width/--height: expected " + what);
  throw DataError(req.input + ": expected " + what + " (the file's size; --width and --height render smaller)");
}

// Options that would be ignored are usage errors: the core's options with the reference engine,
// a method variant with the core, dithering of a format that is not RGB565.
void check_engine_options(const RenderRequest& req) {
  const CLI::App& cmd = *req.command;
  if (req.engine == "reference") {
    for (const char* core_only : {"--tile", "--format", "--dither", "--raw"})
      if (cmd.get_option_no_throw(core_only) && cmd.count(core_only))
        throw UsageError(std::string(core_only) + ": applies to --engine core only");
    return;
  }
  if (!req.variant.empty()) throw UsageError("--variant: applies to --engine reference only");
  if (req.dither && req.format != "rgb565le" && req.format != "rgb565be")
    throw UsageError("--dither: applies to --format rgb565le and rgb565be only");
}

// What the input file holds: a .tri, or a blob whose bytes the core renders as they are (a
// compressed blob from its streams, band by band; its v1 expansion, made by the core's
// expand_compressed_blob, serves the mesh, the checks and bench's side-by-side v1 timing).
struct Input {
  Triangulation tri;  // for a blob: its size and colour space, and with the mesh read back (unpack_blob) when needed
  std::vector<std::uint8_t> blob;  // the v1 blob's bytes when the file is a blob, else empty
  core::Method blob_method = core::Method::bilinear;
  bool compressed = false;           // the file is a compressed blob (TSTC) and `blob` its expansion
  std::size_t expand_workspace = 0;  // compressed: the ring the expansion needed (expand_workspace_size)
  std::vector<std::uint8_t> compressed_bytes;  // compressed: the file's bytes, which the core renders
  bool is_blob() const { return !blob.empty(); }
};

// Reads a .tri or a blob (by its content). A blob's mesh is read back only when `need_mesh`
// (the reference engine, compare): the core draws blobs whose mesh the reference could not.
Input read_input(const std::string& path, bool need_mesh) {
  const std::string text = read_file(path);
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  Input in;
  if (!tristream::is_blob(bytes)) {
    in.tri = parse_tri(text, path);
    return in;
  }
  in.compressed = core::is_compressed_blob(bytes.data(), bytes.size());
  if (in.compressed) {
    in.blob = expand_compressed_or_throw(bytes, path, &in.expand_workspace);
    in.compressed_bytes.assign(bytes.begin(), bytes.end());
  }
  else
    in.blob.assign(bytes.begin(), bytes.end());
  // Offsets of the checks below are in the file, or for a compressed blob in its expansion.
  const std::string name = in.compressed ? path + " (expanded to v1)" : path;
  const core::Blob blob = open_blob_or_throw(in.blob, name);
  in.blob_method = blob.method;
  if (need_mesh) {
    in.tri = unpack_blob(blob, name).tri;
  } else {
    in.tri.width = blob.width;
    in.tri.height = blob.height;
    in.tri.space = blob.space == core::ColorSpace::grey  ? ColorSpace::grey
                   : blob.space == core::ColorSpace::rgb ? ColorSpace::rgb
                                                         : ColorSpace::ycbcr;
  }
  return in;
}

// A blob goes to the core unless --engine says otherwise, with its own method unless --method
// says otherwise: another method with the core is a usage error (the blob holds what its method
// needs, gradients or not).
void resolve_blob_request(const Input& in, RenderRequest& req, bool method_given) {
  if (!in.is_blob()) return;
  if (!req.command->count("--engine")) req.engine = "core";
  const std::string packed(to_string(in.blob_method));
  if (!method_given) req.method = packed;
  if (req.engine == "core" && req.method != packed)
    throw UsageError("--method " + req.method + ": " + req.input + " is a blob packed for " + packed +
                     ", which the core renders with that method only (--engine reference renders its mesh with any)");
}

// Whether render or bench needs a blob's mesh: with --engine reference (a blob's default engine is
// the core, which draws the blob from its bytes).
bool needs_mesh(const RenderRequest& req) { return req.command->count("--engine") && req.engine == "reference"; }

struct Rendered {
  Image image;
  double ms = 0;
};

CoreOptions core_options(const Triangulation& tri, const RenderRequest& req) {
  CoreOptions o;
  o.width = req.width;
  o.height = req.height;
  o.fit = req.fit == "inside" ? core::Fit::inside : req.fit == "fill" ? core::Fit::fill : core::Fit::stretch;
  o.tile_width = o.tile_height = req.tile;
  o.format = parse_pixel_format(req.format.empty() ? (tri.channels() == 1 ? "l8" : "rgb888") : req.format);
  o.dither = req.dither;
  o.background = static_cast<std::uint8_t>(req.background);
  return o;
}

// The core's frame of the input: a blob's own bytes, a .tri packed for the method.
CoreFrame core_frame(const Input& in, const RenderRequest& req) {
  if (!in.is_blob()) return render_core_frame(in.tri, req.method, core_options(in.tri, req), req.input);
  CoreRenderer renderer(in.compressed ? in.compressed_bytes : in.blob, core_options(in.tri, req), req.input);
  CoreFrame frame;
  renderer.render(frame);
  return frame;
}

// The picture a render is measured by: for a grey triangulation rendered by the core in a colour
// format, the luma of the decoded frame (what an original grey image is compared with).
Rendered render(const Input& in, const RenderRequest& req) {
  const Triangulation& tri = in.tri;
  if (req.engine == "core") {
    const auto t0 = std::chrono::steady_clock::now();
    Image image = frame_to_image(core_frame(in, req));
    if (tri.channels() == 1 && image.channels == 3) image = to_grey(image);
    Rendered out{std::move(image), 0};
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  const MethodInfo* method = find_reference_method(req.method);
  if (!method) throw UsageError("unknown method '" + req.method + "'");
  RenderOptions options;
  options.width = req.width;
  options.height = req.height;
  options.fit = req.fit == "inside" ? Fit::inside : req.fit == "fill" ? Fit::fill : Fit::stretch;
  options.variant = req.variant;
  options.background = static_cast<std::uint8_t>(req.background);
  const auto t0 = std::chrono::steady_clock::now();
  Rendered out{render_reference(tri, *method, options), 0};
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
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

struct RenderCommand {
  RenderRequest req;
  std::string output;
  bool raw = false;  // --engine core: the frame's bytes instead of a PNG
};

struct CompareCommand {
  RenderRequest req;
  std::vector<std::string> methods;
  std::string original, window = "gaussian", save;
  bool json = false;
};

struct BenchCommand {
  RenderRequest req;
  bool json = false;
  int runs = 0;  // 0: as many as fit in about 2 s
};

struct MetricsCommand {
  std::string a, b, window = "gaussian";
  bool json = false;
};

CLI::App* add_render_command(CLI::App& app, RenderCommand& c) {
  auto* cmd = app.add_subcommand("render", "Render a triangulation to a PNG image");
  add_render_options(cmd, c.req);
  cmd->add_option("-o,--output", c.output, "Output PNG (with --raw: the frame's bytes)")->required();
  cmd->add_flag("--raw", c.raw,
                "Core: write the frame's bytes as they would go to the display (rows packed, in --format) "
                "instead of a PNG");
  return cmd;
}

CLI::App* add_compare_command(CLI::App& app, CompareCommand& c) {
  auto* cmd = app.add_subcommand(
      "compare", "Render a triangulation with one or more methods and compare each render with the original");
  add_render_options(cmd, c.req);
  cmd->remove_option(cmd->get_option("--method"));
  std::vector<std::string> method_choices = method_names();
  method_choices.push_back("all");
  cmd->add_option("-m,--method", c.methods, "Interpolation methods, or 'all' (default: bilinear)")
      ->check(CLI::IsMember(method_choices));
  cmd->add_option("--save", c.save, "Also write each render as <dir>/<method>.png")->check(CLI::ExistingDirectory);
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
  add_render_options(cmd, c.req);
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
  return cmd;
}

// Writes what the render produces: with the core, the frame in its pixel format (a PNG of the
// decoded values, RGB for every format but l8, or with --raw the bytes themselves).
int run_render(RenderCommand& c) {
  const Input in = read_input(c.req.input, needs_mesh(c.req));
  resolve_blob_request(in, c.req, c.req.command->count("--method") > 0);
  check_engine_options(c.req);
  check_render_size(in.tri, c.req);
  int width = 0, height = 0;
  double ms = 0;
  if (c.req.engine == "core") {
    const auto t0 = std::chrono::steady_clock::now();
    const CoreFrame frame = core_frame(in, c.req);
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (c.raw)
      write_file_atomically(c.output,
                            std::string_view(reinterpret_cast<const char*>(frame.bytes.data()), frame.bytes.size()));
    else
      write_png(c.output, frame_to_image(frame));
    width = frame.width, height = frame.height;
  } else {
    const Rendered r = render(in, c.req);
    write_png(c.output, r.image);
    width = r.image.width, height = r.image.height, ms = r.ms;
  }
  std::fprintf(stderr, "trisim: %s %dx%d with %s (%s) in %.1f ms\n", c.output.c_str(), width, height,
               c.req.method.c_str(), c.req.engine.c_str(), ms);
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

int run_compare(CompareCommand& c) {
  const Input in = read_input(c.req.input, true);
  const bool methods_given = !c.methods.empty();
  if (c.methods.empty()) c.methods = {in.is_blob() ? std::string(to_string(in.blob_method)) : "bilinear"};
  if (std::find(c.methods.begin(), c.methods.end(), "all") != c.methods.end()) c.methods = method_names();
  for (const std::string& method : c.methods) {
    c.req.method = method;
    resolve_blob_request(in, c.req, methods_given);
  }
  check_engine_options(c.req);
  if (c.original.empty() && c.req.engine != "core")
    throw UsageError("--original: required unless --engine core (which is measured against the reference)");
  const Triangulation& tri = in.tri;
  check_render_size(tri, c.req);
  const SsimOptions so = ssim_options(c.window);
  std::size_t vertices = 0, triangles = 0;
  for (const Mesh& mesh : tri.layers) vertices += mesh.vertex_count(), triangles += mesh.triangles.size();
  if (!c.json) std::printf("%-14s %-10s %10s %10s %9s %10s\n", "method", "engine", "mse", "psnr_db", "ssim", "ms");
  Image original;
  for (const std::string& method : c.methods) {
    RenderRequest req = c.req;
    req.method = method;
    const Comparison cmp = compare_method(in, req, c, so, original);
    if (!c.save.empty()) write_png(c.save + "/" + method + ".png", cmp.render.image);
    print_comparison(cmp, req, so, c.json, vertices, triangles);
  }
  if (!c.json)
    std::printf("# %zu vertices, %zu triangles; SSIM %s\n", vertices, triangles,
                so.window == SsimWindow::gaussian11 ? "Gaussian 11x11, sigma 1.5" : "uniform 8x8");
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
  const Input in = read_input(c.req.input, needs_mesh(c.req));
  resolve_blob_request(in, c.req, c.req.command->count("--method") > 0);
  check_engine_options(c.req);
  const Triangulation& tri = in.tri;
  check_render_size(tri, c.req);
  std::function<int()> once;  // renders one frame, returns its pixel count
  std::optional<CoreRenderer> core_renderer;
  CoreFrame frame;
  std::vector<std::uint8_t> blob;  // read in place by the core: outlives core_renderer
  std::optional<Timings> v1;       // a compressed blob: the same frames from its v1 expansion
  std::size_t v1_ram = 0;
  if (c.req.engine == "core") {
    blob = in.compressed ? in.compressed_bytes
           : in.is_blob() ? in.blob
                          : pack_blob(tri, parse_core_method(c.req.method), c.req.input);
    core_renderer.emplace(blob, core_options(tri, c.req), c.req.input);
    if (in.compressed) {
      CoreRenderer expanded(in.blob, core_options(tri, c.req), c.req.input);
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
      const Image image = render(in, c.req).image;
      return image.width * image.height;
    };
  }
  const Timings t = time_frames(once, c.runs);
  const double median = median_of(t.ms), cpu_median = median_of(t.cpu_ms);
  const double fastest = *std::min_element(t.ms.begin(), t.ms.end());
  const double mpix = t.pixels / (median * 1e-3) * 1e-6;
  if (c.json) {
    nlohmann::json j;
    j["method"] = c.req.method;
    j["engine"] = c.req.engine;
    j["runs"] = t.ms.size();
    j["pixels"] = t.pixels;
    j["ms_median"] = median;
    j["ms_min"] = fastest;
    j["cpu_ms_median"] = cpu_median;
    j["mpix_per_s"] = mpix;
    if (core_renderer) {
      j["tile"] = c.req.tile;
      j["format"] = c.req.format.empty() ? (tri.channels() == 1 ? "l8" : "rgb888") : c.req.format;
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
                c.req.method.c_str(), c.req.engine.c_str(), median, t.ms.size(), cpu_median, fastest, mpix);
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
  const Metrics m = compare_images(a2, b, so);
  if (c.json) std::printf("%s\n", metrics_json(m, so).dump().c_str());
  else print_metrics(m, so);
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"trisim: render triangulation-represented images and measure them"};
  app.require_subcommand(1);
  RenderCommand render_c;
  CompareCommand compare_c;
  BenchCommand bench_c;
  MetricsCommand metrics_c;
  const CLI::App* render_cmd = add_render_command(app, render_c);
  const CLI::App* compare_cmd = add_compare_command(app, compare_c);
  const CLI::App* bench_cmd = add_bench_command(app, bench_c);
  add_metrics_command(app, metrics_c);
  return run_tool("trisim", app, argc, argv, [&]() -> int {
    if (*render_cmd) return run_render(render_c);
    if (*bench_cmd) return run_bench(bench_c);
    if (*compare_cmd) return run_compare(compare_c);
    return run_metrics(metrics_c);
  });
}
