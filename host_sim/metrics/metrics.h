/* SPDX-License-Identifier: MIT */
#pragma once
// Full-reference image quality metrics: MSE, PSNR and SSIM of two 8-bit images.
//
// Both images must have the same width, height and channel count; otherwise the functions
// throw DataError ("image sizes differ: expected WxHxC, found W'xH'xC'"). Callers that know
// the file names should catch it and prefix them.
#include "model/image.h"

namespace tristream {

// Mean of the squared differences over every pixel and every channel.
double mse(const Image& a, const Image& b);

// 10 log10(255^2 / mse). Returns +infinity when mse is 0 (identical images).
// Convention for tools: text output prints "inf", JSON output writes null (JSON has no
// infinity); see is_identical_psnr().
double psnr_from_mse(double mse);
double psnr(const Image& a, const Image& b);
// True for the +infinity that psnr_from_mse() returns for identical images.
bool is_identical_psnr(double psnr);

enum class SsimWindow {
  // Wang et al. 2004 (the default): 11x11 Gaussian window, sigma 1.5 (scikit-image's
  // truncate = 3.5, radius int(3.5 * 1.5 + 0.5) = 5), normalised weights.
  gaussian11,
  // The thesis's 8x8 window: uniform weights 1/64, sliding pixel by pixel.
  uniform8,
};

struct SsimOptions {
  SsimWindow window = SsimWindow::gaussian11;
  double k1 = 0.01;
  double k2 = 0.03;
  double data_range = 255.0;
};

// Mean SSIM (MSSIM). For each channel: local weighted means, population variances and
// covariance over every window position that lies entirely inside the image (no
// downsampling), SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))
// with C1 = (k1 * range)^2 and C2 = (k2 * range)^2, averaged over those positions; colour
// images return the mean of the per-channel values.
//
// gaussian11 equals scikit-image's
//   structural_similarity(a, b, gaussian_weights=True, sigma=1.5,
//                         use_sample_covariance=False, data_range=255, channel_axis=-1)
// because skimage crops a border of (win_size - 1) / 2 = 5 pixels before averaging, which is
// exactly the set of pixels whose filter would read past the image (so its 'reflect' padding
// never reaches the mean). uniform8 is the same computation with an 8x8 box window whose
// top-left corner runs over [0, W-8] x [0, H-8]; skimage cannot express it (its win_size must
// be odd), but for an odd box size k this definition equals skimage with win_size=k,
// gaussian_weights=False, use_sample_covariance=False (tested with k = 7).
//
// Throws DataError when the sizes differ or the image is smaller than the window.
double ssim(const Image& a, const Image& b, const SsimOptions& options = {});

// The side of the window of `options` (11, or 8 for uniform8): SSIM needs images at least that
// wide and high. Tools check it first, to name their files.
int ssim_window_side(const SsimOptions& options);

// SSIM with a uniform (box) window of any size k >= 1 (uniform8 is k = 8).
double ssim_uniform(const Image& a, const Image& b, int k, const SsimOptions& options = {});

struct Metrics {
  double mse = 0;
  double psnr = 0;  // +infinity for identical images
  double ssim = 0;
};

Metrics compare_images(const Image& a, const Image& b, const SsimOptions& options = {});

}  // namespace tristream
