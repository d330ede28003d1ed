/* SPDX-License-Identifier: MIT */
#pragma once
// The parameters of a render call: the fit, the render parameters, the caller's buffers and the
// frame sink. The render calls themselves are in render.h; the core's own headers include this
// one to name the parameters without the calls.
#include <stddef.h>
#include <stdint.h>

#include "tristream/pixel_format.h"
#include "tristream/tile.h"

namespace tristream::core {

// How the triangulation's W x H domain maps to a W' x H' output (docs/CONVENTIONS.md, "Fitting").
enum class Fit : uint8_t {
  stretch = 0,  // each axis corner to corner: the picture fills the output, its aspect follows the output's
  inside = 1,   // one scale for both axes, the whole picture visible and centred, a `background` border
  fill = 2,     // one scale for both axes covering the whole output, centred, the excess cropped
};

struct RenderParams {
  // Output size; 0 means the blob's size. With Fit::stretch output pixel (i, j) samples the domain
  // at (i * (W-1) / (W'-1), j * (H-1) / (H'-1)): corners map to corners.
  uint16_t output_width = 0;
  uint16_t output_height = 0;
  // The part of the output to render, in output pixels; all zeros means all of it, and any other
  // empty rectangle (x0 == x1 or y0 == y1, as from a dirty rectangle of no area) is bad_params.
  Rect viewport;
  // Tile size in pixels; 0 means the viewport's width (bands) or height (one band).
  uint16_t tile_width = 0;
  uint16_t tile_height = 0;
  PixelFormat format = PixelFormat::rgb888;
  // Ordered 4x4 Bayer dithering of RGB565, keyed on the absolute output position.
  bool dither = false;
  // Colour of pixels outside the triangulation's domain (R, G, B; grey uses the first).
  uint8_t background[3] = {0, 0, 0};
  // Every tile's rows back to back (stride = the tile's own width in bytes, also for the narrower
  // tiles of the last column), so a tile is one contiguous transfer; otherwise the stride is the
  // tile width's.
  bool packed_tiles = false;
  // The mapping of the domain to the output; stretch, the default, is the only one that changes
  // the picture's aspect. Pixels outside the picture (the border of Fit::inside) are outside the
  // domain and get `background` like any other. A fill is bad_params when its picture, counted
  // from its crop rounded up to a multiple of 4 pixels before the output, would reach
  // TS_MAX_DIMENSION pixels (the coordinate budget).
  Fit fit = Fit::stretch;
  // Rendering in place into the caller's framebuffer (an LVGL canvas, a partial framebuffer): with
  // a target, pixel (x, y) of the viewport goes to
  //   target + (y - viewport.y0) * target_stride + (x - viewport.x0) * bytes_per_pixel(format)
  // (viewport in output pixels; the default viewport is the whole output). Tiles are drawn where
  // they belong, no tile buffer is used (it may be null and 0 bytes; tile_buffer_size says 0), and
  // the sink, which may then be null, gets each finished tile pointing into the target (stride
  // target_stride) and may still stop the frame. target_stride 0 means rows back to back (the
  // viewport's width in bytes); a negative one is a bottom-up buffer (target still the viewport's
  // top row). Only the viewport's pixels are read or written: bytes [target + (rows - 1) *
  // target_stride, target + width x bpp) for a negative stride, [target, target + (rows - 1) *
  // target_stride + width x bpp) otherwise, and of those only each row's first width x bpp.
  // bad_params: |target_stride| below the viewport's width in bytes or above 2^19 (524,288)
  // bytes, packed_tiles with a target, a target_stride without a target.
  int32_t target_stride = 0;
  void* target = nullptr;
};

// Caller memory of a render: one tile buffer, or two that the tiles alternate between (double
// buffering: the sink may hand a tile to a DMA transfer and return at once), none with a target
// (RenderParams::target), and the workspace.
struct RenderBuffers {
  void* tile[2] = {nullptr, nullptr};  // tile[1] null: every tile in tile[0]
  size_t tile_bytes = 0;               // bytes of each tile buffer (tile_buffer_size)
  void* workspace = nullptr;
  size_t workspace_bytes = 0;          // workspace_size
};

// Receives each finished tile (in the order of TileSink) and returns whether to go on: false stops
// the frame, and render returns Status::stopped. With two tile buffers, tile k + 1 goes into the
// buffer of tile k - 1 as soon as the sink returns from tile k: the sink must not return from tile
// k while a transfer of tile k - 1 still reads its buffer (wait for it there), and after render
// returns the last tile's transfer may still be running.
using FrameSink = bool (*)(void* context, const Tile* tile);

}  // namespace tristream::core
