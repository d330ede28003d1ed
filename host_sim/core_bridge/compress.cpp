// SPDX-License-Identifier: MIT
#include "core_bridge/compress.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

#include "bytes.h"
#include "common/errors.h"
#include "core_bridge/blob_error.h"
#include "stream_models.h"
#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "wire_layout.h"

namespace tristream {

namespace {

using core::detail::Prob;
using core::detail::prob_bits;
using core::detail::prob_half;
using core::detail::prob_shift;
using core::detail::load_i32;
using core::detail::load_u16;
using core::detail::store_u16;
using core::detail::store_u32;

enum Category { positions, values, gradients, connectivity, flags, category_count };

// The encoder of the decoder in firmware_core/src/range_decoder.h (LZMA's binary range coder:
// carries propagate through a cached byte and a run of 0xFF bytes). Also sums -log2 p per
// category.
class RangeEncoder {
 public:
  Category category = positions;
  double cost[category_count] = {};

  void bit(Prob& p, std::uint32_t b) {
    const double p0 = double(p) / double(1u << prob_bits);
    cost[category] -= std::log2(b ? 1.0 - p0 : p0);
    const std::uint32_t bound = (range_ >> prob_bits) * p;
    if (!b) {
      range_ = bound;
      p = Prob(p + (((1u << prob_bits) - p) >> prob_shift));
    } else {
      low_ += bound;
      range_ -= bound;
      p = Prob(p - (p >> prob_shift));
    }
    normalize();
  }
  void direct(std::uint32_t value, int count) {
    cost[category] += count;
    for (int i = count - 1; i >= 0; --i) {
      range_ >>= 1;
      if ((value >> i) & 1u) low_ += range_;
      normalize();
    }
  }
  // The bytes, without the first (always zero, and not stored).
  std::vector<std::uint8_t> finish() {
    for (int i = 0; i < 5; ++i) shift_low();
    if (out_.empty() || out_[0] != 0) throw std::logic_error("range coder: first byte not zero");
    return std::vector<std::uint8_t>(out_.begin() + 1, out_.end());
  }

 private:
  void normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      shift_low();
    }
  }
  void shift_low() {
    if (std::uint32_t(low_) < 0xFF000000u || (low_ >> 32) != 0) {
      const std::uint8_t carry = std::uint8_t(low_ >> 32);
      std::uint8_t temp = cache_;
      do {
        out_.push_back(std::uint8_t(temp + carry));
        temp = 0xFF;
      } while (--cache_size_ != 0);
      cache_ = std::uint8_t(low_ >> 24);
    }
    ++cache_size_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }

  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cache_size_ = 1;
  std::vector<std::uint8_t> out_;
};

void reset(Prob* p, int n) { std::fill(p, p + n, prob_half); }
void reset(core::detail::UintModel& m) {
  reset(m.prefix, 16);
  reset(&m.mantissa[0][0], 16 * 3);
}
void reset(core::detail::IntModel& m) {
  m.zero = m.sign = prob_half;
  reset(m.magnitude);
}

void encode_uint(RangeEncoder& e, core::detail::UintModel& m, int max_bits, std::uint64_t u) {
  const std::uint64_t n = u + 1;
  int k = 0;
  while ((n >> (k + 1)) != 0) ++k;
  if (k > max_bits) throw std::logic_error("compress: integer beyond its field");
  for (int i = 0; i < k; ++i) e.bit(m.prefix[std::min(i, 15)], 1);
  e.bit(m.prefix[std::min(k, 15)], 0);
  Prob* tree = m.mantissa[std::min(k, 15)];
  std::uint32_t first = 0;
  for (int i = 0; i < k && i < 2; ++i) {
    const std::uint32_t b = std::uint32_t(n >> (k - 1 - i)) & 1u;
    e.bit(tree[i == 0 ? 0 : 1 + first], b);
    first = b;
  }
  if (k > 2) e.direct(std::uint32_t(n & ((std::uint64_t(1) << (k - 2)) - 1)), k - 2);
}

void encode_int(RangeEncoder& e, core::detail::IntModel& m, int max_bits, std::int64_t s) {
  e.bit(m.zero, s != 0);
  if (s == 0) return;
  e.bit(m.sign, s < 0);
  encode_uint(e, m.magnitude, max_bits, std::uint64_t(s < 0 ? -s : s) - 1);
}

// The integer sizes of the decoder (compressed_blob.cpp).
constexpr int gap_bits = 24, index_bits = 16, value_bits = 9, gradient_bits = 31;

constexpr std::uint32_t escape_symbol = 7, none = 0xFFFFFFFFu;

void encode_symbol8(RangeEncoder& e, Prob* tree, std::uint32_t s) {
  std::uint32_t node = 1;
  for (int i = 2; i >= 0; --i) {
    const std::uint32_t b = (s >> i) & 1u;
    e.bit(tree[node], b);
    node = (node << 1) | b;
  }
}

struct Vertex {
  std::uint32_t x, y;
  std::uint32_t values[3];
  std::int32_t gradients[3][2];
};

struct LayerStream {
  std::vector<std::uint8_t> bytes;
  std::uint32_t window = 0;
  std::uint32_t pinned = 0;
  std::size_t ram = 0;  // the decoder's ring and pinned slots, and their tags
  std::uint32_t gradient_shift = 0;  // the layer's gradient step bits
};

// A triangle by the raster ranks of its corners.
struct Tri {
  std::uint32_t a, b, c;  // ranks, a < b < c
  std::uint32_t rotation;  // the stored first corner is the positive cyclic order's (a first) corner `rotation`
  std::uint32_t flags;
};

// The columns (1/16 pixel) where the third corner of a triangle is looked for.
struct Columns {
  std::int32_t lo, hi;
};

// How a triangle's anchor (its second corner) and third corner are coded.
struct Anchor {
  std::uint32_t pick;  // an open edge of the first corner (0, 1), or escape_symbol: gap-coded
  std::uint32_t anchor, third;
  int side;  // the third corner's side of first -> anchor (+1, -1)
  bool hit;  // the third corner is the predicted one
};

// One layer's stream, as the decoder (LayerDecoderState, compressed_blob.cpp) reads it back: the
// same models, the same predictions, the same order. A corner more than `reach` ranks past its
// triangle's first vertex that is not decoded yet is lifted (decoded alone into a pinned slot)
// instead of decoding every vertex up to it: a shorter ring for a few explicit positions.
class LayerEncoder {
 public:
  LayerEncoder(const core::Blob& blob, const core::BlobLayer& layer, RangeEncoder& e, std::uint32_t reach)
      : blob_(blob), e_(e), nv_(blob.values_per_vertex), zienkiewicz_(blob.method == core::Method::zienkiewicz),
        rgb_(blob.space == core::ColorSpace::rgb && nv_ == 3), V_(layer.vertex_count) {
    read_vertices(layer);
    sort_raster();
    read_triangles(layer);
    plan_lifts(reach);
  }

  LayerStream encode() {
    reset_models();
    valued_.assign(V_, 0);
    edge_end_.assign(V_, {0, 0});
    edge_sides_.assign(V_, {0, 0});
    for (std::size_t t = 0; t < tris_.size(); ++t) encode_triangle(tris_[t], t);
    while (encoded_ < V_) position();
    for (std::uint32_t i = V_ > window_ ? V_ - window_ : 0; i < V_; ++i)
      if (!valued_[i]) values_of(i, -1, -1);
    const std::size_t record = ((4 + 2 * std::size_t(nv_) + 3) & ~std::size_t(3)) + 4 + (zienkiewicz_ ? 8 * nv_ : 0);
    // The slots' records, the pinned slots' indices and every slot's tag (compressed_ring_bytes and
    // compressed_tag_bytes, less the value models, which every reach has).
    const std::size_t slots = std::size_t(window_) + pinned_slots_;
    return LayerStream{e_.finish(), window_, pinned_slots_, slots * (record + 2) + 4 * pinned_slots_, shift_};
  }

 private:
  static constexpr int S = core::config::subpixel_bits;

  void read_vertices(const core::BlobLayer& layer) {
    namespace w = core::wire;
    in_.resize(V_);
    for (std::uint32_t v = 0; v < V_; ++v) {
      Vertex& x = in_[v];
      const std::uint8_t* p = layer.positions + w::position::bytes * v;
      x.x = load_u16(p + w::position::x);
      x.y = load_u16(p + w::position::y);
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t k = v * std::uint32_t(nv_) + std::uint32_t(c);
        x.values[c] = c < nv_ ? load_u16(layer.values + w::value::bytes * k) : 0;
        const std::uint8_t* g = zienkiewicz_ && c < nv_ ? layer.gradients + w::gradient::bytes * k : nullptr;
        x.gradients[c][0] = g ? load_i32(g + w::gradient::gx) : 0;
        x.gradients[c][1] = g ? load_i32(g + w::gradient::gy) : 0;
      }
    }
    gradient_step();
  }

  // The gradient step bits s: the largest s <= 24 for which every gradient component of the layer
  // is a multiple of 2^s (0 when all are 0, and for bilinear, whose components are all 0).
  void gradient_step() {
    std::uint32_t bits = 0;
    for (const Vertex& x : in_)
      for (int c = 0; c < nv_; ++c) bits |= std::uint32_t(x.gradients[c][0]) | std::uint32_t(x.gradients[c][1]);
    shift_ = bits == 0 ? 0 : std::min(std::uint32_t(std::countr_zero(bits)), core::compressed_max_gradient_shift);
  }

  // Raster order: pixel row, pixel column, then the sub-pixel bits (ties kept in input order).
  void sort_raster() {
    auto key = [&](std::uint32_t v) {
      const Vertex& x = in_[v];
      return std::array<std::uint32_t, 4>{x.y >> S, x.x >> S, x.y & ((1u << S) - 1), x.x & ((1u << S) - 1)};
    };
    order_.resize(V_);
    rank_.resize(V_);
    std::iota(order_.begin(), order_.end(), 0u);
    std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    for (std::uint32_t i = 0; i < V_; ++i) rank_[order_[i]] = i;
  }

  void read_triangles(const core::BlobLayer& layer) {
    namespace T = core::wire::triangle;
    tris_.resize(layer.triangle_count);
    for (std::uint32_t t = 0; t < layer.triangle_count; ++t) {
      const std::uint8_t* p = layer.triangles + T::bytes * t;
      const std::uint32_t v[3] = {rank_[load_u16(p + T::corner(0))], rank_[load_u16(p + T::corner(1))],
                                  rank_[load_u16(p + T::corner(2))]};
      std::uint32_t s[3] = {v[0], v[1], v[2]};
      std::sort(s, s + 3);
      // The positive cyclic order starting at the smallest rank is (s0, s1, s2) or (s0, s2, s1):
      // the one the stored triangle is a rotation of.
      const int first = v[0] == s[0] ? 0 : (v[1] == s[0] ? 1 : 2);
      const std::uint32_t after = v[(first + 1) % 3];
      const std::uint32_t cyc[3] = {s[0], after, after == s[1] ? s[2] : s[1]};
      // Stored v[0] is cyc[rotation].
      const std::uint32_t rotation = v[0] == cyc[0] ? 0 : (v[0] == cyc[1] ? 1 : 2);
      tris_[t] = Tri{s[0], s[1], s[2], rotation, load_u16(p + T::flags)};
    }
  }

  // Pass 1: the lifts, the window (the ring must hold every corner decoded in raster order) and
  // the pinned slots (taken in turn: a slot is free again once its vertex reached the ring).
  void plan_lifts(std::uint32_t reach) {
    const std::size_t T = tris_.size();
    lift_.assign(3 * T, 0);
    window_ = 3;
    pinned_slots_ = 0;
    std::uint32_t done = 0;
    std::uint64_t lifts = 0;
    std::map<std::uint32_t, std::uint64_t> pending;  // pinned rank -> its lift number
    std::set<std::uint64_t> pending_lifts;
    auto advance_to = [&](std::uint32_t x) {
      for (; done <= x; ++done)
        if (auto it = pending.find(done); it != pending.end()) {
          pending_lifts.erase(it->second);
          pending.erase(it);
        }
    };
    for (std::size_t t = 0; t < T; ++t) {
      const std::uint32_t corner[3] = {tris_[t].a, tris_[t].b, tris_[t].c};
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t x = corner[k];
        if (x < done || pending.count(x)) continue;
        if (x + 1 - corner[0] > reach) {
          lift_[3 * t + k] = 1;
          pending[x] = lifts;
          pending_lifts.insert(lifts);
          pinned_slots_ = std::max(pinned_slots_, std::uint32_t(lifts - *pending_lifts.begin() + 1));
          ++lifts;
        } else {
          advance_to(x);
        }
      }
      for (std::uint32_t x : corner)
        if (x < done) window_ = std::max(window_, done - x);
    }
    window_ = std::min(window_, V_);
  }

  void reset_models() {
    reset(m_.gap);
    m_.subpixel = m_.fraction = m_.flags_nonzero = prob_half;
    for (auto& x : value_model_) reset(x);
    for (auto& x : gradient_model_) reset(x);
    reset(&m_.top[0][0], 6 * 8);
    reset(m_.top_far);
    reset(&m_.anchor[0][0], 3 * 8);
    reset(m_.anchor_gap);
    m_.side = prob_half;
    reset(m_.predicted, 3);
    reset(m_.fresh, 3);
    reset(m_.fresh_count);
    reset(m_.third_gap);
    reset(m_.rotation, 2);
    m_.lift = prob_half;
    reset(m_.lift_gap);
    reset(m_.flag_bit, 9);
  }

  // Values (and gradients) of rank i, predicted from ranks p0, p1 (-1: none) as the decoder does.
  void values_of(std::uint32_t i, std::int64_t p0, std::int64_t p1) {
    const Vertex& x = in_[order_[i]];
    if (p0 < 0) p0 = p1, p1 = -1;
    std::uint32_t predicted[3];
    for (int c = 0; c < 3; ++c) {
      if (p0 >= 0) {
        const std::uint32_t h = in_[order_[p0]].values[c] >> 8;
        predicted[c] = p1 >= 0 ? (h + (in_[order_[p1]].values[c] >> 8) + 1) >> 1 : h;
      } else {
        predicted[c] = last_values_[c] >> 8;
      }
    }
    e_.category = values;
    std::int64_t shared = 0;
    for (int k = 0; k < nv_; ++k) {
      const int c = rgb_ ? (k == 0 ? 1 : (k == 1 ? 0 : 2)) : k;
      std::int64_t r = std::int64_t(x.values[c] >> 8) - std::int64_t(predicted[c]);
      if (rgb_ && k == 0) shared = r;
      if (rgb_ && k > 0) r -= shared;
      encode_int(e_, value_model_[k], value_bits, r);
    }
    bool fraction = false;
    for (int c = 0; c < nv_; ++c) fraction |= (x.values[c] & 0xFFu) != 0;
    e_.bit(m_.fraction, fraction);
    if (fraction)
      for (int c = 0; c < nv_; ++c) e_.direct(x.values[c] & 0xFFu, 8);
    if (zienkiewicz_) {
      e_.category = gradients;
      for (int c = 0; c < nv_; ++c)
        for (int a = 0; a < 2; ++a) {
          std::int32_t guess = last_gradients_[c][a];
          if (p0 >= 0) {
            const std::int64_t g0 = in_[order_[p0]].gradients[c][a];
            guess = p1 >= 0 ? std::int32_t((g0 + in_[order_[p1]].gradients[c][a]) >> 1) : std::int32_t(g0);
          }
          // In units of 2^s: the difference to the guess floored to a multiple of 2^s (the decoder's
          // prediction), which the gradient, a multiple of 2^s, is an exact number of steps from.
          const std::uint32_t floored = std::uint32_t(guess) & ~((1u << shift_) - 1u);
          encode_int(e_, gradient_model_[a], gradient_bits,
                     std::int32_t(std::uint32_t(x.gradients[c][a]) - floored) >> shift_);
        }
    }
    for (int c = 0; c < 3; ++c) {
      last_values_[c] = x.values[c];
      last_gradients_[c][0] = x.gradients[c][0];
      last_gradients_[c][1] = x.gradients[c][1];
    }
    valued_[i] = 1;
  }

  // A vertex's raster pixel gap to the last one and its sub-pixel bits (position, and a lift).
  void encode_point(core::detail::UintModel& gap_model, const Vertex& x) {
    const std::uint32_t here = (x.y >> S) * blob_.width + (x.x >> S);
    encode_uint(e_, gap_model, gap_bits, here - pixel_);
    const std::uint32_t sx = x.x & ((1u << S) - 1), sy = x.y & ((1u << S) - 1);
    e_.bit(m_.subpixel, (sx | sy) != 0);
    if (sx | sy) {
      e_.direct(sx, S);
      e_.direct(sy, S);
    }
  }

  // The position of rank encoded_; first the values of the rank it evicts from the ring, if no
  // triangle asked for them.
  void position() {
    if (encoded_ >= window_ && !valued_[encoded_ - window_]) values_of(encoded_ - window_, -1, -1);
    const Vertex& x = in_[order_[encoded_]];
    e_.category = positions;
    const std::uint32_t here = (x.y >> S) * blob_.width + (x.x >> S);
    if (!pinned_.erase(encoded_)) encode_point(m_.gap, x);  // decoded ahead: no bits
    pixel_ = here;
    ++encoded_;
  }

  bool has_record(std::uint32_t r) const {
    return (r < encoded_ && encoded_ - r <= window_) || pinned_.count(r) != 0;
  }
  std::int64_t cross(std::uint32_t o, std::uint32_t p, std::uint32_t q) const {
    const Vertex &O = in_[order_[o]], &P = in_[order_[p]], &Q = in_[order_[q]];
    return (std::int64_t(P.x) - O.x) * (std::int64_t(Q.y) - O.y) - (std::int64_t(P.y) - O.y) * (std::int64_t(Q.x) - O.x);
  }
  // LayerDecoderState::columns, predict and fresh.
  Columns columns(std::uint32_t a, std::uint32_t s) const {
    if (!has_record(a) || !has_record(s)) return Columns{0, 0xFFFF};
    const std::int32_t ax = in_[order_[a]].x, ay = in_[order_[a]].y, sx = in_[order_[s]].x, sy = in_[order_[s]].y;
    const std::int32_t reach = std::max(std::abs(ax - sx), std::abs(ay - sy)) + (2 << S);
    return Columns{std::min(ax, sx) - reach, std::max(ax, sx) + reach};
  }
  bool in_columns(std::uint32_t r, Columns c) const {
    return std::int32_t(in_[order_[r]].x) >= c.lo && std::int32_t(in_[order_[r]].x) <= c.hi;
  }
  std::uint32_t predict(std::uint32_t a, std::uint32_t s, int side) const {
    if (!has_record(a) || !has_record(s)) return none;
    auto px = [&](std::uint32_t r) { return std::int32_t(in_[order_[r]].x >> S); };
    auto py = [&](std::uint32_t r) { return std::int32_t(in_[order_[r]].y >> S); };
    std::uint32_t best = none;
    std::int64_t best_dot = 0, best_cross = 0;
    auto consider = [&](std::uint32_t q) {
      const std::int32_t x1 = px(a) - px(q), y1 = py(a) - py(q), x2 = px(s) - px(q), y2 = py(s) - py(q);
      const std::int32_t cr = (x1 * y2 - y1 * x2) * side;
      if (cr <= 0) return;
      const std::int32_t dot = x1 * x2 + y1 * y2;
      if (best == none || std::int64_t(dot) * best_cross < best_dot * cr) {
        best = q;
        best_dot = dot;
        best_cross = cr;
      }
    };
    for (std::uint32_t e : {a, s})
      for (int j = 0; j < 2; ++j) {
        if (!edge_sides_[e][j]) continue;
        const std::uint32_t q = edge_end_[e][j];
        if (q <= a || q == s || q == best || !has_record(q)) continue;
        consider(q);
      }
    return best;
  }
  // Whether fresh() can reach r (unused, and in the columns when in the ring).
  bool eligible(std::uint32_t r, Columns cols) const {
    return r >= encoded_ || (!valued_[r] && in_columns(r, cols));
  }
  // LayerDecoderState::add_edge: open edges (the other end, the sides decoded: 1 positive, 2
  // negative, 0 none), the most recent first.
  void add_edge(std::uint32_t from, std::uint32_t to, bool positive) {
    const std::uint8_t bit = positive ? 1 : 2;
    auto& end = edge_end_[from];
    auto& sd = edge_sides_[from];
    for (int j = 0; j < 2; ++j) {
      if (!sd[j] || end[j] != to) continue;
      if ((sd[j] | bit) != 3) return;
      if (j == 0) {
        end[0] = end[1];
        sd[0] = sd[1];
      }
      sd[1] = 0;
      return;
    }
    end[1] = end[0];
    sd[1] = sd[0];
    end[0] = to;
    sd[0] = bit;
  }

  // The triangle's first corner against the previous triangle's; returns the step's class.
  std::uint32_t encode_top(const Tri& t) {
    e_.category = connectivity;
    const std::int64_t delta = std::int64_t(t.a) - std::int64_t(previous_top_);
    const std::uint32_t step = delta >= 0 && delta <= 2 ? std::uint32_t(delta) : (delta == -1 ? 3 : 7);
    encode_symbol8(e_, m_.top[previous_picks_], step);
    if (step == 7) encode_int(e_, m_.top_far, index_bits, delta);
    return step < 2 ? step : 2;
  }

  // The anchor: an open edge of a whose other end is a corner, preferring one whose prediction
  // is the third corner; else gap-coded, preferring the corner whose prediction is the other.
  Anchor choose_anchor(const Tri& t) const {
    Anchor x{escape_symbol, t.b, t.c, 1, false};
    for (int j = 0; j < 2 && !x.hit; ++j) {
      const std::uint32_t y = edge_end_[t.a][j];
      if (!edge_sides_[t.a][j] || !has_record(t.a) || (y != t.b && y != t.c)) continue;
      const std::uint32_t other = y == t.b ? t.c : t.b;
      const int sd = edge_sides_[t.a][j] == 1 ? -1 : 1;
      const bool h = predict(t.a, y, sd) == other;
      if (x.pick == escape_symbol || h) x = Anchor{std::uint32_t(j), y, other, sd, h};
    }
    if (x.pick == escape_symbol) {
      for (const auto& [s0, t0] : {std::pair{t.b, t.c}, std::pair{t.c, t.b}}) {
        const int sd = cross(t.a, s0, t0) > 0 ? 1 : -1;
        if (predict(t.a, s0, sd) == t0) {
          x.anchor = s0, x.third = t0, x.side = sd, x.hit = true;
          break;
        }
      }
      if (!x.hit) x.side = cross(t.a, t.b, t.c) > 0 ? 1 : -1;
    }
    return x;
  }

  // The anchor, then the third corner: predicted, or fresh (counted among the eligible), or gap-coded.
  void encode_anchor_and_third(const Tri& t, std::uint32_t step_class, const Anchor& x, std::uint32_t kind) {
    encode_symbol8(e_, m_.anchor[step_class], x.pick);
    if (x.pick == escape_symbol) {
      encode_uint(e_, m_.anchor_gap, index_bits, x.anchor - t.a - 1);
      e_.bit(m_.side, x.side < 0);
    }
    const Columns cols = columns(t.a, x.anchor);
    const std::uint32_t guess = predict(t.a, x.anchor, x.side);
    if (guess != none) e_.bit(m_.predicted[kind], x.hit);
    if (x.hit) return;
    const bool fresh = x.third - t.a <= core::compressed_fresh_reach && eligible(x.third, cols);
    e_.bit(m_.fresh[kind], fresh);
    if (fresh) {
      std::uint32_t count = 0;
      for (std::uint32_t r = t.a + 1; r < x.third; ++r) count += eligible(r, cols);
      encode_uint(e_, m_.fresh_count, index_bits, count);
    } else {
      encode_uint(e_, m_.third_gap, index_bits, x.third - t.a - 1);
    }
  }

  // The corners not decoded yet: the positions up to each, or a lift into a pinned slot.
  void place_corners(const Tri& t, std::size_t index) {
    const std::uint32_t corners[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = corners[k];
      if (c < encoded_ || pinned_.count(c)) continue;
      e_.category = positions;
      const bool lifted = lift_[3 * index + k];
      e_.bit(m_.lift, lifted);
      if (!lifted) {
        while (encoded_ <= c) position();
        continue;
      }
      encode_point(m_.lift_gap, in_[order_[c]]);
      pinned_.insert(c);
    }
  }

  void encode_triangle(const Tri& t, std::size_t index) {
    const std::uint32_t step_class = encode_top(t);
    const Anchor x = choose_anchor(t);
    const std::uint32_t kind = x.pick == escape_symbol ? 2 : x.pick;
    encode_anchor_and_third(t, step_class, x, kind);
    place_corners(t, index);
    e_.category = connectivity;
    e_.bit(m_.rotation[0], t.rotation != 0);
    if (t.rotation) e_.bit(m_.rotation[1], t.rotation == 2);
    e_.category = flags;
    e_.bit(m_.flags_nonzero, t.flags != 0);
    if (t.flags)
      for (int i = 0; i < 9; ++i) e_.bit(m_.flag_bit[i], (t.flags >> i) & 1u);
    const std::uint32_t corner[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      if (valued_[corner[k]]) continue;
      std::int64_t known[2] = {-1, -1};
      for (int j = 0, n = 0; j < 3; ++j)
        if (j != k && valued_[corner[j]]) known[n++] = corner[j];
      values_of(corner[k], known[0], known[1]);
    }
    previous_top_ = t.a;
    previous_picks_ = 2 * kind + (x.hit ? 1 : 0);
    const std::int64_t area = cross(t.a, t.b, t.c);
    add_edge(t.a, t.b, area > 0);
    add_edge(t.a, t.c, area < 0);
    add_edge(t.b, t.c, area > 0);
  }

  const core::Blob& blob_;
  RangeEncoder& e_;
  const int nv_;
  const bool zienkiewicz_, rgb_;
  const std::uint32_t V_;
  std::vector<Vertex> in_;
  std::vector<std::uint32_t> order_, rank_;  // rank -> vertex, vertex -> rank
  std::vector<Tri> tris_;
  std::vector<char> lift_;  // per triangle corner
  std::uint32_t window_ = 3, pinned_slots_ = 0;
  std::uint32_t shift_ = 0;  // gradient step bits (gradient_step)
  std::uint32_t encoded_ = 0, pixel_ = 0;
  std::uint32_t last_values_[3] = {0, 0, 0};
  std::int32_t last_gradients_[3][2] = {};
  core::detail::StreamModels m_;
  core::detail::IntModel value_model_[3], gradient_model_[2];  // the decoder's value models
  std::uint32_t previous_top_ = 0, previous_picks_ = 0;
  std::set<std::uint32_t> pinned_;  // ranks decoded ahead, not yet in the ring
  std::vector<char> valued_;
  std::vector<std::array<std::uint32_t, 2>> edge_end_;
  std::vector<std::array<std::uint8_t, 2>> edge_sides_;
};

LayerStream encode_layer(const core::Blob& blob, const core::BlobLayer& layer, RangeEncoder& e, std::uint32_t reach) {
  return LayerEncoder(blob, layer, e, reach).encode();
}

}  // namespace

std::vector<std::uint8_t> compress_blob(const std::vector<std::uint8_t>& v1, std::string_view name,
                                        CompressStats* stats) {
  core::Blob blob;
  core::BlobError error;
  const core::Status s = core::open_blob(v1.data(), v1.size(), &blob, &error);
  if (s != core::Status::ok) throw DataError(blob_error_message(name, v1, s, error.offset));
  namespace h = core::wire::header;
  namespace L = core::wire::compressed_layer;
  const std::uint32_t table = h::bytes;
  std::vector<std::uint8_t> out(table + L::bytes * blob.layer_count, 0);
  std::copy(v1.begin() + h::shared_begin, v1.begin() + h::shared_end, out.begin() + h::shared_begin);
  core::wire::put_magic(out.data() + h::magic, core::wire::compressed_magic);
  store_u16(out.data() + h::version, core::compressed_version);
  store_u16(out.data() + h::header_size, h::bytes);
  store_u32(out.data() + h::layer_table, table);
  CompressStats st;
  st.v1_bytes = v1.size();
  for (int l = 0; l < blob.layer_count; ++l) {
    // The reach with the least decoder RAM among those within 3 % of the bytes without lifts:
    // reaches from the window down by a tenth at a time, until the bytes pass that (a shorter
    // reach lifts more corners, each coded apart: the bytes grow as the reach shrinks).
    RangeEncoder e;
    LayerStream ls = encode_layer(blob, blob.layers[l], e, std::numeric_limits<std::uint32_t>::max());
    const std::size_t unlifted = ls.bytes.size();
    for (std::uint32_t reach = ls.window - ls.window / 10 - 1; reach >= 16; reach -= reach / 10 + 1) {
      RangeEncoder trial;
      LayerStream candidate = encode_layer(blob, blob.layers[l], trial, reach);
      if (candidate.bytes.size() * 100 > unlifted * 103) break;
      if (candidate.ram < ls.ram) {
        ls = std::move(candidate);
        e = trial;
      }
    }
    std::uint8_t* entry = out.data() + table + L::bytes * l;
    store_u32(entry + L::vertex_count, blob.layers[l].vertex_count);
    store_u32(entry + L::triangle_count, blob.layers[l].triangle_count);
    store_u32(entry + L::stream_offset, std::uint32_t(out.size()));
    store_u32(entry + L::stream_bytes, std::uint32_t(ls.bytes.size()));
    store_u32(entry + L::window, ls.window);
    store_u32(entry + L::pinned, ls.pinned);
    entry[L::gradient_step] = std::uint8_t(ls.gradient_shift);
    out.insert(out.end(), ls.bytes.begin(), ls.bytes.end());
    st.vertices += blob.layers[l].vertex_count;
    st.triangles += blob.layers[l].triangle_count;
    st.position_bits += e.cost[positions];
    st.value_bits += e.cost[values];
    st.gradient_bits += e.cost[gradients];
    st.connectivity_bits += e.cost[connectivity];
    st.flag_bits += e.cost[flags];
    st.window = std::max(st.window, ls.window);
    st.gradient_step_bits.push_back(ls.gradient_shift);
  }
  store_u32(out.data() + h::total_size, std::uint32_t(out.size()));
  st.bytes = out.size();
  if (stats) *stats = st;
  return out;
}

}  // namespace tristream
