#include "reference/methods/patch_raster.h"

namespace tristream::detail {

PatchCanvas::PatchCanvas(const Field& prefill)
    : prefill_(prefill),
      inside_(std::size_t(prefill.width) * prefill.height, 0),
      count_(std::size_t(prefill.width) * prefill.height, 0),
      sum_(std::size_t(prefill.width) * prefill.height * prefill.channels, 0.0) {
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    bool covered = prefill.channels > 0;
    for (int c = 0; c < prefill.channels; ++c) covered = covered && !std::isnan(prefill.v[p * prefill.channels + c]);
    inside_[p] = covered ? 1 : 0;
  }
}

void PatchCanvas::resolve_thesis(Field& out) const {
  const int nc = prefill_.channels;
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    if (!inside_[p]) continue;
    const double n = double(count_[p]) + 1.0;
    for (int c = 0; c < nc; ++c) out.v[p * nc + c] = (prefill_.v[p * nc + c] + sum_[p * nc + c]) / n;
  }
}

void PatchCanvas::resolve_exact(Field& out) const {
  const int nc = prefill_.channels;
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    if (!inside_[p]) continue;
    for (int c = 0; c < nc; ++c)
      out.v[p * nc + c] = count_[p] > 0 ? sum_[p * nc + c] / double(count_[p]) : prefill_.v[p * nc + c];
  }
}

}  // namespace tristream::detail
