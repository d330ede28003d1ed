// SPDX-License-Identifier: MIT
// Fuzz target that renders: the first 16 bytes of the input choose the render parameters (pixel
// format, dithering, tile size, output size, viewport, the sizes of the tile buffer and of the
// workspace, background), the rest is the blob. Rendering must stay inside its buffers (ASan,
// UBSan), every tile must lie inside the viewport and the output, inside the tile buffer, and
// no pixel may be delivered twice; a render that returns ok has delivered every viewport pixel.
//
// Parameter bytes: 0 format (low bits) and dither (bit 7); 1, 2 tile width and height; 3 flags
// (bit 0 output size from bytes 4, 5; bit 1 viewport from bytes 6..9; bit 2 tile buffer size
// changed by the signed byte 10; bit 3 workspace size changed by the signed byte 11; bits 4, 5 the
// fit, 3 being no fit, which must be refused); 12 background.
//
// The blob is sealed with its checksum before it is opened (tests/support/blob_seal.h): a mutated
// blob would otherwise end at the checksum and never reach the renderer (fuzz_blob opens the bytes
// as they are too).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../support/blob_seal.h"
#include "tristream/render.h"

namespace {

namespace core = tristream::core;

// Workspaces below what workspace_size() reports are fuzzed: the core must refuse them before the
// first tile (issue 17 items 1 and 2; corpus/render/render_short_workspace.bin once divided by zero
// in ActiveSet). Short tile buffers likewise.
constexpr bool short_workspaces = true;

// Layered renders whose reported workspace holds no bitmap (no triangle meets the viewport's rows:
// workspace_size() reports the 8-byte alignment and the scratch only, and render's active sets get
// capacity 0) are fuzzed too: corpus/render/render_empty_window.bin once divided by zero there.
constexpr bool empty_windows = true;

// Whether the workspace workspace_size() reported for a layered blob has no room for an active-set
// bitmap (it is the 8-byte alignment plus a scratch of 6 bytes per tile pixel rounded to 8, none
// for coverage8).
bool reports_no_bitmap(const core::Blob& blob, const core::RenderParams& params, std::size_t tile_need,
                       std::size_t work_need) {
  const int bpp = core::bytes_per_pixel(params.format);
  const std::size_t tile_pixels = bpp ? tile_need / std::size_t(bpp) : 0;
  const bool scratch = blob.layer_count > 1 && params.format != core::PixelFormat::coverage8;
  return blob.layer_count > 1 && work_need <= 8 + (scratch ? (tile_pixels * 6 + 7) / 8 * 8 : 0);
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_render: %s\n", what);
  std::abort();
}

struct Check {
  const std::uint8_t* buffer;
  std::size_t buffer_bytes;
  core::Rect view;       // the viewport as rendered
  int output_width, output_height;
  int bpp;
  std::vector<std::uint8_t> seen;  // per viewport pixel: delivered
  unsigned checksum = 0;
  int tiles = 0;
};

void sink(void* context, const core::Tile* tile) {
  Check& c = *static_cast<Check*>(context);
  ++c.tiles;
  const core::Rect& r = tile->rect;
  if (r.empty()) fail("an empty tile");
  if (r.x0 < c.view.x0 || r.y0 < c.view.y0 || r.x1 > c.view.x1 || r.y1 > c.view.y1) fail("a tile outside the viewport");
  if (r.x0 < 0 || r.y0 < 0 || r.x1 > c.output_width || r.y1 > c.output_height) fail("a tile outside the output");
  const std::size_t row = std::size_t(r.width()) * c.bpp;
  if (tile->stride < 0 || std::size_t(tile->stride) < row) fail("a stride shorter than the tile's row");
  const std::size_t span = std::size_t(r.height() - 1) * std::size_t(tile->stride) + row;
  if (tile->pixels < c.buffer || std::size_t(tile->pixels - c.buffer) + span > c.buffer_bytes)
    fail("a tile outside the tile buffer");
  for (int y = r.y0; y < r.y1; ++y) {
    const std::uint8_t* p = tile->pixels + std::size_t(y - r.y0) * tile->stride;
    for (std::size_t i = 0; i < row; ++i) c.checksum += p[i];  // reads every byte (ASan checks them)
    for (int x = r.x0; x < r.x1; ++x) {
      std::uint8_t& s = c.seen[std::size_t(y - c.view.y0) * c.view.width() + (x - c.view.x0)];
      if (s) fail("a pixel delivered twice");
      s = 1;
    }
  }
}

std::size_t adjusted(std::size_t need, std::uint8_t delta_byte, bool allow_short) {
  const int delta = int(static_cast<std::int8_t>(delta_byte));
  if (delta < 0 && !allow_short) return need + std::size_t(-delta);
  if (delta < 0) return need > std::size_t(-delta) ? need - std::size_t(-delta) : 0;
  return need + std::size_t(delta);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t header = 16;
  if (size < header) return 0;
  const std::uint8_t* p = data;
  std::vector<std::uint8_t> bytes(data + header, data + size);  // exactly sized: ASan sees overreads
  tristream::testing::seal_blob(bytes.data(), bytes.size());
  core::Blob blob;
  if (core::open_blob(bytes.data(), bytes.size(), &blob) != core::Status::ok) return 0;

  core::RenderParams params;
  params.format = core::PixelFormat(p[0] % core::pixel_format_count);
  params.dither = p[0] & 0x80;
  params.tile_width = std::uint16_t(p[1] % 80);
  params.tile_height = std::uint16_t(p[2] % 80);
  const std::uint8_t flags = p[3];
  if (flags & 1) {  // 1..250: sizes below 2 must be refused
    params.output_width = std::uint16_t(1 + p[4] % 250);
    params.output_height = std::uint16_t(1 + p[5] % 250);
  }
  if (flags & 2) params.viewport = core::Rect{p[6] % 260 - 4, p[7] % 260 - 4, p[8] % 260, p[9] % 260};
  params.fit = core::Fit((flags >> 4) & 3);
  for (auto& b : params.background) b = p[12];
  // Keep frames small enough for many runs per second.
  const int out_w = params.output_width ? params.output_width : blob.width;
  const int out_h = params.output_height ? params.output_height : blob.height;
  if (std::size_t(out_w) * std::size_t(out_h) > 250u * 250u && params.viewport.empty()) return 0;

  std::size_t tile_need = 0, work_need = 0;
  const bool sized = core::tile_buffer_size(blob, params, &tile_need) == core::Status::ok &&
                     core::workspace_size(blob, params, &work_need) == core::Status::ok;
  if (!empty_windows && sized && reports_no_bitmap(blob, params, tile_need, work_need)) return 0;
  // Parameters the sizing refuses must be refused by render too, with whatever buffers.
  const std::size_t tile_bytes = (flags & 4) ? adjusted(tile_need, p[10], true) : tile_need;
  const std::size_t work_bytes = (flags & 8) ? adjusted(work_need, p[11], short_workspaces) : work_need;
  if (tile_bytes > (std::size_t(1) << 24) || work_bytes > (std::size_t(1) << 24)) return 0;
  std::vector<std::uint8_t> tile_buffer(tile_bytes), workspace(work_bytes);

  Check c;
  c.buffer = tile_buffer.data();
  c.buffer_bytes = tile_buffer.size();
  c.view = params.viewport.empty() ? core::Rect{0, 0, out_w, out_h} : params.viewport;
  c.output_width = out_w;
  c.output_height = out_h;
  c.bpp = core::bytes_per_pixel(params.format);
  if (c.view.empty() || c.view.width() > 4096 || c.view.height() > 4096) return 0;
  c.seen.assign(std::size_t(c.view.width()) * c.view.height(), 0);
  const core::Status s = core::render(blob, params, tile_buffer.data(), tile_buffer.size(), workspace.data(),
                                      workspace.size(), sink, &c);
  if (s != core::Status::ok && c.tiles) fail("render failed after delivering tiles (a partial frame)");
  if (s == core::Status::ok) {
    if (!sized) fail("render accepted parameters the sizing functions refused");
    for (std::uint8_t v : c.seen)
      if (!v) fail("render returned ok without delivering every viewport pixel");
  }
  return 0;
}
