// SPDX-License-Identifier: MIT
#include "core_bridge/compress.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

#include "common/errors.h"
#include "core_bridge/blob_error.h"
#include "tristream/blob.h"
#include "tristream/compressed_blob.h"

namespace tristream {

namespace {

using core::detail::Prob;
using core::detail::prob_bits;
using core::detail::prob_half;
using core::detail::prob_shift;

std::uint32_t get16(const std::uint8_t* p) { return p[0] | (p[1] << 8); }
std::uint32_t get32(const std::uint8_t* p) { return get16(p) | (get16(p + 2) << 16); }
void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) b[at + k] = std::uint8_t(v >> (8 * k));
}

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
};

// One layer's stream; a corner more than `reach` ranks past its triangle's first vertex that is
// not decoded yet is lifted (decoded alone into a pinned slot) instead of decoding every vertex up
// to it: a shorter ring for a few explicit positions.
LayerStream encode_layer(const core::Blob& blob, const core::BlobLayer& layer, RangeEncoder& e,
                         std::uint32_t reach) {
  const int S = core::config::subpixel_bits;
  const int nv = blob.values_per_vertex;
  const bool zienkiewicz = blob.method == core::Method::zienkiewicz;
  const std::uint32_t V = layer.vertex_count, T = layer.triangle_count;
  std::vector<Vertex> in(V);
  for (std::uint32_t v = 0; v < V; ++v) {
    Vertex& x = in[v];
    x.x = get16(layer.positions + 4 * v);
    x.y = get16(layer.positions + 4 * v + 2);
    for (int c = 0; c < 3; ++c) {
      x.values[c] = c < nv ? get16(layer.values + 2 * (v * nv + c)) : 0;
      for (int a = 0; a < 2; ++a)
        x.gradients[c][a] = zienkiewicz && c < nv ? std::int32_t(get32(layer.gradients + 8 * (v * nv + c) + 4 * a)) : 0;
    }
  }
  // Raster order: pixel row, pixel column, then the sub-pixel bits (ties kept in input order).
  auto key = [&](std::uint32_t v) {
    const Vertex& x = in[v];
    return std::array<std::uint32_t, 4>{x.y >> S, x.x >> S, x.y & ((1u << S) - 1), x.x & ((1u << S) - 1)};
  };
  std::vector<std::uint32_t> order(V), rank(V);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  for (std::uint32_t i = 0; i < V; ++i) rank[order[i]] = i;

  struct Tri {
    std::uint32_t a, b, c;  // ranks, a < b < c
    std::uint32_t rotation;
    std::uint32_t flags;
  };
  std::vector<Tri> tris(T);
  for (std::uint32_t t = 0; t < T; ++t) {
    const std::uint8_t* p = layer.triangles + core::blob_triangle_size * t;
    const std::uint32_t v[3] = {rank[get16(p)], rank[get16(p + 2)], rank[get16(p + 4)]};
    std::uint32_t s[3] = {v[0], v[1], v[2]};
    std::sort(s, s + 3);
    // The positive cyclic order starting at the smallest rank is (s0, s1, s2) or (s0, s2, s1):
    // the one the stored triangle is a rotation of.
    const int first = v[0] == s[0] ? 0 : (v[1] == s[0] ? 1 : 2);
    const std::uint32_t after = v[(first + 1) % 3];
    const std::uint32_t cyc[3] = {s[0], after, after == s[1] ? s[2] : s[1]};
    // Stored v[0] is cyc[rotation].
    const std::uint32_t rotation = v[0] == cyc[0] ? 0 : (v[0] == cyc[1] ? 1 : 2);
    tris[t] = Tri{s[0], s[1], s[2], rotation, get16(p + 6)};
  }
  // Pass 1: the lifts, the window (the ring must hold every corner decoded in raster order) and
  // the pinned slots (taken in turn: a slot is free again once its vertex reached the ring).
  std::vector<char> lift(3 * std::size_t(T), 0);
  std::uint32_t window = 3, pinned_slots = 0;
  {
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
    for (std::uint32_t t = 0; t < T; ++t) {
      const std::uint32_t corner[3] = {tris[t].a, tris[t].b, tris[t].c};
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t x = corner[k];
        if (x < done || pending.count(x)) continue;
        if (x + 1 - corner[0] > reach) {
          lift[3 * std::size_t(t) + k] = 1;
          pending[x] = lifts;
          pending_lifts.insert(lifts);
          pinned_slots = std::max(pinned_slots, std::uint32_t(lifts - *pending_lifts.begin() + 1));
          ++lifts;
        } else {
          advance_to(x);
        }
      }
      for (std::uint32_t x : corner)
        if (x < done) window = std::max(window, done - x);
    }
  }
  window = std::min(window, V);

  std::uint32_t encoded = 0, pixel = 0;
  std::uint32_t last_values[3] = {0, 0, 0};
  std::int32_t last_gradients[3][2] = {};
  const bool rgb = blob.space == core::ColorSpace::rgb && nv == 3;
  core::detail::StreamModels m;
  core::detail::IntModel value_model[3], gradient_model[2];  // the decoder's value models
  reset(m.gap);
  m.subpixel = m.fraction = m.flags_nonzero = prob_half;
  for (auto& x : value_model) reset(x);
  for (auto& x : gradient_model) reset(x);
  reset(&m.top[0][0], 6 * 8);
  reset(m.top_far);
  reset(&m.anchor[0][0], 3 * 8);
  reset(m.anchor_gap);
  m.side = prob_half;
  reset(m.predicted, 3);
  reset(m.fresh, 3);
  reset(m.fresh_count);
  reset(m.third_gap);
  std::uint32_t previous_picks = 0;
  reset(m.rotation, 2);
  m.lift = prob_half;
  reset(m.lift_gap);
  std::set<std::uint32_t> pinned;  // ranks decoded ahead, not yet in the ring
  reset(m.flag_bit, 9);
  std::vector<char> valued(V, 0);
  // Values (and gradients) of rank i, predicted from ranks p0, p1 (-1: none) as the decoder does.
  auto values_of = [&](std::uint32_t i, std::int64_t p0, std::int64_t p1) {
    const Vertex& x = in[order[i]];
    if (p0 < 0) p0 = p1, p1 = -1;
    std::uint32_t predicted[3];
    for (int c = 0; c < 3; ++c) {
      if (p0 >= 0) {
        const std::uint32_t h = in[order[p0]].values[c] >> 8;
        predicted[c] = p1 >= 0 ? (h + (in[order[p1]].values[c] >> 8) + 1) >> 1 : h;
      } else {
        predicted[c] = last_values[c] >> 8;
      }
    }
    e.category = values;
    std::int64_t shared = 0;
    for (int k = 0; k < nv; ++k) {
      const int c = rgb ? (k == 0 ? 1 : (k == 1 ? 0 : 2)) : k;
      std::int64_t r = std::int64_t(x.values[c] >> 8) - std::int64_t(predicted[c]);
      if (rgb && k == 0) shared = r;
      if (rgb && k > 0) r -= shared;
      encode_int(e, value_model[k], value_bits, r);
    }
    bool fraction = false;
    for (int c = 0; c < nv; ++c) fraction |= (x.values[c] & 0xFFu) != 0;
    e.bit(m.fraction, fraction);
    if (fraction)
      for (int c = 0; c < nv; ++c) e.direct(x.values[c] & 0xFFu, 8);
    if (zienkiewicz) {
      e.category = gradients;
      for (int c = 0; c < nv; ++c)
        for (int a = 0; a < 2; ++a)
        {
          std::int32_t predicted = last_gradients[c][a];
          if (p0 >= 0) {
            const std::int64_t g0 = in[order[p0]].gradients[c][a];
            predicted = p1 >= 0 ? std::int32_t((g0 + in[order[p1]].gradients[c][a]) >> 1) : std::int32_t(g0);
          }
          encode_int(e, gradient_model[a], gradient_bits,
                     std::int32_t(std::uint32_t(x.gradients[c][a]) - std::uint32_t(predicted)));
        }
    }
    for (int c = 0; c < 3; ++c) {
      last_values[c] = x.values[c];
      last_gradients[c][0] = x.gradients[c][0];
      last_gradients[c][1] = x.gradients[c][1];
    }
    valued[i] = 1;
  };
  // The position of rank `encoded`; first the values of the rank it evicts from the ring, if no
  // triangle asked for them.
  auto position = [&]() {
    if (encoded >= window && !valued[encoded - window]) values_of(encoded - window, -1, -1);
    const Vertex& x = in[order[encoded]];
    e.category = positions;
    const std::uint32_t here = (x.y >> S) * blob.width + (x.x >> S);
    if (pinned.erase(encoded)) {  // decoded ahead: no bits
      pixel = here;
      ++encoded;
      return;
    }
    encode_uint(e, m.gap, gap_bits, here - pixel);
    const std::uint32_t sx = x.x & ((1u << S) - 1), sy = x.y & ((1u << S) - 1);
    e.bit(m.subpixel, (sx | sy) != 0);
    if (sx | sy) {
      e.direct(sx, S);
      e.direct(sy, S);
    }
    pixel = here;
    ++encoded;
  };
  std::uint32_t previous_top = 0;
  // The decoder's records: open edges (the other end, the sides decoded: 1 positive, 2 negative,
  // 0 none), the most recent first, as LayerDecoder::add_edge keeps them.
  std::vector<std::array<std::uint32_t, 2>> edge_end(V, {0, 0});
  std::vector<std::array<std::uint8_t, 2>> edge_sides(V, {0, 0});
  auto has_record = [&](std::uint32_t r) { return (r < encoded && encoded - r <= window) || pinned.count(r) != 0; };
  auto cross = [&](std::uint32_t o, std::uint32_t p, std::uint32_t q) {
    const Vertex &O = in[order[o]], &P = in[order[p]], &Q = in[order[q]];
    return (std::int64_t(P.x) - O.x) * (std::int64_t(Q.y) - O.y) - (std::int64_t(P.y) - O.y) * (std::int64_t(Q.x) - O.x);
  };
  // LayerDecoder::columns, predict and fresh.
  struct Columns {
    std::int32_t lo, hi;
  };
  auto columns = [&](std::uint32_t a, std::uint32_t s) {
    if (!has_record(a) || !has_record(s)) return Columns{0, 0xFFFF};
    const std::int32_t ax = in[order[a]].x, ay = in[order[a]].y, sx = in[order[s]].x, sy = in[order[s]].y;
    const std::int32_t reach = std::max(std::abs(ax - sx), std::abs(ay - sy)) + (2 << S);
    return Columns{std::min(ax, sx) - reach, std::max(ax, sx) + reach};
  };
  auto in_columns = [&](std::uint32_t r, Columns c) {
    return std::int32_t(in[order[r]].x) >= c.lo && std::int32_t(in[order[r]].x) <= c.hi;
  };
  auto predict = [&](std::uint32_t a, std::uint32_t s, int side) {
    if (!has_record(a) || !has_record(s)) return none;
    auto px = [&](std::uint32_t r) { return std::int32_t(in[order[r]].x >> S); };
    auto py = [&](std::uint32_t r) { return std::int32_t(in[order[r]].y >> S); };
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
        if (!edge_sides[e][j]) continue;
        const std::uint32_t q = edge_end[e][j];
        if (q <= a || q == s || q == best || !has_record(q)) continue;
        consider(q);
      }
    return best;
  };
  // Whether fresh() can reach r (unused, and in the columns when in the ring).
  auto eligible = [&](std::uint32_t r, Columns cols) { return r >= encoded || (!valued[r] && in_columns(r, cols)); };
  // LayerDecoder::add_edge.
  auto add_edge = [&](std::uint32_t from, std::uint32_t to, bool positive) {
    const std::uint8_t bit = positive ? 1 : 2;
    auto& end = edge_end[from];
    auto& sd = edge_sides[from];
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
  };
  for (const Tri& t : tris) {
    e.category = connectivity;
    const std::int64_t delta = std::int64_t(t.a) - std::int64_t(previous_top);
    const std::uint32_t step = delta >= 0 && delta <= 2 ? std::uint32_t(delta) : (delta == -1 ? 3 : 7);
    encode_symbol8(e, m.top[previous_picks], step);
    if (step == 7) encode_int(e, m.top_far, index_bits, delta);
    const std::uint32_t step_class = step < 2 ? step : 2;
    // The anchor: an open edge of a whose other end is a corner, preferring one whose prediction
    // is the third corner; else gap-coded, preferring the corner whose prediction is the other.
    std::uint32_t pick = escape_symbol, anchor = t.b, third = t.c;
    int side = 1;
    bool hit = false;
    for (int j = 0; j < 2 && !hit; ++j) {
      const std::uint32_t y = edge_end[t.a][j];
      if (!edge_sides[t.a][j] || !has_record(t.a) || (y != t.b && y != t.c)) continue;
      const std::uint32_t other = y == t.b ? t.c : t.b;
      const int sd = edge_sides[t.a][j] == 1 ? -1 : 1;
      const bool h = predict(t.a, y, sd) == other;
      if (pick == escape_symbol || h) pick = std::uint32_t(j), anchor = y, third = other, side = sd, hit = h;
    }
    if (pick == escape_symbol) {
      for (const auto& [s0, t0] : {std::pair{t.b, t.c}, std::pair{t.c, t.b}}) {
        const int sd = cross(t.a, s0, t0) > 0 ? 1 : -1;
        if (predict(t.a, s0, sd) == t0) {
          anchor = s0, third = t0, side = sd, hit = true;
          break;
        }
      }
      if (!hit) side = cross(t.a, t.b, t.c) > 0 ? 1 : -1;
    }
    const std::uint32_t kind = pick == escape_symbol ? 2 : pick;
    encode_symbol8(e, m.anchor[step_class], pick);
    if (pick == escape_symbol) {
      encode_uint(e, m.anchor_gap, index_bits, anchor - t.a - 1);
      e.bit(m.side, side < 0);
    }
    const Columns cols = columns(t.a, anchor);
    const std::uint32_t guess = predict(t.a, anchor, side);
    if (guess != none) e.bit(m.predicted[kind], hit);
    if (!hit) {
      const bool fresh = eligible(third, cols);
      e.bit(m.fresh[kind], fresh);
      if (fresh) {
        std::uint32_t count = 0;
        for (std::uint32_t r = t.a + 1; r < third; ++r) count += eligible(r, cols);
        encode_uint(e, m.fresh_count, index_bits, count);
      } else {
        encode_uint(e, m.third_gap, index_bits, third - t.a - 1);
      }
    }
    const std::uint32_t corners[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = corners[k];
      if (c < encoded || pinned.count(c)) continue;
      e.category = positions;
      const bool lifted = lift[3 * std::size_t(&t - tris.data()) + k];
      e.bit(m.lift, lifted);
      if (!lifted) {
        while (encoded <= c) position();
        continue;
      }
      const Vertex& x = in[order[c]];
      const std::uint32_t here = (x.y >> S) * blob.width + (x.x >> S);
      encode_uint(e, m.lift_gap, gap_bits, here - pixel);
      const std::uint32_t sx = x.x & ((1u << S) - 1), sy = x.y & ((1u << S) - 1);
      e.bit(m.subpixel, (sx | sy) != 0);
      if (sx | sy) {
        e.direct(sx, S);
        e.direct(sy, S);
      }
      pinned.insert(c);
    }
    e.category = connectivity;
    e.bit(m.rotation[0], t.rotation != 0);
    if (t.rotation) e.bit(m.rotation[1], t.rotation == 2);
    e.category = flags;
    e.bit(m.flags_nonzero, t.flags != 0);
    if (t.flags)
      for (int i = 0; i < 9; ++i) e.bit(m.flag_bit[i], (t.flags >> i) & 1u);
    const std::uint32_t corner[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      if (valued[corner[k]]) continue;
      std::int64_t known[2] = {-1, -1};
      for (int j = 0, n = 0; j < 3; ++j)
        if (j != k && valued[corner[j]]) known[n++] = corner[j];
      values_of(corner[k], known[0], known[1]);
    }
    previous_top = t.a;
    previous_picks = 2 * kind + (hit ? 1 : 0);
    const std::int64_t area = cross(t.a, t.b, t.c);
    add_edge(t.a, t.b, area > 0);
    add_edge(t.a, t.c, area < 0);
    add_edge(t.b, t.c, area > 0);
  }
  while (encoded < V) position();
  for (std::uint32_t i = V > window ? V - window : 0; i < V; ++i)
    if (!valued[i]) values_of(i, -1, -1);
  const std::size_t record = ((4 + 2 * std::size_t(nv) + 3) & ~std::size_t(3)) + 4 + (zienkiewicz ? 8 * nv : 0);
  // The slots' records, the pinned slots' indices and every slot's tag (compressed_ring_bytes and
  // compressed_tag_bytes, less the value models, which every reach has).
  const std::size_t slots = std::size_t(window) + pinned_slots;
  return LayerStream{e.finish(), window, pinned_slots, slots * (record + 2) + 4 * pinned_slots};
}

}  // namespace

std::vector<std::uint8_t> compress_blob(const std::vector<std::uint8_t>& v1, std::string_view name,
                                        CompressStats* stats) {
  core::Blob blob;
  core::BlobError error;
  const core::Status s = core::open_blob(v1.data(), v1.size(), &blob, &error);
  if (s != core::Status::ok) throw DataError(blob_error_message(name, v1, s, error.offset));
  const std::size_t table = core::compressed_header_size;
  std::vector<std::uint8_t> out(table + core::compressed_layer_entry_size * blob.layer_count, 0);
  std::copy(v1.begin() + 12, v1.begin() + 36, out.begin() + 12);  // the fields both forms share
  out[0] = 'T', out[1] = 'S', out[2] = 'T', out[3] = 'C';
  out[4] = std::uint8_t(core::compressed_version), out[5] = 0;
  out[6] = std::uint8_t(core::compressed_header_size), out[7] = 0;
  put32(out, 28, std::uint32_t(table));
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
    const std::size_t entry = table + core::compressed_layer_entry_size * l;
    put32(out, entry, blob.layers[l].vertex_count);
    put32(out, entry + 4, blob.layers[l].triangle_count);
    put32(out, entry + 8, std::uint32_t(out.size()));
    put32(out, entry + 12, std::uint32_t(ls.bytes.size()));
    put32(out, entry + 16, ls.window);
    put32(out, entry + 20, ls.pinned);
    out.insert(out.end(), ls.bytes.begin(), ls.bytes.end());
    st.vertices += blob.layers[l].vertex_count;
    st.triangles += blob.layers[l].triangle_count;
    st.position_bits += e.cost[positions];
    st.value_bits += e.cost[values];
    st.gradient_bits += e.cost[gradients];
    st.connectivity_bits += e.cost[connectivity];
    st.flag_bits += e.cost[flags];
    st.window = std::max(st.window, ls.window);
  }
  put32(out, 8, std::uint32_t(out.size()));
  st.bytes = out.size();
  if (stats) *stats = st;
  return out;
}

}  // namespace tristream
