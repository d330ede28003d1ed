/* SPDX-License-Identifier: MIT */
#pragma once
// Greedy insertion (Garland and Heckbert 1995, algorithm III): an incremental Delaunay
// triangulation of pixel positions; each triangle keeps one candidate pixel in a priority
// queue; an insertion rescans only the triangles it created.
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

#include "encoder/pixel_scan.h"
#include "encoder/planes.h"
#include "geometry/delaunay.h"
#include "model/triangulation.h"

namespace tristream::encoder {

struct GreedyOptions {
  // true: a triangle's priority is its total squared error; false: the error of its
  // candidate pixel (plain Garland-Heckbert).
  bool rank_by_total_error = true;
  // Per-channel weights of the squared errors (empty = all 1).
  std::vector<double> channel_weight;
};

class GreedyInserter {
 public:
  // Gives a new vertex at (x, y) its values: `interpolated` holds the current interpolant
  // there (channels values); write `channels` values to `out`.
  using ValueRule = std::function<void(int x, int y, const double* interpolated, double* out)>;

  // `target`: the data the error is measured against. `guide`: the data candidates are
  // chosen against (a smoothed copy of target, or target itself), same size. Starts with the
  // four corners (width, height >= 2). Both must outlive the inserter.
  GreedyInserter(const Planes& target, const Planes& guide, GreedyOptions options, ValueRule rule);

  // Inserts the candidate of the highest-priority triangle. False when every pixel is a vertex.
  bool step();
  // Reassigns every vertex's values (rule(x, y, current values, out)) and rescans everything.
  void revalue(const ValueRule& rule);
  // Changes the rule that values later insertions.
  void set_value_rule(ValueRule rule) { rule_ = std::move(rule); }
  // Changes the channel weights (rescans everything).
  void set_channel_weight(std::vector<double> weight);

  std::size_t vertex_count() const { return delaunay_.vertex_count(); }
  std::size_t triangle_count() const { return delaunay_.solid_count(); }
  // Weighted sum over all pixels of the squared error of the linear interpolant.
  double total_squared_error() const { return total_sse_; }
  // The current mesh (positions, values, triangles).
  Mesh mesh() const;

 private:
  struct Candidate {
    double priority;
    std::uint32_t slot;
    std::uint32_t version;
    bool operator<(const Candidate& o) const {
      return priority != o.priority ? priority < o.priority : slot > o.slot;
    }
  };
  struct SlotInfo {
    std::uint32_t version = 0;
    double sse = 0;  // 0 for ghosts and dead slots
    std::int32_t cx = -1, cy = -1;  // candidate pixel, cx < 0 when none
  };

  void scan(std::uint32_t slot);
  void rescan_all();
  void add_vertex_values(int x, int y, const double* interpolated);

  const Planes& target_;
  const Planes& guide_;
  GreedyOptions options_;
  ValueRule rule_;
  int channels_;
  std::vector<double> weight_;
  DelaunayBuilder delaunay_;
  std::vector<double> values_;  // vertex_count * channels
  std::vector<std::uint8_t> is_vertex_;
  std::vector<SlotInfo> info_;
  std::priority_queue<Candidate> queue_;
  double total_sse_ = 0;
  std::vector<double> scratch_;
};

}  // namespace tristream::encoder
