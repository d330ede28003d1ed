// SPDX-License-Identifier: MIT
#include "encoder/greedy.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace tristream::encoder {
namespace {

const Planes& checked(const Planes& target, const Planes& guide) {
  if (target.channels < 1 || target.channels > 4)
    throw std::invalid_argument("greedy insertion: 1 to 4 channels");
  if (target.width < 2 || target.height < 2)
    throw std::invalid_argument("greedy insertion needs at least 2 x 2 pixels, found " +
                                std::to_string(target.width) + " x " + std::to_string(target.height));
  if (guide.width != target.width || guide.height != target.height || guide.channels != target.channels)
    throw std::invalid_argument("greedy insertion: guide and target differ in size");
  if (target.width > (1 << 20) || target.height > (1 << 20))
    throw std::invalid_argument("greedy insertion: image wider or higher than 2^20 pixels");
  return target;
}

// Values of the linear interpolant over triangle (a, b, c): f(p) = f_a + gx (px - ax) + gy (py - ay).
struct Plane {
  double gx, gy;
};
Plane plane_through(const IntPoint& a, const IntPoint& b, const IntPoint& c, double fa, double fb, double fc) {
  const double bax = b.x - a.x, bay = b.y - a.y, cax = c.x - a.x, cay = c.y - a.y;
  const double d = bax * cay - bay * cax;
  return {((fb - fa) * cay - (fc - fa) * bay) / d, ((fc - fa) * bax - (fb - fa) * cax) / d};
}

}  // namespace

GreedyInserter::GreedyInserter(const Planes& target, const Planes& guide, GreedyOptions options, ValueRule rule)
    : target_(checked(target, guide)),
      guide_(guide),
      options_(std::move(options)),
      rule_(std::move(rule)),
      channels_(target.channels),
      delaunay_({0, 0}, {double(target.width - 1), 0}, {0, double(target.height - 1)}) {
  weight_ = options_.channel_weight.empty() ? std::vector<double>(channels_, 1.0) : options_.channel_weight;
  if (int(weight_.size()) != channels_) throw std::invalid_argument("greedy insertion: one weight per channel");
  is_vertex_.assign(std::size_t(target.width) * target.height, 0);
  std::vector<double> here(channels_);
  auto add_corner = [&](int x, int y) {
    for (int c = 0; c < channels_; ++c) here[c] = target_.at(x, y, c);
    add_vertex_values(x, y, here.data());
  };
  add_corner(0, 0);
  add_corner(target.width - 1, 0);
  add_corner(0, target.height - 1);
  delaunay_.insert({double(target.width - 1), double(target.height - 1)});
  add_corner(target.width - 1, target.height - 1);
  rescan_all();
}

void GreedyInserter::add_vertex_values(int x, int y, const double* interpolated) {
  const std::size_t base = values_.size();
  values_.resize(base + channels_);
  rule_(x, y, interpolated, values_.data() + base);
  is_vertex_[std::size_t(y) * target_.width + x] = 1;
}

void GreedyInserter::scan(std::uint32_t slot) {
  SlotInfo& info = info_[slot];
  info.sse = 0;
  info.cx = info.cy = -1;
  if (!delaunay_.is_live(slot) || delaunay_.is_ghost(slot)) return;
  const auto& tv = delaunay_.vertices(slot);
  std::array<IntPoint, 3> p;
  for (int e = 0; e < 3; ++e) {
    const Point& q = delaunay_.point(tv[e]);
    p[e] = {std::int32_t(q.x), std::int32_t(q.y)};
  }
  constexpr int max_channels = 4;
  double fa[max_channels], gx[max_channels], gy[max_channels];
  for (int c = 0; c < channels_; ++c) {
    fa[c] = values_[tv[0] * channels_ + c];
    const Plane pl =
        plane_through(p[0], p[1], p[2], fa[c], values_[tv[1] * channels_ + c], values_[tv[2] * channels_ + c]);
    gx[c] = pl.gx;
    gy[c] = pl.gy;
  }
  const int width = target_.width;
  const float* target = target_.v.data();
  const float* guide = guide_.v.data();
  const int channels = channels_;
  const double* weight = weight_.data();
  double sse = 0, best = -1;
  std::int32_t bx = -1, by = -1;
  scan_triangle(p, [&](int x, int y) {
    const std::size_t pixel = std::size_t(y) * width + x;
    const double dx = x - p[0].x, dy = y - p[0].y;
    double err = 0, guide_err = 0;
    for (int c = 0; c < channels; ++c) {
      const double value = fa[c] + gx[c] * dx + gy[c] * dy;
      const double e = value - target[pixel * channels + c];
      const double g = value - guide[pixel * channels + c];
      err += weight[c] * e * e;
      guide_err += weight[c] * g * g;
    }
    sse += err;
    if (guide_err > best && !is_vertex_[pixel]) {
      best = guide_err;
      bx = x;
      by = y;
    }
  });
  info.sse = sse;
  total_sse_ += sse;
  if (bx < 0) return;
  info.cx = bx;
  info.cy = by;
  queue_.push({options_.rank_by_total_error ? sse : best, slot, info.version});
}

void GreedyInserter::rescan_all() {
  info_.resize(delaunay_.slot_count());
  queue_ = {};
  total_sse_ = 0;
  for (std::uint32_t t = 0; t < info_.size(); ++t) {
    ++info_[t].version;
    scan(t);
  }
}

bool GreedyInserter::step() {
  while (!queue_.empty() && queue_.top().version != info_[queue_.top().slot].version) queue_.pop();
  if (queue_.empty()) return false;
  const std::uint32_t slot = queue_.top().slot;
  queue_.pop();
  const int x = info_[slot].cx, y = info_[slot].cy;

  const auto& tv = delaunay_.vertices(slot);
  std::array<IntPoint, 3> p;
  for (int e = 0; e < 3; ++e) p[e] = {std::int32_t(delaunay_.point(tv[e]).x), std::int32_t(delaunay_.point(tv[e]).y)};
  std::vector<double>& here = scratch_;
  here.resize(channels_);
  for (int c = 0; c < channels_; ++c) {
    const double fa = values_[tv[0] * channels_ + c];
    const Plane pl =
        plane_through(p[0], p[1], p[2], fa, values_[tv[1] * channels_ + c], values_[tv[2] * channels_ + c]);
    here[c] = fa + pl.gx * (x - p[0].x) + pl.gy * (y - p[0].y);
  }
  const std::size_t before = delaunay_.vertex_count();
  const std::uint32_t v = delaunay_.insert({double(x), double(y)}, slot);
  if (v != before) throw std::logic_error("greedy insertion: candidate pixel is already a vertex");
  add_vertex_values(x, y, here.data());

  info_.resize(delaunay_.slot_count());
  for (std::uint32_t t : delaunay_.destroyed()) {
    total_sse_ -= info_[t].sse;
    info_[t].sse = 0;
    ++info_[t].version;
  }
  for (std::uint32_t t : delaunay_.created()) {
    ++info_[t].version;
    scan(t);
  }
  return true;
}

void GreedyInserter::revalue(const ValueRule& rule) {
  std::vector<double> old = values_;
  for (std::size_t v = 0; v < delaunay_.vertex_count(); ++v) {
    const Point& q = delaunay_.point(std::uint32_t(v));
    rule(int(q.x), int(q.y), old.data() + v * channels_, values_.data() + v * channels_);
  }
  rescan_all();
}

void GreedyInserter::set_channel_weight(std::vector<double> weight) {
  if (int(weight.size()) != channels_) throw std::invalid_argument("greedy insertion: one weight per channel");
  weight_ = std::move(weight);
  rescan_all();
}

Mesh GreedyInserter::mesh() const {
  Mesh m;
  m.value_count = channels_;
  m.points = delaunay_.points();
  m.values = values_;
  m.triangles = delaunay_.triangles();
  return m;
}

}  // namespace tristream::encoder
