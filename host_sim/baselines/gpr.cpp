// SPDX-License-Identifier: MIT
#include "baselines/gpr.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "encoder/least_squares.h"
#include "encoder/pixel_scan.h"
#include "metrics/metrics.h"

namespace tristream::baselines {

PointRemoval::PointRemoval(const encoder::Planes& target) : target_(target), mesh_(target.width, target.height) {
  error_.resize(mesh_.slot_count());
  for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t) error_[t] = triangle_error(mesh_.vertices(t));
  const std::uint32_t n = std::uint32_t(std::size_t(target.width) * target.height);
  version_.assign(n, 0);
  for (std::uint32_t v = 0; v < n; ++v)
    if (!mesh_.is_corner(v)) requeue(v);
}

// Sum over the triangle's pixels and the channels of (plane - pixel)^2, the plane through the
// pixel values at the corners.
double PointRemoval::triangle_error(const RemovalMesh::Corners& c) const {
  constexpr int max_channels = 4;
  const std::array<encoder::IntPoint, 3> p{mesh_.pixel(c[0]), mesh_.pixel(c[1]), mesh_.pixel(c[2])};
  const double dx1 = p[1].x - p[0].x, dy1 = p[1].y - p[0].y, dx2 = p[2].x - p[0].x, dy2 = p[2].y - p[0].y;
  const double area2 = dx1 * dy2 - dy1 * dx2;
  const int ch = target_.channels;
  double f0[max_channels], gx[max_channels], gy[max_channels];
  for (int k = 0; k < ch; ++k) {
    f0[k] = target_.at(p[0].x, p[0].y, k);
    const double d1 = target_.at(p[1].x, p[1].y, k) - f0[k], d2 = target_.at(p[2].x, p[2].y, k) - f0[k];
    gx[k] = (d1 * dy2 - d2 * dy1) / area2;
    gy[k] = (d2 * dx1 - d1 * dx2) / area2;
  }
  double sse = 0;
  const float* pixels = target_.v.data();
  const std::size_t width = std::size_t(target_.width);
  encoder::scan_triangle(p, [&](int x, int y) {
    const float* px = pixels + (std::size_t(y) * width + x) * ch;
    for (int k = 0; k < ch; ++k) {
      const double e = f0[k] + gx[k] * (x - p[0].x) + gy[k] * (y - p[0].y) - px[k];
      sse += e * e;
    }
  });
  return sse;
}

double PointRemoval::significance(std::uint32_t v) const {
  mesh_.star(v, star_);
  mesh_.fill(star_, fill_);
  double before = 0, after = 0;
  for (std::uint32_t t : star_.triangles) before += error_[t];
  for (const auto& c : fill_) after += triangle_error(c);
  return after - before;
}

void PointRemoval::requeue(std::uint32_t v) { queue_.push({significance(v), v, ++version_[v]}); }

bool PointRemoval::step() {
  while (!queue_.empty()) {
    const Entry top = queue_.top();
    queue_.pop();
    if (!mesh_.alive(top.vertex) || top.version != version_[top.vertex]) continue;
    mesh_.star(top.vertex, star_);
    mesh_.fill(star_, fill_);
    neighbours_ = star_.link;
    created_.clear();
    mesh_.remove(top.vertex, star_, fill_, created_);
    error_.resize(mesh_.slot_count());
    for (std::uint32_t t : created_) error_[t] = triangle_error(mesh_.vertices(t));
    last_removed_ = top.vertex;
    last_significance_ = top.significance;
    for (std::uint32_t a : neighbours_)
      if (!mesh_.is_corner(a)) requeue(a);
    return true;
  }
  return false;
}

double PointRemoval::total_squared_error() const {
  double sum = 0;
  for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t)
    if (mesh_.is_live(t)) sum += error_[t];
  return sum;
}

Mesh PointRemoval::mesh() const {
  Mesh m;
  m.value_count = target_.channels;
  const std::uint32_t n = std::uint32_t(std::size_t(target_.width) * target_.height);
  std::vector<std::uint32_t> index(n, RemovalMesh::none);
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!mesh_.alive(v)) continue;
    const encoder::IntPoint p = mesh_.pixel(v);
    index[v] = std::uint32_t(m.points.size());
    m.points.push_back({double(p.x), double(p.y)});
    for (int k = 0; k < target_.channels; ++k) m.values.push_back(target_.at(p.x, p.y, k));
  }
  for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t)
    if (mesh_.is_live(t)) {
      const auto& c = mesh_.vertices(t);
      m.triangles.push_back({{index[c[0]], index[c[1]], index[c[2]]}});
    }
  return m;
}

GprResult greedy_point_removal(const Image& image, const GprOptions& o) {
  check_image_shape(image);
  check_vertex_count(image, o.vertices);
  const Activity activity("greedy point removal on a " + std::to_string(image.width) + " x " +
                          std::to_string(image.height) + " image");
  const auto start = std::chrono::steady_clock::now();
  Triangulation tri;
  tri.width = image.width;
  tri.height = image.height;
  tri.space = image.channels == 1 ? ColorSpace::grey : ColorSpace::rgb;
  const encoder::Planes target = encoder::to_planes(image, tri.space);
  PointRemoval removal(target);
  const std::size_t removals = removal.vertex_count() - o.vertices;
  constexpr std::size_t report_every = 4096;
  while (removal.vertex_count() > o.vertices && removal.step())
    if (o.progress && removal.vertex_count() % report_every == 0)
      o.progress(double(removals - (removal.vertex_count() - o.vertices)) / double(std::max<std::size_t>(1, removals)));
  Mesh mesh = removal.mesh();
  if (o.values == VertexFit::lsq) encoder::fit_least_squares(mesh, target, true);
  tri.layers.push_back(std::move(mesh));
  GprResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.vertices = tri.layers[0].vertex_count();
  r.triangles = tri.layers[0].triangles.size();
  r.psnr = psnr(render_linear(tri), encoded_original(image, tri));
  r.triangulation = std::move(tri);
  if (o.progress) o.progress(1.0);
  return r;
}

}  // namespace tristream::baselines
