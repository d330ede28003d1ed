// SPDX-License-Identifier: MIT
// The band store of a compressed blob's render (firmware_core/src/band_store.h) against a model:
// random streams of triangles whose density varies by row, bands of random height, stores of the
// exact need, a little more, and less. After each band the records, read in the layout the tile
// path picks (packed while the layer's vertex_count is at most 1,024), must give back every live
// triangle's corners, flags and guard; a store must take every band whose need
// (band_store_bytes) fits and fail at the first that does not. Run under ASan, every store is
// exactly sized.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "band_store.h"

using namespace tristream::core;
using namespace tristream::core::detail;

namespace {

struct ModelTriangle {
  std::uint32_t v[3];
  std::uint16_t flags;
  std::int32_t top, bottom;
};

struct Stream {
  std::uint32_t values_per_vertex = 1;
  bool gradients = false;
  int rows = 0, band_rows = 1;
  std::vector<std::uint16_t> x, y;
  std::vector<ModelTriangle> triangles;  // by top row
};

// Vertices (two thirds of them in a band of rows, so the stores cross 1,024 slots up and down)
// and triangles of nearby vertices in top-row order.
Stream random_stream(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  Stream s;
  s.values_per_vertex = uniform(0, 1) ? 3 : 1;
  s.gradients = uniform(0, 1) != 0;
  s.rows = uniform(20, 120);
  s.band_rows = uniform(1, 16);
  const int n = uniform(200, 4000);
  const int dense0 = uniform(0, s.rows - 1), dense1 = std::min(s.rows - 1, dense0 + uniform(1, 30));
  constexpr int sub = 1 << config::subpixel_bits;
  for (int i = 0; i < n; ++i) {
    const int row = uniform(0, 2) ? uniform(dense0, dense1) : uniform(0, s.rows - 1);
    s.y.push_back(std::uint16_t(row * sub + (uniform(0, 3) ? 0 : uniform(0, sub - 1))));
    s.x.push_back(std::uint16_t(uniform(0, 60000)));
  }
  std::vector<std::uint32_t> by_row(n);
  for (int i = 0; i < n; ++i) by_row[i] = std::uint32_t(i);
  std::sort(by_row.begin(), by_row.end(), [&](std::uint32_t a, std::uint32_t b) { return s.y[a] < s.y[b]; });
  const Mapping identity;
  for (int t = uniform(n / 2, 3 * n); t > 0; --t) {
    const int centre = uniform(0, n - 1), reach = uniform(1, uniform(0, 5) ? 40 : 400);
    ModelTriangle m;
    for (auto& v : m.v) v = by_row[std::clamp(centre + uniform(-reach, reach), 0, n - 1)];
    m.flags = uniform(0, 7) ? 0 : std::uint16_t(uniform(1, 0x1FF));
    raw_row_extent(identity, s.y[m.v[0]], s.y[m.v[1]], s.y[m.v[2]], &m.top, &m.bottom);
    s.triangles.push_back(m);
  }
  std::stable_sort(s.triangles.begin(), s.triangles.end(),
                   [](const ModelTriangle& a, const ModelTriangle& b) { return a.top < b.top; });
  return s;
}

std::uint16_t value_of(std::uint32_t v, std::uint32_t c) { return std::uint16_t(v * 3 + c); }
std::int32_t gradient_of(std::uint32_t v, std::uint32_t c, int k) { return k ? -std::int32_t(v + c) : std::int32_t(v * 7 + c); }

// The guard after a store's `records` records (none without records), which the tile renderer reads
// after the last triangle, in the layout the tile path picks.
void check_guard(const BlobLayer& layer, std::uint32_t records) {
  if (!records) return;
  const bool packed = layer.vertex_count <= store_packed_slots;
  const std::uint8_t* guard = layer.triangles + std::size_t(packed ? 4 : 6) * records;
  CHECK((packed ? PackedStoreRecords::word(guard) : load_u16(guard)) == 0u);
}

struct Outcome {
  int failed_band = -1;                // the first band the store refused, or -1
  std::vector<std::size_t> needs;      // band_store_bytes of each band taken
  int packed_draws = 0, unpacked_draws = 0, layout_changes = 0;
};

// Runs the stream's bands through a store of exactly `bytes` and checks what it holds.
Outcome run(const Stream& s, std::size_t bytes) {
  Outcome out;
  const std::uint32_t n = std::uint32_t(s.x.size());
  std::vector<std::uint16_t> tags(n, band_store_free);
  std::vector<std::uint8_t> memory(bytes, 0xA5);  // not zero: a guard the store did not write shows
  BlobLayer layer{};
  BandStore store;
  store.init(memory.data(), bytes, s.values_per_vertex, s.gradients, &layer, tags.data(), n);
  const Mapping identity;
  std::size_t next = 0;
  std::vector<std::size_t> live;  // the model: live triangles in store order
  bool drew_packed = true;
  for (int y0 = 0, band = 0; y0 < s.rows; y0 += s.band_rows, ++band) {
    store.begin_band(identity, y0);
    check_guard(layer, store.count());  // (the tile path may read it before a triangle is appended)
    live.erase(std::remove_if(live.begin(), live.end(), [&](std::size_t i) { return s.triangles[i].bottom < y0; }),
               live.end());
    Status status = Status::ok;
    for (; next < s.triangles.size() && s.triangles[next].top <= y0 + s.band_rows - 1; ++next) {
      const ModelTriangle& m = s.triangles[next];
      if (m.bottom < y0 || m.top > m.bottom) continue;
      DecodedTriangle d{};
      d.flags = m.flags;
      for (int k = 0; k < 3; ++k) {
        d.v[k] = m.v[k];
        d.x[k] = s.x[m.v[k]];
        d.y[k] = s.y[m.v[k]];
        for (std::uint32_t c = 0; c < 3; ++c) {
          d.values[k][c] = value_of(m.v[k], c);
          for (int g = 0; g < 2; ++g) d.gradients[k][c][g] = gradient_of(m.v[k], c, g);
        }
        d.tag[k] = &tags[m.v[k]];
      }
      status = store.append(d);
      if (status != Status::ok) break;
      live.push_back(next);
    }
    std::set<std::uint32_t> vertices;
    std::uint32_t flagged = 0;
    for (std::size_t i : live) {
      vertices.insert(s.triangles[i].v, s.triangles[i].v + 3);
      flagged += s.triangles[i].flags != 0;
    }
    const std::uint32_t* words = status == Status::ok ? store.mark_all_live() : nullptr;
    if (!words) {
      CHECK((status == Status::ok || status == Status::workspace_too_small));
      out.failed_band = band;
      return out;
    }
    out.needs.push_back(band_store_bytes(std::uint32_t(vertices.size()), std::uint32_t(live.size()), flagged,
                                         s.values_per_vertex, s.gradients));
    // The tile path's reading (tile_renderer.h, BandStoreRecords).
    const bool packed = layer.vertex_count <= store_packed_slots;
    (packed ? out.packed_draws : out.unpacked_draws)++;
    if (band > 0 && packed != drew_packed) ++out.layout_changes;
    drew_packed = packed;
    REQUIRE(store.vertices == vertices.size());
    const std::uint32_t stride = packed ? PackedStoreRecords::stride : StoreRecords::stride;
    std::uint32_t r = 0;
    for (std::size_t i : live) {
      const ModelTriangle& m = s.triangles[i];
      const std::uint8_t* p = layer.triangles + std::size_t(stride) * r;
      CHECK(((words[r / 32] >> (r % 32)) & 1u) == 1u);
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t slot = packed ? PackedStoreRecords::vertex(p, k) : StoreRecords::vertex(p, k);
        REQUIRE(slot < store.vertices);
        CHECK(tags[m.v[k]] == slot);
        CHECK(load_u16(layer.positions + 4 * slot) == s.x[m.v[k]]);
        CHECK(load_u16(layer.positions + 4 * slot + 2) == s.y[m.v[k]]);
        for (std::uint32_t c = 0; c < s.values_per_vertex; ++c) {
          const std::size_t at = std::size_t(slot) * s.values_per_vertex + c;
          CHECK(load_u16(layer.values + 2 * at) == value_of(m.v[k], c));
          if (s.gradients) {
            CHECK(load_i32(layer.gradients + 8 * at) == gradient_of(m.v[k], c, 0));
            CHECK(load_i32(layer.gradients + 8 * at + 4) == gradient_of(m.v[k], c, 1));
          }
        }
      }
      CHECK((packed ? PackedStoreRecords::flags(p) : StoreRecords::flags(p)) == m.flags);
      if (m.flags) {
        ++r;  // the flag record: never live
        CHECK(((words[r / 32] >> (r % 32)) & 1u) == 0u);
      }
      ++r;
    }
    REQUIRE(r == store.count());
    check_guard(layer, r);
  }
  return out;
}

// The first band whose need passes `bytes`, or -1.
int first_over(const std::vector<std::size_t>& needs, std::size_t bytes) {
  for (std::size_t b = 0; b < needs.size(); ++b)
    if (needs[b] > bytes) return int(b);
  return -1;
}

}  // namespace

TEST_CASE("the band store holds every live triangle and takes exactly the bands whose need fits") {
  int changes = 0, packed = 0, unpacked = 0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    CAPTURE(seed);
    const Stream s = random_stream(seed);
    const Outcome roomy = run(s, std::size_t(1) << 22);
    REQUIRE(roomy.failed_band == -1);
    changes += roomy.layout_changes;
    packed += roomy.packed_draws;
    unpacked += roomy.unpacked_draws;
    const std::size_t most = *std::max_element(roomy.needs.begin(), roomy.needs.end());
    std::mt19937 rng{std::uint32_t(seed)};
    const std::size_t more = most + 4 * (rng() % 200), less = 4 * (rng() % (most / 4 + 1));
    for (std::size_t bytes : {most, most + 4, more, most - 4, less}) {
      CAPTURE(bytes, most);
      const Outcome o = run(s, bytes);
      CHECK(o.failed_band == first_over(roomy.needs, bytes));
    }
  }
  // The draws went through both layouts, and from one band to the next across them.
  CHECK(packed > 0);
  CHECK(unpacked > 0);
  CHECK(changes > 0);
}
