// SPDX-License-Identifier: MIT
#include "metrics/metrics.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "common/errors.h"

namespace tristream {
namespace {

std::string describe(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
         std::to_string(image.channels);
}

void require_same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw DataError("image sizes differ: expected " + describe(a) + ", found " + describe(b));
  if (a.pixels.size() != std::size_t(a.width) * a.height * a.channels ||
      b.pixels.size() != a.pixels.size())
    throw DataError("image pixel buffer does not match its size " + describe(a));
}

// Weights of scipy.ndimage.gaussian_filter1d(sigma, truncate) as skimage calls it:
// exp(-x^2 / (2 sigma^2)) for x in [-r, r], r = int(truncate * sigma + 0.5), normalised.
std::vector<double> gaussian_weights(double sigma, double truncate) {
  const int r = static_cast<int>(truncate * sigma + 0.5);
  std::vector<double> w(2 * r + 1);
  double sum = 0;
  for (int x = -r; x <= r; ++x) sum += w[x + r] = std::exp(-0.5 / (sigma * sigma) * x * x);
  for (double& v : w) v /= sum;
  return w;
}

// The five local statistics of a window position, each a weighted mean.
enum Stat { sx, sy, sxx, syy, sxy, stat_count };

// Mean SSIM of channel c over all positions of the separable window w x w that lie inside
// the image. Horizontal pass per row into a ring of k rows, vertical pass per output row:
// O(k) per pixel and statistic, memory O(k * W).
double channel_ssim(const Image& a, const Image& b, int c, const std::vector<double>& w,
                    const SsimOptions& options) {
  const int k = static_cast<int>(w.size());
  const int width = a.width;
  const int out_w = width - k + 1;
  const int out_h = a.height - k + 1;
  const double c1 = (options.k1 * options.data_range) * (options.k1 * options.data_range);
  const double c2 = (options.k2 * options.data_range) * (options.k2 * options.data_range);

  std::array<std::vector<double>, stat_count> row;
  for (auto& r : row) r.resize(width);
  // ring[(y % k) * stat_count + s] holds the horizontal pass of statistic s for image row y.
  std::vector<std::vector<double>> ring(std::size_t(k) * stat_count, std::vector<double>(out_w));
  std::array<std::vector<double>, stat_count> acc;
  for (auto& r : acc) r.resize(out_w);

  double total = 0;
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* pa = &a.pixels[std::size_t(y) * width * a.channels + c];
    const std::uint8_t* pb = &b.pixels[std::size_t(y) * width * b.channels + c];
    for (int x = 0; x < width; ++x) {
      const double va = pa[std::size_t(x) * a.channels];
      const double vb = pb[std::size_t(x) * b.channels];
      row[sx][x] = va;
      row[sy][x] = vb;
      row[sxx][x] = va * va;
      row[syy][x] = vb * vb;
      row[sxy][x] = va * vb;
    }
    for (int s = 0; s < stat_count; ++s) {
      double* out = ring[std::size_t(y % k) * stat_count + s].data();
      const double* in = row[s].data();
      for (int x = 0; x < out_w; ++x) out[x] = w[0] * in[x];
      for (int i = 1; i < k; ++i) {
        const double wi = w[i];
        for (int x = 0; x < out_w; ++x) out[x] += wi * in[x + i];
      }
    }
    const int y0 = y - k + 1;  // output row completed by image row y
    if (y0 < 0) continue;
    for (int s = 0; s < stat_count; ++s) {
      double* out = acc[s].data();
      const double* in0 = ring[std::size_t(y0 % k) * stat_count + s].data();
      for (int x = 0; x < out_w; ++x) out[x] = w[0] * in0[x];
      for (int i = 1; i < k; ++i) {
        const double wi = w[i];
        const double* in = ring[std::size_t((y0 + i) % k) * stat_count + s].data();
        for (int x = 0; x < out_w; ++x) out[x] += wi * in[x];
      }
    }
    double row_sum = 0;
    for (int x = 0; x < out_w; ++x) {
      const double ux = acc[sx][x], uy = acc[sy][x];
      const double vx = acc[sxx][x] - ux * ux;
      const double vy = acc[syy][x] - uy * uy;
      const double vxy = acc[sxy][x] - ux * uy;
      row_sum += ((2 * ux * uy + c1) * (2 * vxy + c2)) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
    }
    total += row_sum;
  }
  return total / (double(out_w) * out_h);
}

double windowed_ssim(const Image& a, const Image& b, const std::vector<double>& w,
                     const SsimOptions& options) {
  require_same_size(a, b);
  const int k = static_cast<int>(w.size());
  if (a.width < k || a.height < k)
    throw DataError("image too small for SSIM: expected at least " + std::to_string(k) + "x" +
                    std::to_string(k) + " pixels, found " + describe(a));
  if (a.channels < 1) throw DataError("image has no channels: " + describe(a));
  double sum = 0;
  for (int c = 0; c < a.channels; ++c) sum += channel_ssim(a, b, c, w, options);
  return sum / a.channels;
}

}  // namespace

double mse(const Image& a, const Image& b) {
  require_same_size(a, b);
  if (a.pixels.empty()) throw DataError("empty image: " + describe(a));
  // Exact integer sum: at most 65025 per sample, so 2^64 covers over 2^47 samples.
  unsigned long long sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const int d = int(a.pixels[i]) - int(b.pixels[i]);
    sum += static_cast<unsigned long long>(d * d);
  }
  return double(sum) / double(a.pixels.size());
}

double psnr_from_mse(double mse) {
  if (mse <= 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

double psnr(const Image& a, const Image& b) { return psnr_from_mse(mse(a, b)); }

bool is_identical_psnr(double psnr) { return std::isinf(psnr) && psnr > 0; }

int ssim_window_side(const SsimOptions& options) { return options.window == SsimWindow::uniform8 ? 8 : 11; }

double ssim(const Image& a, const Image& b, const SsimOptions& options) {
  switch (options.window) {
    case SsimWindow::uniform8: return ssim_uniform(a, b, 8, options);
    case SsimWindow::gaussian11: break;
  }
  static const std::vector<double> w = gaussian_weights(1.5, 3.5);
  return windowed_ssim(a, b, w, options);
}

double ssim_uniform(const Image& a, const Image& b, int k, const SsimOptions& options) {
  if (k < 1) throw UsageError("SSIM window size: expected at least 1, found " + std::to_string(k));
  return windowed_ssim(a, b, std::vector<double>(k, 1.0 / k), options);
}

Metrics compare_images(const Image& a, const Image& b, const SsimOptions& options) {
  Metrics m;
  m.mse = mse(a, b);
  m.psnr = psnr_from_mse(m.mse);
  m.ssim = ssim(a, b, options);
  return m;
}

}  // namespace tristream
