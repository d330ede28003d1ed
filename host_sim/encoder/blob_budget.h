/* SPDX-License-Identifier: MIT */
#pragma once
// The encoding whose blob fills a byte budget (triencode --max-bytes): the vertex count of
// encoder/budget.h's search, each trial measured as the blob tripack writes for it.
#include <cstddef>
#include <string>

#include "encoder/budget.h"
#include "encoder/encoder.h"
#include "encoder/panel.h"
#include "model/triangulation.h"
#include "tristream/blob.h"

namespace tristream {

struct BlobBudget {
  std::size_t max_bytes = 0;
  core::Method method = core::Method::bilinear;  // the blob's method (tripack -m)
  bool compressed = true;                          // tripack --compress, else the v1 blob
  std::string option = "--max-bytes";              // how the caller names the budget in messages
};

struct BudgetEncoding {
  EncodeResult result;  // the encoding chosen (its triangulation on the picture)
  Triangulation tri;    // that triangulation on the panel (on_panel)
  BudgetSearch search;  // the trials and the one chosen
  double seconds = 0;   // all encodes
};

// The bytes of the blob that budget measures: pack_blob for its method, compressed or not.
std::size_t blob_bytes(const Triangulation& tri, const BlobBudget& budget, const std::string& name);

// The most vertices found whose blob fits the budget, one encode per trial (options.vertices and
// max_rms are replaced by each trial's count). Throws UsageError when even the four corners exceed
// it, DataError naming `name` when the panel is larger than the core takes or no count lands
// within 0.85 to 1 times the budget (unless the picture needs no more vertices).
BudgetEncoding encode_to_budget(const PanelPicture& panel, const EncodeOptions& options, const BlobBudget& budget,
                                const std::string& name);

}  // namespace tristream
