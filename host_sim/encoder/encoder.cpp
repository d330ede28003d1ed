// SPDX-License-Identifier: MIT
#include "encoder/encoder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "encoder/flips.h"
#include "encoder/greedy.h"
#include "encoder/hermite_fit.h"
#include "encoder/least_squares.h"
#include "encoder/pixel_scan.h"
#include "encoder/planes.h"
#include "encoder/relocate.h"
#include "geometry/delaunay.h"
#include "io/limits.h"
#include "model/color.h"
#include "reference/render.h"

namespace tristream {
namespace {

using encoder::GreedyInserter;
using encoder::Planes;

double to_byte(double v) { return std::clamp(std::round(v), 0.0, 255.0); }

// Vertex values are 8-bit: the (converted) pixel value, rounded.
GreedyInserter::ValueRule pixel_values(const Planes& target) {
  return [&target](int x, int y, const double*, double* out) {
    for (int c = 0; c < target.channels; ++c) out[c] = to_byte(target.at(x, y, c));
  };
}

double rms(double sse, const Planes& p) { return std::sqrt(sse / (double(p.width) * p.height * p.channels)); }

// Progress of one run towards its stop criteria, in [0, 1].
struct Progress {
  const EncodeOptions& options;
  double first_rms = 0;
  double of(std::size_t vertices, double current_rms) const {
    double f = 0;
    if (options.vertices > 4) f = double(vertices - 4) / double(options.vertices - 4);
    if (options.max_rms > 0 && first_rms > options.max_rms && current_rms > 0)
      f = std::max(f, std::log(first_rms / current_rms) / std::log(first_rms / options.max_rms));
    return std::clamp(f, 0.0, 1.0);
  }
};

// Runs greedy insertion until a stop criterion holds; `share` scales progress reports.
void run_greedy(GreedyInserter& g, const Planes& target, const EncodeOptions& o, std::size_t vertex_limit,
                double progress_base, double progress_share) {
  Progress progress{o, rms(g.total_squared_error(), target)};
  constexpr std::size_t report_every = 256;
  std::size_t next_report = 0;
  for (;;) {
    if (g.vertex_count() >= vertex_limit) break;
    if (o.max_rms > 0 && rms(g.total_squared_error(), target) <= o.max_rms) break;
    if (!g.step()) break;
    if (o.progress && g.vertex_count() >= next_report) {
      o.progress(progress_base + progress_share * progress.of(g.vertex_count(), rms(g.total_squared_error(), target)));
      next_report = g.vertex_count() + report_every;
    }
  }
}

// What follows the greedy insertion: the fit, relocation, flips and the fit for o.method.
Mesh finish(Mesh mesh, const Planes& target, const EncodeOptions& o) {
  if (o.fit == VertexFit::lsq) {
    encoder::fit_least_squares(mesh, target, false);
    if (o.relocate_passes > 0) encoder::relocate_vertices(mesh, target, o.relocate_passes);
    for (int r = 0; r < o.flip_rounds; ++r) {
      const encoder::FlipReport flips = encoder::flip_edges(mesh, target);
      if (o.relocate_passes > 0)
        encoder::relocate_vertices(mesh, target, o.relocate_passes, false, &flips.touched);
      else
        encoder::fit_least_squares(mesh, target, false);
    }
  }
  if (o.method != FitMethod::bilinear) {
    encoder::HermiteFitOptions h;
    h.method = o.method == FitMethod::zienkiewicz ? encoder::HermiteMethod::zienkiewicz
                                                  : encoder::HermiteMethod::clough_tocher;
    h.gradient_step_bits = o.gradient_step_bits;
    encoder::fit_hermite(mesh, target, h);
  }
  for (double& v : mesh.values) v = to_byte(v);
  return mesh;
}

std::vector<double> one_hot(int channels, int c) {
  std::vector<double> w(channels, 0.0);
  w[c] = 1.0;
  return w;
}

// Mean of channel c over the pixel and its in-image 8-neighbours: the thesis's "average of
// the nearest few points of data set c".
double nearest_average(const Planes& p, int x, int y, int c) {
  double s = 0;
  int n = 0;
  for (int j = std::max(0, y - 1); j <= std::min(p.height - 1, y + 1); ++j)
    for (int i = std::max(0, x - 1); i <= std::min(p.width - 1, x + 1); ++i) s += p.at(i, j, c), ++n;
  return s / n;
}

// The thesis's co-triangulation (section 2.4): one pass per channel c; the pass first gives
// every vertex the channel-c value "average of the nearest points", then inserts points where
// the channel-c error is largest (the vertex budget is split evenly over the passes; with
// max_rms a pass also stops when its channel's RMS is at most max_rms); an inserted point
// takes its channel-c value from the data and its other channels from the interpolant of the
// triangle it falls in.
Mesh encode_thesis_cotri(const Planes& target, const Planes& guide, const EncodeOptions& o, std::size_t limit) {
  const int ch = target.channels;
  encoder::GreedyOptions go;
  go.rank_by_total_error = o.rank_by_total_error;
  go.channel_weight = one_hot(ch, 0);
  GreedyInserter g(target, guide, go, pixel_values(target));
  const std::size_t extra = limit - std::min<std::size_t>(limit, 4);
  std::size_t goal = 4;
  for (int c = 0; c < ch; ++c) {
    goal += extra / ch + (std::size_t(c) < extra % ch ? 1 : 0);
    auto rule = [&target, c, ch](int x, int y, const double* current, double* out) {
      for (int k = 0; k < ch; ++k) out[k] = to_byte(current[k]);
      out[c] = to_byte(nearest_average(target, x, y, c));
    };
    if (c > 0) g.set_channel_weight(one_hot(ch, c));
    g.revalue(rule);
    g.set_value_rule(rule);
    // RMS of one channel: the weighted sum covers one channel of `ch`.
    for (;;) {
      if (g.vertex_count() >= goal) break;
      if (o.max_rms > 0 && std::sqrt(g.total_squared_error() / (double(target.width) * target.height)) <= o.max_rms)
        break;
      if (!g.step()) break;
    }
    if (o.progress) o.progress(double(c + 1) / ch);
  }
  return g.mesh();
}

void check_options(const Image& image, const EncodeOptions& o) {
  check_image_shape(image);
  if (o.vertices == 0 && !(o.max_rms > 0)) throw UsageError("give a vertex count or an error target");
  if (o.vertices != 0) check_vertex_count(image, o.vertices);
  if (!(o.max_rms >= 0)) throw UsageError("--error must be positive");
  if (image.channels == 3 && !o.grey && o.space == ColorSpace::grey)
    throw UsageError("a colour image needs the rgb or ycbcr space (or --grey)");
  if (o.method != FitMethod::bilinear && o.fit != VertexFit::lsq)
    throw UsageError("a fit for zienkiewicz or clough-tocher needs least-squares values (not --values pixel)");
  if (o.gradient_step_bits < 0 || o.gradient_step_bits > 12)
    throw UsageError("--gradient-step " + std::to_string(o.gradient_step_bits) + ": expected 0 to 12");
}

// The reference's render of a gradient method, 8-bit.
Image render_fitted(const Triangulation& tri, FitMethod method) {
  return render_reference(tri, *find_reference_method(to_string(method)), RenderOptions{});
}

}  // namespace

EncodeResult encode(const Image& image, const EncodeOptions& options, const std::string& name) {
  try {
    return encode(image, options);
  } catch (const DataError& e) {
    throw DataError(name + ": " + e.what());
  }
}

void check_image_shape(const Image& image) {
  if (image.width < 2 || image.height < 2)
    throw DataError("image of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                    " pixels: expected at least 2 x 2");
  if (image.channels != 1 && image.channels != 3)
    throw DataError("expected a grey or RGB image, found " + std::to_string(image.channels) + " channels");
}

void check_vertex_count(const Image& image, std::size_t vertices) {
  const std::size_t pixels = std::size_t(image.width) * image.height;
  if (vertices < 4) throw UsageError("--vertices " + std::to_string(vertices) + ": expected at least 4 (the corners)");
  if (vertices > pixels)
    throw UsageError("--vertices " + std::to_string(vertices) + ": expected at most the pixel count " +
                     std::to_string(pixels) + " (" + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + ")");
}

std::string_view to_string(FitMethod method) {
  return method == FitMethod::zienkiewicz     ? "zienkiewicz"
         : method == FitMethod::clough_tocher ? "clough-tocher"
                                              : "bilinear";
}

FitMethod parse_fit_method(std::string_view name) {
  for (FitMethod m : {FitMethod::bilinear, FitMethod::zienkiewicz, FitMethod::clough_tocher})
    if (to_string(m) == name) return m;
  throw UsageError("--method " + std::string(name) + ": expected bilinear, zienkiewicz or clough-tocher");
}

void check_encodable(const Image& image, const std::string& name) {
  const std::string found = std::to_string(image.width) + "x" + std::to_string(image.height);
  if (image.width > limits::max_image_side || image.height > limits::max_image_side)
    throw DataError(name + ": expected an image of at most " + std::to_string(limits::max_image_side) +
                    " pixels a side (the largest a .tri file holds), found " + found);
  if (std::uint64_t(image.width) * std::uint64_t(image.height) > limits::max_encode_pixels)
    throw DataError(name + ": expected an image of at most " + std::to_string(limits::max_encode_pixels) +
                    " pixels (the limit for encoding), found " + found);
}

Image encoded_original(const Image& image, const Triangulation& tri) {
  return tri.channels() == 1 ? to_grey(image) : image;
}

EncodeResult encode(const Image& image, const EncodeOptions& o) {
  check_options(image, o);
  const Activity activity("encoding a " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                          " image");
  const auto start = std::chrono::steady_clock::now();
  const bool grey = image.channels == 1 || o.grey;
  Triangulation tri;
  tri.width = image.width;
  tri.height = image.height;
  tri.space = grey ? ColorSpace::grey : o.space;
  const Planes target = encoder::to_planes(grey ? to_grey(image) : image, tri.space);
  const double sigma = o.smoothing_sigma >= 0 ? o.smoothing_sigma : (o.fit == VertexFit::lsq ? 0.5 : 1.0);
  const Planes guide = encoder::gaussian_blur(target, sigma);
  const std::size_t pixels = std::size_t(image.width) * image.height;
  const std::size_t limit = o.vertices ? o.vertices : pixels;
  encoder::GreedyOptions go;
  go.rank_by_total_error = o.rank_by_total_error;

  if (grey || o.color == ColorMode::co) {
    Mesh mesh;
    if (!grey && o.cotri == CotriMethod::thesis) {
      mesh = encode_thesis_cotri(target, guide, o, limit);
    } else {
      GreedyInserter g(target, guide, go, pixel_values(target));
      run_greedy(g, target, o, limit, 0.0, 1.0);
      mesh = g.mesh();
    }
    tri.layers.push_back(finish(std::move(mesh), target, o));
  } else {
    const char* names[2][3] = {{"r", "g", "b"}, {"y", "cb", "cr"}};
    for (int c = 0; c < 3; ++c) {
      const Planes t = encoder::channel_of(target, c), gd = encoder::channel_of(guide, c);
      GreedyInserter g(t, gd, go, pixel_values(t));
      run_greedy(g, t, o, limit, c / 3.0, 1 / 3.0);
      Mesh mesh = finish(g.mesh(), t, o);
      mesh.name = names[tri.space == ColorSpace::ycbcr][c];
      tri.layers.push_back(std::move(mesh));
    }
  }
  EncodeResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const Mesh& m : tri.layers) r.vertices += m.vertex_count(), r.triangles += m.triangles.size();
  const Image rendered = o.method == FitMethod::bilinear ? render_linear(tri) : render_fitted(tri, o.method);
  const Image original = encoded_original(image, tri);
  double sse = 0;
  for (std::size_t i = 0; i < rendered.pixels.size(); ++i) {
    const double d = double(rendered.pixels[i]) - original.pixels[i];
    sse += d * d;
  }
  const double mse = sse / double(rendered.pixels.size());
  r.psnr = mse == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / mse);
  r.triangulation = std::move(tri);
  if (o.progress) o.progress(1.0);
  return r;
}

Image render_linear(const Triangulation& tri) {
  const int w = tri.width, h = tri.height, ch = tri.channels();
  std::vector<double> field(std::size_t(w) * h * ch, 0.0);
  for (int c = 0; c < ch; ++c) {
    const Mesh& mesh = tri.mesh_of_channel(c);
    const int k = tri.value_index_of_channel(c);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      std::array<encoder::IntPoint, 3> p;
      const auto& v = mesh.triangles[t].v;
      for (int e = 0; e < 3; ++e) {
        p[e] = {std::int32_t(mesh.points[v[e]].x), std::int32_t(mesh.points[v[e]].y)};
      }
      const double area2 = double(std::int64_t(p[1].x - p[0].x) * (p[2].y - p[0].y) -
                                  std::int64_t(p[1].y - p[0].y) * (p[2].x - p[0].x));
      encoder::scan_triangle(p, [&](int x, int y) {
        double value = 0;
        for (int i = 0; i < 3; ++i) {
          const auto& b = p[(i + 1) % 3];
          const auto& cc = p[(i + 2) % 3];
          const double l = double(std::int64_t(cc.x - b.x) * (y - b.y) - std::int64_t(cc.y - b.y) * (x - b.x)) / area2;
          value += l * mesh.value(v[i], k);
        }
        field[(std::size_t(y) * w + x) * ch + c] = value;
      });
    }
  }
  Image out(w, h, ch);
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    const double* f = &field[i * ch];
    if (tri.space == ColorSpace::ycbcr) {
      const auto rgb = ycbcr_to_rgb(f[0], f[1], f[2]);
      for (int c = 0; c < 3; ++c) out.pixels[i * 3 + c] = std::uint8_t(to_byte(rgb[c]));
    } else {
      for (int c = 0; c < ch; ++c) out.pixels[i * ch + c] = std::uint8_t(to_byte(f[c]));
    }
  }
  return out;
}

Triangulation regular_grid(const Image& image, std::size_t vertices, ColorSpace space, VertexFit fit) {
  const int w = image.width, h = image.height;
  // nx / ny follows w / h; try the neighbouring counts and keep the product closest to N.
  const double ideal = std::sqrt(double(vertices) * (w - 1) / std::max(1, h - 1));
  int best_nx = 2, best_ny = 2;
  std::size_t best_diff = SIZE_MAX;
  for (int nx = std::max(2, int(ideal) - 2); nx <= std::min(w, int(ideal) + 3); ++nx) {
    for (int ny : {int(std::floor(double(vertices) / nx)), int(std::ceil(double(vertices) / nx))}) {
      ny = std::clamp(ny, 2, h);
      const std::size_t n = std::size_t(nx) * ny;
      const std::size_t diff = n > vertices ? n - vertices : vertices - n;
      if (diff < best_diff) best_diff = diff, best_nx = nx, best_ny = ny;
    }
  }
  Triangulation tri;
  tri.width = w;
  tri.height = h;
  tri.space = image.channels == 1 ? ColorSpace::grey : space;
  const Planes target = encoder::to_planes(image, tri.space);
  Mesh mesh;
  mesh.value_count = target.channels;
  for (int j = 0; j < best_ny; ++j)
    for (int i = 0; i < best_nx; ++i) {
      const int x = int(std::lround(double(i) * (w - 1) / (best_nx - 1)));
      const int y = int(std::lround(double(j) * (h - 1) / (best_ny - 1)));
      mesh.points.push_back({double(x), double(y)});
      for (int c = 0; c < target.channels; ++c) mesh.values.push_back(to_byte(target.at(x, y, c)));
    }
  mesh.triangles = delaunay_triangulation(mesh.points);
  EncodeOptions o;
  o.fit = fit;
  o.relocate_passes = 0;
  o.flip_rounds = 0;
  tri.layers.push_back(finish(std::move(mesh), target, o));
  return tri;
}

}  // namespace tristream
