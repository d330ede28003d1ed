#pragma once
// Streaming rendering of a validated blob, band by band and tile by tile, into caller memory.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/pixel_format.h"
#include "tristream/status.h"
#include "tristream/tile.h"

namespace tristream::core {

struct RenderParams {
  // Output size; 0 means the blob's size. Output pixel (i, j) samples the domain at
  // (i * (W-1) / (W'-1), j * (H-1) / (H'-1)): corners map to corners.
  uint16_t output_width = 0;
  uint16_t output_height = 0;
  // The part of the output to render, in output pixels; an empty rectangle means all of it.
  Rect viewport;
  // Tile size in pixels; 0 means the viewport's width (bands) or height (one band).
  uint16_t tile_width = 0;
  uint16_t tile_height = 0;
  PixelFormat format = PixelFormat::rgb888;
  // Ordered 4x4 Bayer dithering of RGB565, keyed on the absolute output position.
  bool dither = false;
  // Colour of pixels outside the triangulation's domain (R, G, B; grey uses the first).
  uint8_t background[3] = {0, 0, 0};
};

// Bytes of the tile buffer: tile width * tile height * bytes per pixel (tile size after defaults).
Status tile_buffer_size(const Blob& blob, const RenderParams& params, size_t* bytes);

// Bytes of workspace `render` needs with these parameters: per layer, a bitmap of its active
// triangles (one bit per triangle of the longest window from the oldest live to the newest
// started triangle over all bands), plus, for layered blobs, a channel scratch of 6 bytes per
// tile pixel. One pass over the triangles.
Status workspace_size(const Blob& blob, const RenderParams& params, size_t* bytes);

// Renders the viewport tile by tile into `tile_buffer` and passes each tile to `sink`.
// Every pixel whose sample point lies in the domain is written by exactly one triangle; the
// output does not depend on the tile size. Never allocates.
Status render(const Blob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context);

}  // namespace tristream::core
