/* SPDX-License-Identifier: MIT */
#pragma once
// Streaming rendering of a validated blob, band by band and tile by tile, into caller memory.
#include <stddef.h>
#include <stdint.h>

#include "tristream/blob.h"
#include "tristream/compressed_blob.h"
#include "tristream/pixel_format.h"
#include "tristream/render_params.h"
#include "tristream/status.h"
#include "tristream/tile.h"

namespace tristream::core {

// Bytes of the tile buffer: tile width * tile height * bytes per pixel (tile size after defaults);
// 0 with a target (RenderParams::target).
Status tile_buffer_size(const Blob& blob, const RenderParams& params, size_t* bytes);

// Bytes of workspace `render` needs with these parameters: per layer, a bitmap of its active
// triangles (one bit per triangle of the longest window from the oldest live to the newest
// started triangle over all bands), plus, for layered blobs, a channel scratch of 6 bytes per
// tile pixel, and 8 bytes for the alignment (a workspace starts with 1 to 8 bytes of padding to
// the next 8-aligned address): exact for an 8-aligned workspace (one byte less is
// workspace_too_small), enough at any alignment. One pass over the triangles.
Status workspace_size(const Blob& blob, const RenderParams& params, size_t* bytes);

// Renders the viewport tile by tile into `tile_buffer` (or in place into params.target) and passes
// each tile to `sink` (null_argument if null, unless there is a target).
// Every pixel whose sample point lies in the domain is written by exactly one triangle; the
// output does not depend on the tile size. Never allocates.
Status render(const Blob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context);
// The same with one or two tile buffers and a sink that may stop the frame early.
Status render(const Blob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context);

// A compressed blob ("TSTC", compressed_blob.h) rendered from its streams band by band, in the
// same band and tile order as a v1 blob and with bit-identical pixels: per layer a LayerDecoder
// and its ring and tags, and the band's live triangles (those of the stream whose rows meet the
// band) copied into a small v1-shaped layer whose vertices each live triangle's corners share, all
// in the workspace (docs/COMPRESSED_BLOB.md, "Rendering from the stream"). Its workspace is
//   8 + scratch + sum over layers (align8(decoder) + align8(ring) + align8(tags)) + layers x band
//   store, tags = compressed_tag_bytes, band store = the largest over the layers and bands of
//     need(V, C, F) with C the band's live triangles, F those with flags and V their vertices,
//     need(V, C, F) = 4 V + align4(2 v V) + 8 v V (zienkiewicz) + records
//       + max(align4(6 ceil(V / 32)), 4 ceil((C + F) / 32)),
//     records = 4 (C + F) + 4 for V <= 1,024 (10-bit slots), else align4(6 (C + F) + 2); 0 if C = 0
// (v values per vertex; the channel scratch as for a v1 blob), which only a decode of the streams
// finds: workspace_size decodes them once with `scratch` (measure_scratch_size bytes) to count
// each band's C, F and V and checks every stream to its end.
Status tile_buffer_size(const CompressedBlob& blob, const RenderParams& params, size_t* bytes);
// Bytes of scratch workspace_size(CompressedBlob) needs: 8 + align8(decoder) + align8(largest
// ring) + 12 (bands + 1) + 2 x the largest layer's vertex count (the 8 as for a workspace: exact
// for an 8-aligned scratch, enough at any alignment).
Status measure_scratch_size(const CompressedBlob& blob, const RenderParams& params, size_t* bytes);
// Bytes of workspace `render` needs for this blob and these parameters (exact for an 8-aligned
// workspace: one byte less is workspace_too_small). Decodes every stream: a damaged one returns
// its status and `error` the decoder's byte offset. The store's vertex slots hold any layer (at
// most 65,535 vertices); its triangles are bounded by the workspace only.
Status workspace_size(const CompressedBlob& blob, const RenderParams& params, void* scratch, size_t scratch_bytes,
                      size_t* bytes, BlobError* error = nullptr);
// The terms of that workspace (bytes == 8 + channel_scratch + decoders + layers x band_store).
struct CompressedWorkspace {
  size_t bytes = 0;
  size_t channel_scratch = 0;
  size_t decoders = 0;          // per layer: the decoder object, the held triangle, its ring and tags
  size_t band_store = 0;        // per layer: the largest need(V, C, F) of a band
  uint32_t live_triangles = 0;  // the most live triangles of a layer in one band
  uint32_t live_vertices = 0;   // the most vertices of a layer's live triangles in one band
};
Status workspace_size(const CompressedBlob& blob, const RenderParams& params, void* scratch, size_t scratch_bytes,
                      CompressedWorkspace* figures, BlobError* error = nullptr);
// Renders a compressed blob from its streams. The decoders, rings and the channel scratch are
// checked before the first tile; a band's live triangles only when the band is reached, so with
// less workspace than workspace_size a frame can stop after some tiles with workspace_too_small,
// and a stream damaged past the first band stops it with the decoder's status (and `error` its
// offset). A blob workspace_size accepted, given that many bytes, renders whole. Never allocates.
Status render(const CompressedBlob& blob, const RenderParams& params, const RenderBuffers& buffers, FrameSink sink,
              void* context, BlobError* error = nullptr);
Status render(const CompressedBlob& blob, const RenderParams& params, void* tile_buffer, size_t tile_buffer_bytes,
              void* workspace, size_t workspace_bytes, TileSink sink, void* context);

}  // namespace tristream::core
