// SPDX-License-Identifier: MIT
#include "encoder/budget.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace tristream {

BudgetSearch search_vertex_budget(const std::function<BudgetTrial(std::size_t)>& trial, const BudgetOptions& o) {
  if (o.max_bytes == 0 || o.min_vertices > o.max_vertices || o.max_trials < 1 || !(o.bytes_per_vertex > 0))
    throw std::invalid_argument("search_vertex_budget: bad options");
  BudgetSearch s;
  auto run = [&](std::size_t n) {
    BudgetTrial t = trial(n);
    t.vertices = n;
    s.trials.push_back(t);
    return t;
  };
  BudgetTrial lo = run(o.min_vertices);
  s.chosen = lo;
  if (lo.bytes > o.max_bytes) return s;
  s.found = true;
  std::optional<BudgetTrial> hi;  // the fewest vertices tried above the budget
  const double target = o.aim * double(o.max_bytes);
  const double enough = o.good_enough * double(o.max_bytes);
  while (s.trials.size() < o.max_trials) {
    if (double(lo.bytes) >= enough || lo.exhausted || lo.vertices >= o.max_vertices) break;
    const std::size_t ceiling = hi ? hi->vertices - 1 : o.max_vertices;
    if (ceiling <= lo.vertices) break;
    // Bytes per vertex: between the bracket's ends, else from the first trial to lo, else the guess.
    const BudgetTrial& first = s.trials.front();
    double slope = o.bytes_per_vertex;
    if (hi) slope = (double(hi->bytes) - double(lo.bytes)) / double(hi->vertices - lo.vertices);
    else if (lo.vertices > first.vertices && lo.bytes > first.bytes)
      slope = (double(lo.bytes) - double(first.bytes)) / double(lo.vertices - first.vertices);
    // Within a bracket, at least an eighth of it from either end: the bracket shrinks by that much
    // even where the sizes are not linear (and bisects where they fall).
    const double room = double(ceiling - lo.vertices);
    const double margin = hi ? std::max(1.0, std::floor((room + 1) / 8)) : 1.0;
    const double step = slope > 0 ? std::floor((target - double(lo.bytes)) / slope) : std::floor((room + 1) / 2);
    const std::size_t n = lo.vertices + std::size_t(std::clamp(step, margin, std::max(margin, room + 1 - margin)));
    const BudgetTrial t = run(n);
    if (t.bytes <= o.max_bytes) lo = t;
    else hi = t;
  }
  s.chosen = lo;
  return s;
}

}  // namespace tristream
