// trisim: render triangulation files, compare renders with originals, measure images.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/tool_main.h"
#include "io/image_io.h"
#include "io/tri_file.h"
#include "metrics/metrics.h"
#include "reference/render.h"

using namespace tristream;

namespace {

struct RenderRequest {
  std::string input;
  std::string method = "bilinear";
  std::string engine = "reference";
  std::string variant;
  int width = 0;
  int height = 0;
  int background = 0;
};

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : reference_methods()) names.emplace_back(m.name);
  return names;
}

void add_render_options(CLI::App* cmd, RenderRequest& req) {
  cmd->add_option("input", req.input, "Triangulation file (.tri)")->required();
  cmd->add_option("-m,--method", req.method, "Interpolation method")
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  cmd->add_option("-e,--engine", req.engine, "Renderer: the double-precision reference")
      ->check(CLI::IsMember({"reference"}))
      ->capture_default_str();
  cmd->add_option("--variant", req.variant, "Method variant (e.g. 'thesis' for the patch methods)");
  cmd->add_option("--width", req.width, "Output width (default: the triangulation's; mapped corner to corner)")
      ->check(CLI::Range(1, 65535));
  cmd->add_option("--height", req.height, "Output height (default: the triangulation's)")->check(CLI::Range(1, 65535));
  cmd->add_option("--background", req.background, "Value of pixels outside the triangulation")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();
}

struct Rendered {
  Image image;
  double ms = 0;
};

Rendered render(const Triangulation& tri, const RenderRequest& req) {
  const MethodInfo* method = find_reference_method(req.method);
  if (!method) throw UsageError("unknown method '" + req.method + "'");
  RenderOptions options;
  options.width = req.width;
  options.height = req.height;
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"trisim: render triangulation-represented images and measure them"};
  app.require_subcommand(1);

  RenderRequest render_req;
  std::string render_output;
  auto* render_cmd = app.add_subcommand("render", "Render a triangulation to a PNG image");
  add_render_options(render_cmd, render_req);
  render_cmd->add_option("-o,--output", render_output, "Output PNG")->required();

  RenderRequest compare_req;
  std::vector<std::string> compare_methods;
  std::string compare_original, compare_window = "gaussian", compare_save;
  bool compare_json = false;
  auto* compare_cmd = app.add_subcommand(
      "compare", "Render a triangulation with one or more methods and compare each render with the original");
  add_render_options(compare_cmd, compare_req);
  compare_cmd->remove_option(compare_cmd->get_option("--method"));
  std::vector<std::string> method_choices = method_names();
  method_choices.push_back("all");
  compare_cmd->add_option("-m,--method", compare_methods, "Interpolation methods, or 'all' (default: bilinear)")
      ->check(CLI::IsMember(method_choices));
  compare_cmd->add_option("--save", compare_save, "Also write each render as <dir>/<method>.png")
      ->check(CLI::ExistingDirectory);
  compare_cmd->add_option("--original", compare_original, "Original image")->required();
  compare_cmd->add_option("--ssim-window", compare_window, "SSIM window: 'gaussian' (11x11, sigma 1.5) or '8x8'")
      ->check(CLI::IsMember({"gaussian", "8x8"}))
      ->capture_default_str();
  compare_cmd->add_flag("--json", compare_json, "Print one JSON object per method, one per line");

  std::string metrics_a, metrics_b, metrics_window = "gaussian";
  bool metrics_json_out = false;
  auto* metrics_cmd = app.add_subcommand("metrics", "MSE, PSNR and SSIM of two images of equal size");
  metrics_cmd->add_option("a", metrics_a, "First image")->required();
  metrics_cmd->add_option("b", metrics_b, "Second image")->required();
  metrics_cmd->add_option("--ssim-window", metrics_window, "SSIM window: 'gaussian' (11x11, sigma 1.5) or '8x8'")
      ->check(CLI::IsMember({"gaussian", "8x8"}))
      ->capture_default_str();
  metrics_cmd->add_flag("--json", metrics_json_out, "Print one JSON object");

  return run_tool("trisim", app, argc, argv, [&]() -> int {
    if (*render_cmd) {
      const Triangulation tri = read_tri_file(render_req.input);
      const Rendered r = render(tri, render_req);
      write_png(render_output, r.image);
      std::fprintf(stderr, "trisim: %s %dx%d with %s (%s) in %.1f ms\n", render_output.c_str(), r.image.width,
                   r.image.height, render_req.method.c_str(), render_req.engine.c_str(), r.ms);
      return exit_ok;
    }
    if (*compare_cmd) {
      const Triangulation tri = read_tri_file(compare_req.input);
      if (compare_methods.empty()) compare_methods = {"bilinear"};
      if (std::find(compare_methods.begin(), compare_methods.end(), "all") != compare_methods.end())
        compare_methods = method_names();
      const SsimOptions so = ssim_options(compare_window);
      std::size_t vertices = 0, triangles = 0;
      for (const Mesh& mesh : tri.layers) vertices += mesh.vertex_count(), triangles += mesh.triangles.size();
      if (!compare_json)
        std::printf("%-14s %-10s %10s %10s %9s %10s\n", "method", "engine", "mse", "psnr_db", "ssim", "ms");
      Image original;
      for (const std::string& method : compare_methods) {
        RenderRequest req = compare_req;
        req.method = method;
        const Rendered r = render(tri, req);
        if (original.pixels.empty()) original = load_original(compare_original, tri, r.image.width, r.image.height);
        const Metrics m = compare_images(r.image, original, so);
        if (!compare_save.empty()) write_png(compare_save + "/" + method + ".png", r.image);
        if (compare_json) {
          nlohmann::json j = metrics_json(m, so);
          j["method"] = method;
          j["engine"] = req.engine;
          j["variant"] = req.variant;
          j["ms"] = r.ms;
          j["width"] = r.image.width;
          j["height"] = r.image.height;
          j["vertices"] = vertices;
          j["triangles"] = triangles;
          std::printf("%s\n", j.dump().c_str());
        } else {
          std::printf("%-14s %-10s %10.4f %10.4f %9.6f %10.3f\n", method.c_str(), req.engine.c_str(), m.mse,
                      is_identical_psnr(m.psnr) ? INFINITY : m.psnr, m.ssim, r.ms);
        }
        std::fflush(stdout);
      }
      if (!compare_json)
        std::printf("# %zu vertices, %zu triangles; SSIM %s\n", vertices, triangles,
                    so.window == SsimWindow::gaussian11 ? "Gaussian 11x11, sigma 1.5" : "uniform 8x8");
      return exit_ok;
    }
    const Image a = read_image(metrics_a);
    Image b = read_image(metrics_b);
    if (a.channels == 1 && b.channels == 3) b = to_grey(b);
    Image a2 = (a.channels == 3 && b.channels == 1) ? to_grey(a) : a;
    if (a2.width != b.width || a2.height != b.height)
      throw DataError(metrics_b + ": expected an image of " + std::to_string(a2.width) + "x" +
                      std::to_string(a2.height) + " like " + metrics_a + ", found " + std::to_string(b.width) + "x" +
                      std::to_string(b.height));
    const SsimOptions so = ssim_options(metrics_window);
    const Metrics m = compare_images(a2, b, so);
    if (metrics_json_out) std::printf("%s\n", metrics_json(m, so).dump().c_str());
    else print_metrics(m, so);
    return exit_ok;
  });
}
