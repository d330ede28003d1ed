/* SPDX-License-Identifier: MIT */
/* A C program that renders a blob compiled in by tripack (-o demo_blob.c) through the C API,
   with static buffers only. Exit 0 when every tile arrived and every pixel was written, and the
   same frame rendered in place into a framebuffer with wider rows (ts_params.target) has the
   tiles' pixels and leaves the bytes between its rows alone. */
#include <stdio.h>
#include <string.h>

#include "demo_blob.h"

static uint8_t tile_buffer[32 * 32 * 2];
static uint8_t workspace[16 * 1024];
static uint8_t seen[512 * 768];
static uint8_t frame[512 * 768 * 2]; /* the tiles' pixels */
#define FB_STRIDE (768 * 2 + 6)       /* a canvas 3 pixels wider than the picture */
static uint8_t framebuffer[512 * FB_STRIDE];

struct count {
  long tiles;
  long pixels;
  long wrong_format;
};

static void sink(void* context, const ts_tile* tile) {
  struct count* c = (struct count*)context;
  int x, y;
  c->tiles++;
  if (tile->format != demo_blob.format) c->wrong_format++;
  for (y = tile->rect.y0; y < tile->rect.y1; ++y)
    for (x = tile->rect.x0; x < tile->rect.x1; ++x) {
      if (!seen[y * 768 + x]) c->pixels++;
      seen[y * 768 + x] = 1;
      frame[2 * (y * 768 + x)] = tile->pixels[(y - tile->rect.y0) * tile->stride + 2 * (x - tile->rect.x0)];
      frame[2 * (y * 768 + x) + 1] = tile->pixels[(y - tile->rect.y0) * tile->stride + 2 * (x - tile->rect.x0) + 1];
    }
}

/* Bytes of the framebuffer that differ from the tiles' frame, and gap bytes that changed. */
static long framebuffer_errors(void) {
  long errors = 0;
  int y, i;
  for (y = 0; y < 512; ++y)
    for (i = 0; i < FB_STRIDE; ++i)
      errors += i < 768 * 2 ? framebuffer[y * FB_STRIDE + i] != frame[y * 768 * 2 + i]
                            : framebuffer[y * FB_STRIDE + i] != 0x5A;
  return errors;
}

int main(void) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT; /* then ts_params_init below, which must give the same */
  struct count c = {0, 0, 0};
  uint32_t offset = 0;
  ts_status s = ts_open(demo_blob.bytes, demo_blob.size, &blob, &offset);
  if (s != TS_OK) {
    fprintf(stderr, "ts_open: %s at byte %u\n", ts_status_text(s), (unsigned)offset);
    return 1;
  }
  ts_params_init(&params);
  /* The defaults name no format (TS_FORMAT_UNSET): refused, not rendered as some default. */
  s = ts_render(&blob, &params, tile_buffer, sizeof tile_buffer, workspace, sizeof workspace, sink, &c);
  if (s != TS_BAD_PARAMS || c.tiles != 0) {
    fprintf(stderr, "zeroed ts_params: expected TS_BAD_PARAMS, got %d (%s)\n", s, ts_status_text(s));
    return 1;
  }
  params.tile_width = demo_blob.tile_width;
  params.tile_height = demo_blob.tile_height;
  params.format = demo_blob.format;
  if (demo_blob.tile_buffer_bytes > sizeof tile_buffer || demo_blob.workspace_bytes > sizeof workspace) {
    fprintf(stderr, "buffers too small for the descriptor's figures\n");
    return 1;
  }
  s = ts_render(&blob, &params, tile_buffer, sizeof tile_buffer, workspace, sizeof workspace, sink, &c);
  if (s != TS_OK) {
    fprintf(stderr, "ts_render: %s\n", ts_status_text(s));
    return 1;
  }
  printf("%ld tiles, %ld pixels, RAM %zu bytes\n", c.tiles, c.pixels,
         demo_blob.tile_buffer_bytes + demo_blob.workspace_bytes);
  if (!(c.tiles == 24 * 16 && c.wrong_format == 0 && demo_blob.format == TS_RGB565_BE &&
        c.pixels == (long)demo_blob.width * demo_blob.height))
    return 1;
  /* In place: no tile buffer, no sink. */
  memset(framebuffer, 0x5A, sizeof framebuffer);
  params.target = framebuffer;
  params.target_stride = FB_STRIDE;
  s = ts_render(&blob, &params, NULL, 0, workspace, sizeof workspace, NULL, NULL);
  if (s != TS_OK || framebuffer_errors() != 0) {
    fprintf(stderr, "ts_render into a framebuffer: %s, %ld bytes wrong\n", ts_status_text(s), framebuffer_errors());
    return 1;
  }
  params.target_stride = 768 * 2 - 1; /* shorter than a row */
  s = ts_render(&blob, &params, NULL, 0, workspace, sizeof workspace, NULL, NULL);
  if (s != TS_BAD_PARAMS) {
    fprintf(stderr, "a short target_stride: expected TS_BAD_PARAMS, got %d (%s)\n", s, ts_status_text(s));
    return 1;
  }
  printf("the same frame in place: every pixel, the gaps untouched\n");
  return 0;
}
