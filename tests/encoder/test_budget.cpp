// SPDX-License-Identifier: MIT
// The vertex-count search of triencode --max-bytes (encoder/budget.h) on sizes given as functions.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <functional>

#include "encoder/budget.h"

using namespace tristream;

namespace {

// About `per_vertex` bytes a vertex over a header, with a deterministic wobble of up to +-`noise`
// bytes (sizes of real blobs are not monotone from one count to the next).
std::function<BudgetTrial(std::size_t)> sizes(double header, double per_vertex, int noise, std::size_t* calls) {
  return [=](std::size_t n) {
    ++*calls;
    const std::uint64_t h = (std::uint64_t(n) * 0x9E3779B97F4A7C15ull) >> 40;
    const long wobble = noise ? long(h % std::uint64_t(2 * noise + 1)) - noise : 0;
    return BudgetTrial{n, std::size_t(std::llround(header + per_vertex * double(n)) + wobble), false};
  };
}

}  // namespace

TEST_CASE("search_vertex_budget lands close under the budget in few trials", "[budget]") {
  for (const double per_vertex : {2.5, 4.5, 16.4}) {
    for (const double guess : {1.0, 4.0, 20.0}) {
      for (const std::size_t budget : {300u, 5'000u, 20'000u, 200'000u}) {
        std::size_t calls = 0;
        BudgetOptions o;
        o.max_bytes = budget;
        o.max_vertices = 65535;
        o.bytes_per_vertex = guess;
        const BudgetSearch s = search_vertex_budget(sizes(130, per_vertex, 20, &calls), o);
        INFO("per vertex " << per_vertex << ", guess " << guess << ", budget " << budget);
        REQUIRE(s.found);
        REQUIRE(s.chosen.bytes <= budget);
        // Unless the budget holds more than the most vertices allowed (2.5 bytes a vertex at 200,000);
        // within 5 % where the wobble is small against the budget.
        if (s.chosen.vertices < o.max_vertices) {
          REQUIRE(double(s.chosen.bytes) >= 0.85 * double(budget));
          if (budget >= 5'000) REQUIRE(double(s.chosen.bytes) >= 0.95 * double(budget));
        }
        REQUIRE(s.trials.size() == calls);
        REQUIRE(calls <= o.max_trials);
        // The chosen trial is the one of most vertices that fits.
        for (const BudgetTrial& t : s.trials)
          if (t.bytes <= budget) REQUIRE(t.vertices <= s.chosen.vertices);
        // Deterministic: the same trials again.
        std::size_t again = 0;
        const BudgetSearch s2 = search_vertex_budget(sizes(130, per_vertex, 20, &again), o);
        REQUIRE(s2.trials.size() == s.trials.size());
        for (std::size_t k = 0; k < s.trials.size(); ++k) REQUIRE(s2.trials[k].vertices == s.trials[k].vertices);
      }
    }
  }
}

TEST_CASE("search_vertex_budget: sizes that grow faster than linearly", "[budget]") {
  std::size_t calls = 0;
  auto convex = [&](std::size_t n) {
    ++calls;
    return BudgetTrial{n, std::size_t(100 + std::pow(double(n), 1.4)), false};
  };
  BudgetOptions o;
  o.max_bytes = 50'000;
  o.max_vertices = 65535;
  const BudgetSearch s = search_vertex_budget(convex, o);
  REQUIRE(s.found);
  REQUIRE(s.chosen.bytes <= 50'000);
  REQUIRE(s.chosen.bytes >= 0.95 * 50'000);
  REQUIRE(calls <= o.max_trials);
}

TEST_CASE("search_vertex_budget: a budget below the fewest vertices is not found", "[budget]") {
  std::size_t calls = 0;
  BudgetOptions o;
  o.max_bytes = 129;
  o.max_vertices = 1000;
  const BudgetSearch s = search_vertex_budget(sizes(130, 4, 0, &calls), o);
  REQUIRE_FALSE(s.found);
  REQUIRE(s.chosen.vertices == 4);
  REQUIRE(s.chosen.bytes == 146);
  REQUIRE(calls == 1);
}

TEST_CASE("search_vertex_budget stops at the most vertices allowed or an exhausted encoding", "[budget]") {
  BudgetOptions o;
  o.max_bytes = 1'000'000;
  o.max_vertices = 500;
  std::size_t calls = 0;
  BudgetSearch s = search_vertex_budget(sizes(130, 4, 0, &calls), o);
  REQUIRE(s.found);
  REQUIRE(s.chosen.vertices == 500);
  REQUIRE(calls <= 3);
  // An image that 50 vertices represent exactly: more change nothing.
  auto flat = [](std::size_t n) { return BudgetTrial{n, 130 + 4 * std::min<std::size_t>(n, 50), n >= 50}; };
  o.max_vertices = 65535;
  s = search_vertex_budget(flat, o);
  REQUIRE(s.found);
  REQUIRE(s.chosen.exhausted);
  REQUIRE(s.chosen.bytes == 330);
}

TEST_CASE("search_vertex_budget bisects sizes that fall", "[budget]") {
  // Falling sizes give no slope; every step must still be new and inside the bracket.
  std::size_t calls = 0;
  auto odd = [&](std::size_t n) {
    ++calls;
    return BudgetTrial{n, n < 1000 ? 100 + n : (n < 1100 ? 3000 - n : 5000), false};
  };
  BudgetOptions o;
  o.max_bytes = 1050;
  o.max_vertices = 65535;
  const BudgetSearch s = search_vertex_budget(odd, o);
  REQUIRE(s.found);
  REQUIRE(s.chosen.bytes <= 1050);
  REQUIRE(calls <= o.max_trials);
  for (std::size_t a = 0; a < s.trials.size(); ++a)
    for (std::size_t b = a + 1; b < s.trials.size(); ++b) REQUIRE(s.trials[a].vertices != s.trials[b].vertices);
}
