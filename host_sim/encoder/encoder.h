/* SPDX-License-Identifier: MIT */
#pragma once
// The encoder: an image in, a triangulation out (greedy insertion, encoder/greedy.h).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "model/image.h"
#include "model/triangulation.h"

namespace tristream {

enum class ColorMode : std::uint8_t {
  co,        // one co-triangulation carrying every channel
  separate,  // one triangulation per channel (a layered file)
};

enum class CotriMethod : std::uint8_t {
  greedy,  // greedy insertion on the squared error summed over the channels
  thesis,  // the thesis's section 2.4: one pass per channel (see encode_thesis_cotri)
};

enum class VertexFit : std::uint8_t {
  pixel,  // vertex values are the pixel values at the vertex positions
  lsq,    // least-squares refit over all pixels, rounded to 8 bits
};

// The method the triangulation will be shown with. The mesh is chosen for the linear interpolant
// (the greedy insertion, relocation and flips score it); zienkiewicz and clough_tocher then fit
// values and gradients on their own basis (encoder/hermite_fit.h) and store the gradients in the
// triangulation. tools/experiments/README.md ("Methods at equal bytes") compares them with bilinear at equal bytes.
enum class FitMethod : std::uint8_t { bilinear, zienkiewicz, clough_tocher };

// The method's name as the tools and the reference spell it (clough_tocher: "clough-tocher"), and
// back (UsageError for another name).
std::string_view to_string(FitMethod method);
FitMethod parse_fit_method(std::string_view name);

struct EncodeOptions {
  // Stop criteria; at least one must be set, the first one reached stops. `vertices` counts
  // the vertices of each mesh (of each layer with ColorMode::separate), four corners included.
  std::size_t vertices = 0;
  // Stop when the RMS error of the linear interpolant (over the pixels and the mesh's
  // channels, in the encoding space, unrounded, with pixel values at the vertices) is at most
  // max_rms. A least-squares refit comes after the stop and lowers the error further.
  double max_rms = 0;
  ColorSpace space = ColorSpace::rgb;  // rgb or ycbcr, for colour input
  bool grey = false;                   // encode a colour image as grey (BT.601 luma)
  ColorMode color = ColorMode::co;
  CotriMethod cotri = CotriMethod::greedy;
  // Least squares is the default: +1.4 to +2 dB over pixel values at the same vertex count
  // on the photographs (0.5 to 5 % vertices), for about 10 to 30 % more time.
  VertexFit fit = VertexFit::lsq;
  // The two improvements over plain Garland-Heckbert (false / 0 gives the plain algorithm):
  bool rank_by_total_error = true;  // priority = total squared error of the triangle
  // Candidates chosen on a Gaussian-smoothed copy of this sigma. Negative: automatic, 1.0
  // with VertexFit::pixel and 0.5 with VertexFit::lsq (the best measured for each: the
  // refit absorbs noise at the vertices, and a lighter blur keeps detail).
  double smoothing_sigma = -1;
  // With VertexFit::lsq: passes of vertex relocation after the insertion (encoder/relocate.h).
  int relocate_passes = 4;
  // With VertexFit::lsq: rounds of data-dependent triangulation after the relocation, each
  // edge flips where they lower the error (encoder/flips.h), then relocation without the
  // Delaunay condition. 0 keeps the mesh Delaunay.
  int flip_rounds = 2;
  // With VertexFit::lsq: the method the values (and gradients) are fitted for.
  FitMethod method = FitMethod::bilinear;
  // With a gradient method: gradients in steps of 2^-(12 - gradient_step_bits) values per pixel
  // (HermiteFitOptions::gradient_step_bits).
  int gradient_step_bits = 9;
  // Called now and then with the fraction done, in [0, 1].
  std::function<void(double)> progress;
};

struct EncodeResult {
  Triangulation triangulation;
  std::size_t vertices = 0;   // summed over layers
  std::size_t triangles = 0;  // summed over layers
  double psnr = 0;            // of the 8-bit render of options.method against the encoded image
  double seconds = 0;         // wall time of the encoding
};

// Encodes `image` (1 or 3 channels, at least 2 x 2). A grey image (or `grey`) gives a grey
// triangulation. Deterministic. Throws UsageError for impossible options (no stop
// criterion, fewer than 4 vertices, more vertices than pixels).
EncodeResult encode(const Image& image, const EncodeOptions& options);

// encode(), with a DataError's message prefixed by `name` (the input file's).
EncodeResult encode(const Image& image, const EncodeOptions& options, const std::string& name);

// Refuses an image the encoder does not take: more than limits::max_image_side pixels a side (the
// largest a .tri file holds) or limits::max_encode_pixels pixels. Throws DataError naming `name`.
void check_encodable(const Image& image, const std::string& name);

// What any mesh of pixel positions needs: an image of at least 2 x 2 pixels, grey or RGB
// (DataError otherwise).
void check_image_shape(const Image& image);

// A vertex count from 4 (the corners) to the image's pixel count (UsageError otherwise).
void check_vertex_count(const Image& image, std::size_t vertices);

// The image a triangulation encodes: luma for a grey triangulation of a colour image.
Image encoded_original(const Image& image, const Triangulation& tri);

// The linear interpolant of a triangulation whose vertices are pixel positions tiling
// [0, W-1] x [0, H-1], converted to RGB for YCbCr, clamped and rounded to 8 bits.
Image render_linear(const Triangulation& tri);

// A regular grid of about `vertices` pixel positions (nx x ny with nx * ny closest to it,
// spacing in proportion to the image's sides, the four corners included), Delaunay
// triangulated, with pixel values (or least-squares values): the baseline of adaptive
// sampling.
Triangulation regular_grid(const Image& image, std::size_t vertices, ColorSpace space, VertexFit fit);

}  // namespace tristream
