/* SPDX-License-Identifier: MIT */
/* Renders a blob file through the C API in 16-row bands of RGB565 (big-endian) and checks that
   every band arrived in order and every pixel once. Prints the version it was built against.
   Usage: consumer BLOB_FILE. Exit 0 on success. */
#include <stdio.h>
#include <string.h>

#include "tristream/tristream.h"
#include "tristream/version.h"

static uint8_t blob_bytes[1 << 20];
static uint8_t tile_buffer[2048 * 16 * 2];
static uint8_t workspace[64 * 1024];

struct progress {
  long next_row;
  long pixels;
  int width;
};

static void send_band(void* context, const ts_tile* tile) {
  struct progress* p = (struct progress*)context;
  if (tile->rect.y0 == p->next_row && tile->rect.x0 == 0 && tile->rect.x1 == p->width &&
      tile->format == TS_RGB565_BE) {
    p->next_row = tile->rect.y1;
    p->pixels += (long)(tile->rect.x1 - tile->rect.x0) * (tile->rect.y1 - tile->rect.y0);
  }
}

int main(int argc, char** argv) {
  FILE* f;
  size_t size, tile_bytes, work_bytes;
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  ts_status s;
  uint32_t offset = 0;
  struct progress p = {0, 0, 0};
  if (argc != 2) return 64;
#ifdef PACKAGE_VERSION
  if (strcmp(PACKAGE_VERSION, TRISTREAM_VERSION) != 0) {
    fprintf(stderr, "consumer: package version %s, header %s\n", PACKAGE_VERSION, TRISTREAM_VERSION);
    return 1;
  }
#endif
  f = fopen(argv[1], "rb");
  if (!f) return 66;
  size = fread(blob_bytes, 1, sizeof blob_bytes, f);
  fclose(f);
  s = ts_open(blob_bytes, size, &blob, &offset);
  if (s != TS_OK) {
    fprintf(stderr, "consumer: %s: %s at byte %u\n", argv[1], ts_status_text(s), (unsigned)offset);
    return 65;
  }
  ts_params_init(&params);
  params.format = TS_RGB565_BE;
  params.tile_height = 16;
  if (ts_tile_buffer_size(&blob, &params, &tile_bytes) != TS_OK ||
      ts_workspace_size(&blob, &params, &work_bytes) != TS_OK || tile_bytes > sizeof tile_buffer ||
      work_bytes > sizeof workspace)
    return 1;
  /* The band width is the blob's: the tile buffer's size over 16 rows of 2 bytes. */
  p.width = (int)(tile_bytes / (16 * 2));
  s = ts_render(&blob, &params, tile_buffer, tile_bytes, workspace, work_bytes, send_band, &p);
  if (s != TS_OK) {
    fprintf(stderr, "consumer: ts_render: %s\n", ts_status_text(s));
    return 1;
  }
  printf("consumer: tristream %s, %d x %ld pixels in 16-row bands, tile buffer %u + workspace %u bytes\n",
         TRISTREAM_VERSION, p.width, p.next_row, (unsigned)tile_bytes, (unsigned)work_bytes);
  return p.pixels == (long)p.width * p.next_row && p.pixels > 0 ? 0 : 1;
}
