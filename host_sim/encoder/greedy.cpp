#include "encoder/greedy.h"

#include <algorithm>
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

constexpr int max_candidates = 8;

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
    const Plane pl = plane_through(p[0], p[1], p[2], fa[c], values_[tv[1] * channels_ + c], values_[tv[2] * channels_ + c]);
    gx[c] = pl.gx;
    gy[c] = pl.gy;
  }
  const int width = target_.width;
  const float* target = target_.v.data();
  const float* guide = guide_.v.data();
  const int channels = channels_;
  const double* weight = weight_.data();
  // The `k` pixels of largest guide error, best first.
  const int k = std::clamp(options_.candidates, 1, max_candidates);
  double best[max_candidates];
  std::int32_t bx[max_candidates], by[max_candidates];
  int found = 0;
  double sse = 0;
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
    if (is_vertex_[pixel] || (found == k && guide_err <= best[k - 1])) return;
    int i = found < k ? found++ : k - 1;
    for (; i > 0 && best[i - 1] < guide_err; --i) best[i] = best[i - 1], bx[i] = bx[i - 1], by[i] = by[i - 1];
    best[i] = guide_err, bx[i] = x, by[i] = y;
  });
  info.sse = sse;
  total_sse_ += sse;
  if (found == 0) return;
  int chosen = 0;
  double priority = options_.rank_by_total_error ? sse : best[0];
  if (found > 1 || options_.rank_by_reduction || options_.local_fit) {
    double reduction[max_candidates], delta[max_candidates][4];
    estimate(p, fa, gx, gy, found, bx, by, reduction, delta);
    for (int i = 1; i < found; ++i)
      if (reduction[i] > reduction[chosen]) chosen = i;
    if (options_.rank_by_reduction) priority = reduction[chosen];
    for (int c = 0; c < channels; ++c) info.delta[c] = delta[chosen][c];
  }
  info.cx = bx[chosen];
  info.cy = by[chosen];
  queue_.push({priority, slot, info.version});
}

// Splitting the triangle at candidate q changes the interpolant by delta * phi, phi the hat
// function of q in the split: phi(p) = min over i of l_i(p) / l_i(q) (l = barycentric
// coordinates, i with l_i(q) > 0). With e the current error, the squared error falls by
// (sum e phi)^2 / sum phi^2 for the best delta = -sum e phi / sum phi^2.
void GreedyInserter::estimate(const std::array<IntPoint, 3>& p, const double* fa, const double* gx,
                              const double* gy, int count, const std::int32_t* cx, const std::int32_t* cy,
                              double* reduction, double (*delta)[4]) const {
  // l_i(x, y) = (ax_i x + ay_i y + a0_i) / area2, from the edge opposite vertex i.
  double ax[3], ay[3], a0[3];
  const double area2 = double(std::int64_t(p[1].x - p[0].x) * (p[2].y - p[0].y) -
                              std::int64_t(p[1].y - p[0].y) * (p[2].x - p[0].x));
  for (int i = 0; i < 3; ++i) {
    const IntPoint& b = p[(i + 1) % 3];
    const IntPoint& c = p[(i + 2) % 3];
    ax[i] = -(c.y - b.y) / area2;
    ay[i] = (c.x - b.x) / area2;
    a0[i] = (double(c.y - b.y) * b.x - double(c.x - b.x) * b.y) / area2;
  }
  double inv[max_candidates][3];
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < 3; ++i) {
      const double l = ax[i] * cx[j] + ay[i] * cy[j] + a0[i];
      inv[j][i] = l > 1e-12 ? 1 / l : 0;  // 0: the candidate is on the edge opposite i
    }
  double sum_ephi[max_candidates][4] = {}, sum_phi2[max_candidates] = {};
  const int width = target_.width, channels = channels_;
  const float* target = target_.v.data();
  scan_triangle(p, [&](int x, int y) {
    const std::size_t pixel = std::size_t(y) * width + x;
    const double dx = x - p[0].x, dy = y - p[0].y;
    double e[4];
    for (int c = 0; c < channels; ++c) e[c] = fa[c] + gx[c] * dx + gy[c] * dy - target[pixel * channels + c];
    double l[3];
    for (int i = 0; i < 3; ++i) l[i] = std::max(0.0, ax[i] * x + ay[i] * y + a0[i]);
    for (int j = 0; j < count; ++j) {
      double phi = 1;
      for (int i = 0; i < 3; ++i)
        if (inv[j][i] > 0) phi = std::min(phi, l[i] * inv[j][i]);
      sum_phi2[j] += phi * phi;
      for (int c = 0; c < channels; ++c) sum_ephi[j][c] += e[c] * phi;
    }
  });
  for (int j = 0; j < count; ++j) {
    reduction[j] = 0;
    for (int c = 0; c < channels; ++c) {
      delta[j][c] = sum_phi2[j] > 0 ? -sum_ephi[j][c] / sum_phi2[j] : 0;
      reduction[j] += sum_phi2[j] > 0 ? weight_[c] * sum_ephi[j][c] * sum_ephi[j][c] / sum_phi2[j] : 0;
    }
  }
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
    const Plane pl = plane_through(p[0], p[1], p[2], fa, values_[tv[1] * channels_ + c], values_[tv[2] * channels_ + c]);
    here[c] = fa + pl.gx * (x - p[0].x) + pl.gy * (y - p[0].y);
  }
  const std::size_t before = delaunay_.vertex_count();
  const std::uint32_t v = delaunay_.insert({double(x), double(y)}, slot);
  if (v != before) throw std::logic_error("greedy insertion: candidate pixel is already a vertex");
  add_vertex_values(x, y, here.data());
  if (options_.local_fit) {
    double* added = values_.data() + values_.size() - channels_;
    for (int c = 0; c < channels_; ++c) added[c] = std::clamp(here[c] + info_[slot].delta[c], 0.0, 255.0);
  }

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
