/* SPDX-License-Identifier: MIT */
#pragma once
// The vertex count that fills a byte budget (triencode --max-bytes): a deterministic search over
// encodings whose size grows about linearly with their vertices.
#include <cstddef>
#include <functional>
#include <vector>

namespace tristream {

struct BudgetTrial {
  std::size_t vertices = 0;  // asked for
  std::size_t bytes = 0;
  bool exhausted = false;  // the encoding has all the vertices it can take (more would change nothing)
};

struct BudgetSearch {
  // The trial chosen: the one of most vertices whose bytes are at most the budget; `found` is false
  // when even the fewest vertices exceed it (then chosen is that trial).
  bool found = false;
  BudgetTrial chosen;
  std::vector<BudgetTrial> trials;  // in the order tried
};

struct BudgetOptions {
  std::size_t max_bytes = 0;
  std::size_t min_vertices = 4;
  std::size_t max_vertices = 4;  // the most an encoding may ask for
  double bytes_per_vertex = 4;   // a first guess of the slope; later steps use measured ones
  double aim = 0.975;            // steps aim at aim * max_bytes
  double good_enough = 0.95;     // stop once a trial lands in [good_enough, 1] * max_bytes
  std::size_t max_trials = 12;
};

// Tries vertex counts with `trial` (which must be deterministic): min_vertices first, then a secant
// step through the nearest trials below and above the budget towards aim * max_bytes, clamped
// strictly between them (so every trial is new and the bracket shrinks). Stops when a trial lands in
// [good_enough, 1] * max_bytes, when the largest fitting trial is exhausted or at max_vertices, when
// no count is left between the bracket, or after max_trials trials.
BudgetSearch search_vertex_budget(const std::function<BudgetTrial(std::size_t vertices)>& trial,
                                  const BudgetOptions& options);

}  // namespace tristream
