/* SPDX-License-Identifier: MIT */
#pragma once
// The caller's workspace: [alignment padding][channel scratch][active-set bitmaps, one equal share
// per layer].
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
  // Rounded up to the alignment so that the bitmaps after it are word aligned.
  const size_t bytes = size_t(r.tile_w) * r.tile_h * 3 * sizeof(int16_t);
  return (bytes + workspace_alignment - 1) / workspace_alignment * workspace_alignment;
}

}  // namespace
}  // namespace tristream::core::detail
