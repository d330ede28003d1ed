// Quality of the encoder (issue 4): prints a Markdown table of PSNR / SSIM (Wang 2004
// Gaussian 11x11, metrics.h default) of bilinear and zienkiewicz reference renders, for
// adaptive sampling (plain Garland-Heckbert, improved, improved + least squares) beside a
// regular grid of the same vertex count, at 0.5, 1, 2 and 5 % of the pixels.
//
//   encoder_quality [images...]   (default: the three images in /work/shared/images)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "encoder/encoder.h"
#include "io/image_io.h"
#include "metrics/metrics.h"
#include "reference/render.h"

using namespace tristream;

namespace {

struct Row {
  std::string label;
  Triangulation tri;
  double seconds = 0;
};

void print_row(const std::string& image, double percent, const Row& row, const Image& original) {
  std::printf("| %s | %.1f | %zu | %s |", image.c_str(), percent, row.tri.layers[0].vertex_count() * row.tri.layers.size(),
              row.label.c_str());
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

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty())
    for (const char* p : {"grey/boat.png", "grey/peppers_grey.png", "colour/peppers.png", "kodak/kodim23.png"})
      paths.push_back(std::string("/work/shared/images/") + p);
  std::printf("| image | %% pixels | vertices | sampling | bilinear PSNR | bilinear SSIM | zienkiewicz PSNR | "
              "zienkiewicz SSIM | encode s |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& path : paths) {
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "encoder_quality: SKIPPED %s (absent)\n", path.c_str());
      continue;
    }
    const Image img = read_image(path);
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
      EncodeOptions plain_lsq = plain;
      plain_lsq.fit = VertexFit::lsq;
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
      rows.push_back(encoded(img, "improved, least squares (default)", lsq));
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
