/* SPDX-License-Identifier: MIT */
#pragma once
// Running the fixed-point core on the host: blob bytes in, a whole frame assembled from the
// tiles the core delivers, plus the conversions trisim needs.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "model/color.h"
#include "model/image.h"
#include "model/triangulation.h"
#include "reference/fit.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"

namespace tristream {

struct CoreOptions {
  int width = 0;   // output size; 0 = the triangulation's size (corner-to-corner mapping)
  int height = 0;
  core::Fit fit = core::Fit::stretch;  // how the domain maps to the output (RenderParams::fit)
  core::Rect viewport;  // output pixels to render; empty = all
  int tile_width = 32;  // 0 = the viewport width (bands)
  int tile_height = 32; // 0 = the viewport height (one band: full frame when both are 0)
  core::PixelFormat format = core::PixelFormat::rgb888;
  bool dither = false;
  Background background;  // R, G, B; a grey blob takes the first
};

// The viewport's pixels in `format`, rows packed (stride = width * bytes per pixel).
struct CoreFrame {
  int width = 0;
  int height = 0;
  core::PixelFormat format = core::PixelFormat::rgb888;
  std::vector<std::uint8_t> bytes;
  std::uint64_t tiles = 0;  // tiles delivered by the sink
};

// Buffers sized once for repeated renders of one blob (benchmarks).
class CoreRenderer {
 public:
  // Opens (validates) the blob, which must outlive the renderer (it is read in place), and
  // sizes tile buffer and workspace. Throws DataError
  // ("<name>: byte N: <status>") for an invalid blob and UsageError for invalid options.
  // A compressed blob (TSTC) is rendered from its streams band by band (render.h); its
  // workspace_size decodes every stream once here, so a damaged one is refused here.
  CoreRenderer(std::span<const std::uint8_t> blob, const CoreOptions& options, std::string_view name = "blob");
  // Renders one frame into `frame` (resized on first use).
  void render(CoreFrame& frame);
  std::size_t tile_buffer_bytes() const { return tile_.size(); }
  std::size_t workspace_bytes() const { return workspace_.size(); }
  // For a compressed blob: its header fields and no layers.
  const core::Blob& blob() const { return blob_; }
  bool compressed() const { return compressed_; }
  // For a compressed blob: the terms of its workspace (workspace_size).
  const core::CompressedWorkspace& stream_workspace() const { return stream_workspace_; }

 private:
  core::Blob blob_;
  core::CompressedBlob compressed_blob_;
  bool compressed_ = false;
  core::CompressedWorkspace stream_workspace_;
  core::RenderParams params_;
  std::vector<std::uint8_t> tile_;
  std::vector<std::uint8_t> workspace_;
};

// Decodes a frame to an 8-bit image: L8 -> 1 channel, every other format -> RGB.
Image frame_to_image(const CoreFrame& frame);

// Packs `tri` for `method` ("bilinear" or "zienkiewicz") and renders it with the core. `name`
// (the file's) starts the messages of errors in the data.
Image render_core(const Triangulation& tri, std::string_view method, const CoreOptions& options,
                  std::string_view name = "triangulation");
CoreFrame render_core_frame(const Triangulation& tri, std::string_view method, const CoreOptions& options,
                            std::string_view name = "triangulation");

// The core's Fit of the host's (reference/fit.h): the same layout.
core::Fit core_fit(Fit fit);

}  // namespace tristream
