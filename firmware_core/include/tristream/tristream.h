/* SPDX-License-Identifier: MIT */
/* The C interface of the tristream core: open a blob, size the buffers, render tile by tile.
   Thin wrappers over the C++ API in tristream/render.h; all memory belongs to the caller. */
#ifndef TRISTREAM_TRISTREAM_H
#define TRISTREAM_TRISTREAM_H

#include <stddef.h>
#include <stdint.h>

/* The configuration's macros alone: this header stays C89 and C++98 (config.h). */
#define TS_CONFIG_MACROS_ONLY
#include "tristream/config.h"
#undef TS_CONFIG_MACROS_ONLY

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes: the values of tristream::core::Status (status.h has what each means), named
   TS_ plus the C++ enumerator in capitals; c_api.cpp checks each against the C++ enum. */
typedef int ts_status;
enum {
  TS_OK = 0,
  TS_NULL_ARGUMENT = 1,
  TS_TRUNCATED = 2,
  TS_BAD_MAGIC = 3,
  TS_BAD_VERSION = 4,
  TS_CONFIG_MISMATCH = 5,
  TS_BAD_HEADER = 6,
  TS_BAD_SECTION = 7,
  TS_TOO_LARGE = 8,
  TS_COORDINATE_OUT_OF_RANGE = 9,
  TS_VALUE_OUT_OF_RANGE = 10,
  TS_BAD_INDEX = 11,
  TS_BAD_TRIANGLE = 12,
  TS_UNSORTED = 13,
  TS_BAD_PARAMS = 14,
  TS_TILE_BUFFER_TOO_SMALL = 15,
  TS_NOT_COMPILED = 16,
  TS_WORKSPACE_TOO_SMALL = 17, /* checked before the first tile: no partial frame */
  TS_STOPPED = 18,             /* a ts_frame_sink returned 0 */
  TS_BAD_CHECKSUM = 19         /* the blob's bytes do not match its CRC-32: damaged; offset 36 */
};

/* Pixel formats (tristream/pixel_format.h has their bytes). 0 is no format: a zeroed ts_params
   is refused with TS_BAD_PARAMS rather than rendered in a format nobody chose. An SPI display
   such as the ST7789 or ILI9341 takes TS_RGB565_BE (high byte first). */
enum {
  TS_FORMAT_UNSET = 0,
  TS_L8 = 1,
  TS_RGB888 = 2,
  TS_RGB565_LE = 3,
  TS_RGB565_BE = 4,
  TS_XRGB8888 = 5
};

/* How the triangulation maps to an output of another shape (docs/CONVENTIONS.md, "Fitting"):
   stretched corner to corner (0, a zeroed ts_params), or with one scale for both axes, either the
   whole picture centred inside a border of the background colour, or the output filled and the
   excess cropped equally from both sides. */
enum {
  TS_FIT_STRETCH = 0,
  TS_FIT_INSIDE = 1,
  TS_FIT_FILL = 2
};

/* An opened (validated) blob; treat as opaque. */
typedef struct ts_blob {
  uint64_t storage[24];
} ts_blob;

typedef struct ts_rect {
  int32_t x0, y0, x1, y1; /* half-open: columns x0..x1-1, rows y0..y1-1 */
} ts_rect;

typedef struct ts_tile {
  uint8_t* pixels;
  int32_t stride; /* bytes per row */
  ts_rect rect;
  int format; /* TS_L8 ... TS_XRGB8888 */
} ts_tile;

typedef void (*ts_sink)(void* context, const ts_tile* tile);

/* A sink that may stop the frame: returns nonzero to go on, 0 to stop (ts_render_frame then
   returns TS_STOPPED). With two tile buffers, tile k + 1 goes into the buffer of tile k - 1 as soon
   as the sink returns from tile k: the sink must not return from tile k while a transfer (DMA) of
   tile k - 1 still reads its buffer (wait for that transfer there), and after ts_render_frame
   returns, the last tile's transfer may still be running. */
typedef int (*ts_frame_sink)(void* context, const ts_tile* tile);

/* Caller memory of ts_render_frame: one tile buffer, or two that the tiles alternate between
   (first, second, first, ...), each of tile_size bytes; and the workspace. */
typedef struct ts_buffers {
  void* tile[2]; /* tile[1] NULL: every tile in tile[0] */
  size_t tile_size;
  void* workspace;
  size_t workspace_size;
} ts_buffers;

/* What tripack -o x.c emits besides the bytes: the blob and the buffer sizes it measured for
   the tile size, pixel format and output size it was given (with --compress the bytes are a
   compressed blob, for ts_open_compressed, and the sizes those of ts_render_compressed). */
typedef struct ts_blob_descriptor {
  const uint8_t* bytes;
  size_t size;
  uint16_t width, height;               /* the triangulation's size */
  uint16_t output_width, output_height; /* the size the RAM figures are for */
  uint16_t tile_width, tile_height;
  int format; /* TS_L8 ... TS_XRGB8888 */
  size_t tile_buffer_bytes;
  size_t workspace_bytes;
} ts_blob_descriptor;

typedef struct ts_params {
  uint16_t output_width, output_height; /* 0: the blob's size */
  ts_rect viewport;                     /* all zeros: the whole output; another empty one is refused */
  uint16_t tile_width, tile_height;     /* 0: the viewport's width / height */
  int format;                           /* required: TS_L8 ... TS_XRGB8888 */
  int dither; /* nonzero: Bayer dithering for RGB565 */
  uint8_t background[3];
  int packed_tiles; /* nonzero: stride = each tile's own width (a tile is one contiguous transfer) */
  int fit;          /* TS_FIT_STRETCH (0), TS_FIT_INSIDE or TS_FIT_FILL; another value is refused */
  /* Render in place into a framebuffer (target NULL: into the tile buffers). Pixel (x, y) of the
     viewport goes to target + (y - viewport.y0) * target_stride + (x - viewport.x0) * bytes per
     pixel: a canvas or partial framebuffer covering the viewport (with the default viewport, the
     whole output). target_stride is bytes per row, 0 for the viewport's width; negative for a
     bottom-up buffer (target at the viewport's top row). No tile buffer is needed (NULL, 0 bytes;
     the size calls say 0); the sink, which may then be NULL, gets each finished tile pointing into
     the target, to flush that rectangle. Only the viewport's pixels are read or written. Refused
     (TS_BAD_PARAMS): |target_stride| less than the viewport's width in bytes or more than 2^19
     (524,288), packed_tiles with a target, a target_stride without one. */
  int32_t target_stride;
  void* target;
} ts_params;

/* Every field of a ts_params at its default: the blob's size, the whole output, tiles of the whole
   viewport, no format yet (set one: TS_FORMAT_UNSET is refused), no dithering, a black background,
   rows of the tile buffer's width, stretched, into the tile buffers (no target). Start every ts_params from it, by
   `ts_params p = TS_PARAMS_INIT;` or by ts_params_init(&p), then set the fields you need: a
   ts_params left uninitialised renders or fails at random, and one filled field by field misses
   the fields a later version adds. Both are kept in step with the struct by the core's build. */
#define TS_PARAMS_INIT {0, 0, {0, 0, 0, 0}, 0, 0, TS_FORMAT_UNSET, 0, {0, 0, 0}, 0, TS_FIT_STRETCH, 0, NULL}
void ts_params_init(ts_params* params);

/* Validates the blob at `bytes` and fills `blob`. `size` may be more than the blob (the total size
   its header records; a padded flash section): the bytes after it are not read. On failure
   *error_offset (if not null) is the byte offset of the offending field. Returns TS_OK or a
   status code: TS_BAD_CHECKSUM for bytes that do not match the blob's CRC-32, TS_BAD_VERSION for
   a blob of version 1 (no checksum: pack it again with tripack). It reads every byte of the blob,
   twice (its CRC-32, then its fields; docs/FORMAT.md has the cost): call it once, not once a
   frame, and keep `blob` for every frame.
   The blob is read in place by every later call: its bytes must stay where they are, unchanged,
   while `blob` is used. On a core without unaligned halfword loads (ARMv6-M: Cortex-M0, M0+) the
   blob must start at an even address (tripack's C arrays are 4-aligned): an odd one is
   TS_BAD_SECTION at offset 0. */
ts_status ts_open(const void* bytes, size_t size, ts_blob* blob, uint32_t* error_offset);
/* Bytes of tile buffer and of workspace needed for these parameters. */
ts_status ts_tile_buffer_size(const ts_blob* blob, const ts_params* params, size_t* bytes);
ts_status ts_workspace_size(const ts_blob* blob, const ts_params* params, size_t* bytes);
/* Renders the viewport; each finished tile goes to sink(context, tile). The sink may be NULL
   only with a target (ts_params.target); so may the tile buffer, in both calls. Every render call
   (these two and ts_render_compressed) refuses with TS_BAD_PARAMS a tile buffer (its
   tile_buffer_size bytes; with two, either of them) or a target (its viewport's bytes) that
   shares a byte with the workspace (workspace_size bytes), and two tile buffers that share one:
   the workspace holds the frame's state, which pixels must not overwrite. */
ts_status ts_render(const ts_blob* blob, const ts_params* params, void* tile_buffer, size_t tile_buffer_size,
                    void* workspace, size_t workspace_size, ts_sink sink, void* context);
/* The same with one or two tile buffers and a sink that may stop the frame. */
ts_status ts_render_frame(const ts_blob* blob, const ts_params* params, const ts_buffers* buffers, ts_frame_sink sink,
                          void* context);
/* A compressed blob ("TSTC", tripack --compress, docs/COMPRESSED_BLOB.md), rendered from its
   streams band by band with bit-identical pixels; treat as opaque. */
typedef struct ts_compressed_blob {
  uint64_t storage[24];
} ts_compressed_blob;

/* Checks the header and the layer table (the streams are checked as they are decoded). As for
   ts_open, `size` may be more than the blob: the bytes after its total size are not read. */
ts_status ts_open_compressed(const void* bytes, size_t size, ts_compressed_blob* blob, uint32_t* error_offset);
ts_status ts_compressed_tile_buffer_size(const ts_compressed_blob* blob, const ts_params* params, size_t* bytes);
/* Bytes of scratch ts_compressed_workspace_size needs (its measure decodes every stream once). */
ts_status ts_compressed_scratch_size(const ts_compressed_blob* blob, const ts_params* params, size_t* bytes);
/* Bytes of workspace the render needs (exact for an 8-aligned workspace); a damaged stream returns
   its status and *error_offset (if not null) the decoder's byte offset. */
ts_status ts_compressed_workspace_size(const ts_compressed_blob* blob, const ts_params* params, void* scratch,
                                       size_t scratch_size, size_t* bytes, uint32_t* error_offset);
/* Renders the viewport from the streams. With less workspace than ts_compressed_workspace_size a
   frame can stop after some tiles with TS_WORKSPACE_TOO_SMALL, and a stream damaged beyond the
   first band stops it with the decoder's status; a blob ts_compressed_workspace_size accepted,
   given that many bytes, renders whole. */
ts_status ts_render_compressed(const ts_compressed_blob* blob, const ts_params* params, const ts_buffers* buffers,
                               ts_frame_sink sink, void* context, uint32_t* error_offset);
/* A short English description of a status code. */
const char* ts_status_text(ts_status status);

#ifdef __cplusplus
}
#endif

#endif
