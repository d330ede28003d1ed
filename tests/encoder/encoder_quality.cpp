// SPDX-License-Identifier: MIT
// Quality of the encoder (issue 4): prints a Markdown table of PSNR / SSIM (Wang 2004
// Gaussian 11x11, metrics.h default) of bilinear and zienkiewicz reference renders, for
// adaptive sampling (plain Garland-Heckbert, improved, improved + least squares with and
// without the relocation post-pass) beside a regular grid of the same vertex count, at 0.5,
// 1, 2 and 5 % of the pixels.
//
//   encoder_quality [images...]
//
// Default images: with TRISTREAM_IMAGES set (tests/support/test_images.h), its grey/boat.png,
// grey/peppers_grey.png, colour/peppers.png and kodak/kodim23.png; otherwise the shipped
// data/demo/kodim23.png.
//
// With --sweep it compares encoder settings instead: bilinear PSNR (the 8-bit linear
// interpolant against the encoded image) of each setting on every image (default: every image
// of $TRISTREAM_IMAGES/grey and /colour, colour ones as RGB co-triangulations, or the demo image
// when the variable is unset) at each density, then per setting the mean and the smallest gain
// over the first setting.
//
//   encoder_quality --sweep [--settings a,b,...] [--percent p,q,...] [images...]
#include <algorithm>
#include <chrono>
#include <functional>
#include <sstream>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "encoder/encoder.h"
#include "io/image_io.h"
#include "metrics/metrics.h"
#include "reference/render.h"

#include "../support/test_images.h"

using namespace tristream;

namespace {

// Reads `path` into `img`; false, with a SKIPPED line on stderr, when the image is absent.
bool read_if_present(const std::string& path, Image& img) {
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "encoder_quality: SKIPPED %s (absent)\n", path.c_str());
    return false;
  }
  img = read_image(path);
  return true;
}

struct Row {
  std::string label;
  Triangulation tri;
  double seconds = 0;
};

void print_row(const std::string& image, double percent, const Row& row, const Image& original) {
  std::printf("| %s | %.1f | %zu | %s |", image.c_str(), percent,
              row.tri.layers[0].vertex_count() * row.tri.layers.size(), row.label.c_str());
  for (const char* method : {"bilinear", "zienkiewicz"}) {
    const Image render = render_reference(row.tri, *find_reference_method(method), {});
    const Metrics m = compare_images(render, encoded_original(original, row.tri));
    std::printf(" %.2f | %.4f |", m.psnr, m.ssim);
  }
  std::printf(" %.3f |\n", row.seconds);
  std::fflush(stdout);
}

Row encoded(const Image& img, const std::string& label, EncodeOptions o) {
  EncodeResult r = encode(img, o);
  return {label, std::move(r.triangulation), r.seconds};
}

struct Setting {
  const char* name;
  std::function<void(EncodeOptions&)> apply;
};

// The settings --sweep compares; the first is the reference of the gains.
const std::vector<Setting>& settings() {
  static const std::vector<Setting> all = {
      {"before", [](EncodeOptions& o) { o.relocate_passes = 0, o.flip_rounds = 0; }},  // no post-pass
      {"delaunay", [](EncodeOptions& o) { o.flip_rounds = 0; }},  // relocation, no edge flips
      {"default", [](EncodeOptions&) {}},
      {"flips1", [](EncodeOptions& o) { o.flip_rounds = 1; }},
      {"flips3", [](EncodeOptions& o) { o.flip_rounds = 3; }},
      {"reloc1", [](EncodeOptions& o) { o.relocate_passes = 1; }},
      {"reloc2", [](EncodeOptions& o) { o.relocate_passes = 2; }},
      {"reloc3", [](EncodeOptions& o) { o.relocate_passes = 3; }},
      {"reloc4", [](EncodeOptions& o) { o.relocate_passes = 4; }},
      {"reloc6", [](EncodeOptions& o) { o.relocate_passes = 6; }},
      {"reloc8", [](EncodeOptions& o) { o.relocate_passes = 8; }},
      {"reloc4_sigma0", [](EncodeOptions& o) { o.relocate_passes = 4, o.smoothing_sigma = 0; }},
      {"reloc4_sigma1", [](EncodeOptions& o) { o.relocate_passes = 4, o.smoothing_sigma = 1; }},
      {"sigma0", [](EncodeOptions& o) { o.smoothing_sigma = 0; }},
      {"sigma0.75", [](EncodeOptions& o) { o.smoothing_sigma = 0.75; }},
      {"sigma1", [](EncodeOptions& o) { o.smoothing_sigma = 1; }},
  };
  return all;
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// The default images of the table: four shared photographs, or the demo without them.
std::vector<std::string> default_images() {
  if (test::shared_images_dir().empty()) {
    std::fprintf(stderr, "encoder_quality: %s is unset: the demo image only\n", test::images_variable);
    return {test::demo_image()};
  }
  std::vector<std::string> paths;
  for (const char* p : {"grey/boat.png", "grey/peppers_grey.png", "colour/peppers.png", "kodak/kodim23.png"})
    paths.push_back(test::shared_images_dir() + "/" + p);
  return paths;
}

// The default images of --sweep: every PNG of $TRISTREAM_IMAGES/grey and /colour, or the demo.
std::vector<std::string> default_sweep_images() {
  if (test::shared_images_dir().empty()) {
    std::fprintf(stderr, "encoder_quality: %s is unset: the demo image only\n", test::images_variable);
    return {test::demo_image()};
  }
  std::vector<std::string> paths;
  for (const char* group : {"grey", "colour"}) {
    const std::string dir = test::shared_images_dir() + "/" + group;
    if (!std::filesystem::is_directory(dir)) {
      std::fprintf(stderr, "encoder_quality: SKIPPED %s (absent)\n", dir.c_str());
      continue;
    }
    std::vector<std::string> found;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".png") found.push_back(e.path().string());
    std::sort(found.begin(), found.end());
    paths.insert(paths.end(), found.begin(), found.end());
  }
  return paths;
}

int sweep(std::vector<std::string> args) {
  std::vector<const Setting*> chosen;
  std::vector<double> percents = {0.5, 1, 2, 5};
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--settings" && i + 1 < args.size()) {
      for (const std::string& name : split(args[++i])) {
        auto it = std::find_if(settings().begin(), settings().end(), [&](const Setting& s) { return name == s.name; });
        if (it == settings().end()) {
          std::fprintf(stderr, "encoder_quality: unknown setting %s\n", name.c_str());
          return 64;
        }
        chosen.push_back(&*it);
      }
    } else if (args[i] == "--percent" && i + 1 < args.size()) {
      percents.clear();
      for (const std::string& p : split(args[++i])) percents.push_back(std::stod(p));
    } else {
      paths.push_back(args[i]);
    }
  }
  if (chosen.empty())
    for (const Setting& s : settings()) chosen.push_back(&s);
  if (paths.empty()) paths = default_sweep_images();
  std::printf("| image | %% pixels |");
  for (const Setting* s : chosen) std::printf(" %s |", s->name);
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < chosen.size(); ++i) std::printf("---|");
  std::printf("\n");
  // gains[setting][percent]: gain over the first setting per image.
  std::vector<std::vector<std::vector<double>>> gains(chosen.size(), std::vector<std::vector<double>>(percents.size()));
  std::vector<double> seconds(chosen.size(), 0);
  for (const std::string& path : paths) {
    Image img;
    if (!read_if_present(path, img)) continue;
    const std::string name = std::filesystem::path(path).filename().string();
    const std::size_t pixels = std::size_t(img.width) * img.height;
    for (std::size_t k = 0; k < percents.size(); ++k) {
      std::printf("| %s | %.1f |", name.c_str(), percents[k]);
      double first = 0;
      for (std::size_t s = 0; s < chosen.size(); ++s) {
        EncodeOptions o;
        o.vertices = std::size_t(pixels * percents[k] / 100 + 0.5);
        chosen[s]->apply(o);
        const EncodeResult r = encode(img, o);
        if (s == 0) first = r.psnr;
        gains[s][k].push_back(r.psnr - first);
        seconds[s] += r.seconds;
        std::printf(" %.2f |", r.psnr);
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  }
  std::printf("\nGain over %s in dB, mean (smallest) over the images; encode time summed:\n\n| setting |",
              chosen[0]->name);
  for (double p : percents) std::printf(" %.1f %% |", p);
  std::printf(" all | seconds |\n|---|");
  for (std::size_t k = 0; k <= percents.size(); ++k) std::printf("---|");
  std::printf("---|\n");
  for (std::size_t s = 0; s < chosen.size(); ++s) {
    std::printf("| %s |", chosen[s]->name);
    double total = 0, low = 1e9;
    std::size_t count = 0;
    for (std::size_t k = 0; k < percents.size(); ++k) {
      const auto& g = gains[s][k];
      double sum = 0, min = 1e9;
      for (double v : g) sum += v, min = std::min(min, v);
      total += sum, count += g.size(), low = std::min(low, min);
      std::printf(" %+.2f (%+.2f) |", g.empty() ? 0 : sum / double(g.size()), g.empty() ? 0 : min);
    }
    std::printf(" %+.2f (%+.2f) | %.1f |\n", count ? total / double(count) : 0, count ? low : 0, seconds[s]);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--sweep") return sweep(std::vector<std::string>(argv + 2, argv + argc));
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty()) paths = default_images();
  std::printf("| image | %% pixels | vertices | sampling | bilinear PSNR | bilinear SSIM | zienkiewicz PSNR | "
              "zienkiewicz SSIM | encode s |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& path : paths) {
    Image img;
    if (!read_if_present(path, img)) continue;
    const std::string name = std::filesystem::path(path).filename().string();
    const std::size_t pixels = std::size_t(img.width) * img.height;
    for (double percent : {0.5, 1.0, 2.0, 5.0}) {
      const std::size_t n = std::size_t(pixels * percent / 100 + 0.5);
      EncodeOptions plain;
      plain.vertices = n;
      plain.fit = VertexFit::pixel;
      plain.rank_by_total_error = false;
      plain.smoothing_sigma = 0;
      EncodeOptions improved;  // sigma 1 with pixel values
      improved.vertices = n;
      improved.fit = VertexFit::pixel;
      EncodeOptions lsq;  // the default: least squares, sigma 0.5
      lsq.vertices = n;
      plain.relocate_passes = 0;
      plain.flip_rounds = 0;
      EncodeOptions plain_lsq = plain;
      plain_lsq.fit = VertexFit::lsq;
      EncodeOptions no_relocation = lsq;
      no_relocation.relocate_passes = 0;
      no_relocation.flip_rounds = 0;
      EncodeOptions no_flips = lsq;
      no_flips.flip_rounds = 0;
      const ColorSpace space = img.channels == 1 ? ColorSpace::grey : ColorSpace::rgb;
      std::vector<Row> rows;
      auto t0 = std::chrono::steady_clock::now();
      rows.push_back({"grid, pixel values", regular_grid(img, n, space, VertexFit::pixel), 0});
      rows.back().seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      t0 = std::chrono::steady_clock::now();
      rows.push_back({"grid, least squares", regular_grid(img, n, space, VertexFit::lsq), 0});
      rows.back().seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      rows.push_back(encoded(img, "plain G&H, pixel values", plain));
      rows.push_back(encoded(img, "plain G&H, least squares", plain_lsq));
      rows.push_back(encoded(img, "improved, pixel values", improved));
      rows.push_back(encoded(img, "improved, least squares, no relocation", no_relocation));
      rows.push_back(encoded(img, "improved, least squares, relocation, no flips", no_flips));
      rows.push_back(encoded(img, "improved, least squares, relocation, flips (default)", lsq));
      if (img.channels == 3 && percent == 1.0) {
        // Colour variants, all with the default least-squares values.
        EncodeOptions o = lsq;
        o.space = ColorSpace::ycbcr;
        rows.push_back(encoded(img, "YCbCr co-triangulation", o));
        o = lsq;
        o.cotri = CotriMethod::thesis;
        rows.push_back(encoded(img, "thesis co-triangulation (2.4)", o));
        o = lsq;
        o.color = ColorMode::separate;
        o.vertices = n / 3;
        rows.push_back(encoded(img, "separate RGB, n/3 per channel", o));
        o.space = ColorSpace::ycbcr;
        rows.push_back(encoded(img, "separate YCbCr, n/3 per channel", o));
      }
      for (const Row& row : rows) print_row(name, percent, row, img);
    }
  }
  return 0;
}
