// SPDX-License-Identifier: MIT
#include "encoder/blob_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/errors.h"
#include "core_bridge/compress.h"
#include "core_bridge/pack.h"

namespace tristream {

namespace {

// A first guess of the bytes per vertex; the search measures the real slope after one step.
// Compressed (docs/COMPRESSED_BLOB.md, measured on the demo): about 17 bits of positions,
// connectivity and flags, 6.5 of values per channel and 32 of zienkiewicz gradients per channel
// (estimated gradients; fitted ones on triencode's default step cost about 17, which the search's
// measured slope corrects).
// v1 (tristream/blob.h): a vertex's position 4 bytes and 2 per value, about two triangles of 8 bytes,
// zienkiewicz gradients 8 bytes per value.
double bytes_per_vertex_guess(int channels, core::Method method, bool compressed) {
  const bool z = method == core::Method::zienkiewicz;
  if (compressed) return (17.0 + channels * (6.5 + (z ? 32.0 : 0.0))) / 8.0;
  return 4.0 + 16.0 + channels * (2.0 + (z ? 8.0 : 0.0));
}

const char* blob_name(const BlobBudget& b) { return b.compressed ? "compressed" : "v1"; }

}  // namespace

std::size_t blob_bytes(const Triangulation& tri, const BlobBudget& budget, const std::string& name) {
  const std::vector<std::uint8_t> v1 = pack_blob(tri, budget.method, name);
  return budget.compressed ? compress_blob(v1, name).size() : v1.size();
}

BudgetEncoding encode_to_budget(const PanelPicture& panel, const EncodeOptions& o, const BlobBudget& budget,
                                const std::string& name) {
  const Image& picture = panel.picture;
  if (panel.panel_width > core::config::max_dimension || panel.panel_height > core::config::max_dimension)
    throw DataError(name + ": " + budget.option + " measures a blob for the core, which takes at most " +
                    std::to_string(core::config::max_dimension) + " pixels a side, found " +
                    std::to_string(panel.panel_width) + "x" + std::to_string(panel.panel_height) +
                    " (--width and --height encode for a smaller panel)");
  BudgetEncoding out;
  BudgetOptions b;
  b.max_bytes = budget.max_bytes;
  b.max_vertices =
      std::min<std::size_t>(std::size_t(picture.width) * std::size_t(picture.height), core::blob_max_vertices);
  b.bytes_per_vertex = bytes_per_vertex_guess(o.grey ? 1 : picture.channels, budget.method, budget.compressed);
  if (o.color == ColorMode::separate && !o.grey && picture.channels == 3) b.bytes_per_vertex *= 3;
  std::size_t kept_vertices = 0;
  out.search = search_vertex_budget(
      [&](std::size_t n) {
        EncodeOptions trial = o;
        trial.vertices = n;
        EncodeResult e = encode(picture, trial, name);
        out.seconds += e.seconds;
        Triangulation placed = on_panel(e.triangulation, panel);
        const std::size_t bytes = blob_bytes(placed, budget, name);
        // Exhausted: the linear interpolant is exact, or every mesh stopped short of n; more
        // vertices would only cost bytes.
        bool exhausted = true;
        for (const Mesh& m : e.triangulation.layers) exhausted = exhausted && m.vertex_count() < n;
        exhausted = exhausted || std::isinf(e.psnr);
        // The most vertices fitting the budget so far is the one kept (the search ends on it).
        if (bytes <= b.max_bytes && (out.tri.layers.empty() || n > kept_vertices)) {
          kept_vertices = n;
          out.result = std::move(e);
          out.tri = std::move(placed);
        }
        return BudgetTrial{n, bytes, exhausted};
      },
      b);
  const BudgetSearch& search = out.search;
  const std::string method(to_string(budget.method));
  if (!search.found)
    throw UsageError(budget.option + " " + std::to_string(budget.max_bytes) + ": expected at least " +
                     std::to_string(search.chosen.bytes) + " bytes, the smallest " + blob_name(budget) +
                     " blob of this picture (its 4 corners, " + method + ")");
  const bool complete = search.chosen.exhausted || search.chosen.vertices >= b.max_vertices;
  if (double(search.chosen.bytes) < 0.85 * double(b.max_bytes) && !complete)
    throw DataError(name + ": no vertex count found whose blob is within 0.85 to 1 times " +
                    std::to_string(budget.max_bytes) + " bytes in " + std::to_string(search.trials.size()) +
                    " encodes (the largest that fits: " + std::to_string(search.chosen.vertices) + " vertices, " +
                    std::to_string(search.chosen.bytes) + " bytes)");
  return out;
}

}  // namespace tristream
