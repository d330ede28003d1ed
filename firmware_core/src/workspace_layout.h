/* SPDX-License-Identifier: MIT */
#pragma once
// The caller's workspace: [alignment padding][channel scratch][the layer source's fixed sections]
// [one equal share per layer] (render_driver.h), carved and measured by one WorkspaceCarver.
#include <stddef.h>
#include <stdint.h>

#include "frame_plan.h"
#include "tristream/blob.h"
#include "tristream/config.h"

namespace tristream::core::detail {
namespace {

constexpr size_t workspace_alignment = 8;

// Bytes of a bitmap of `bits` bits in whole 32-bit words.
inline size_t bitmap_bytes(uint32_t bits) { return size_t((bits + 31) / 32) * 4; }

inline bool layered(const Blob& blob) { return blob.layer_count > 1; }

// The layers a render keeps state for: 1 without the layered path (plan_frame rejects layered
// blobs there), which saves the others' stack.
constexpr int max_layers = config::layered ? 3 : 1;

inline size_t scratch_bytes(const Blob& blob, const FramePlan& r, PixelFormat f) {
  if (!layered(blob) || f == PixelFormat::coverage8) return 0;
  // Rounded up to the alignment so that the sections after it stay aligned.
  const size_t bytes = size_t(r.tile_w) * r.tile_h * 3 * sizeof(int16_t);
  return (bytes + workspace_alignment - 1) / workspace_alignment * workspace_alignment;
}

// The padding rule of every caller memory the core carves (a render's workspace, the scratch of
// workspace_size(CompressedBlob)): it starts with workspace_alignment - address mod
// workspace_alignment bytes (1 to 8), none for a null one (which has 0 bytes). A measure counts
// the most, 8, so the bytes it reports are exact for an 8-aligned workspace (one byte less is
// too small) and enough for any other.
inline size_t workspace_padding(const void* p) {
  return p ? workspace_alignment - uintptr_t(p) % workspace_alignment : 0;
}

// Sections taken one after the other from caller memory, or, measuring, only counted: the same
// calls measure a layout and carve it. A section starts at an 8-aligned address when the sizes of
// those before it are multiples of 8. The sections' addresses are computed without checks (no
// branch per section); they may be used once fits() says that every section taken is inside the
// memory, and never when measuring.
class WorkspaceCarver {
 public:
  // Measures: take() only counts.
  WorkspaceCarver() : used_(workspace_alignment), size_(SIZE_MAX) {}
  // Carves the `bytes` bytes at `base` (null with 0 bytes: none).
  WorkspaceCarver(void* base, size_t bytes)
      : base_(uintptr_t(base)), used_(workspace_padding(base)), size_(bytes) {}

  // The next n bytes (counted whether or not they fit).
  uint8_t* take(size_t n) {
    uint8_t* const p = reinterpret_cast<uint8_t*>(base_ + used_);
    used_ += n;
    return p;
  }
  // Whether every section taken so far is inside the memory.
  bool fits() const { return used_ <= size_; }
  // The bytes taken, the padding included: a measure's result.
  size_t used() const { return used_; }
  // After fits(): an equal share of what is left for each of `parts` sections, in whole 32-bit
  // words.
  size_t share(int parts) const { return (size_ - used_) / size_t(parts) / 4 * 4; }

 private:
  uintptr_t base_ = 0;
  size_t used_;
  size_t size_;
};

}  // namespace
}  // namespace tristream::core::detail
