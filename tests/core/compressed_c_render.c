/* SPDX-License-Identifier: MIT */
/* The C API's render of a compressed blob (tripack --compress -o x.c) from its streams: the frame
   equals the C API's render of the v1 blob of the same mesh (the file argv[1]), byte for byte, in
   RGB565 32x32 tiles and in 16-row bands; the workspace ts_compressed_workspace_size gives
   suffices and one byte less is TS_WORKSPACE_TOO_SMALL; for the descriptor's own parameters (the
   whole 768x512 output in RGB565 big-endian 32x32 tiles) the sizes are the descriptor's. Exit 0
   when all hold. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo_compressed.h"

struct frame {
  uint8_t* pixels;
  int width;
  long tiles;
};

static int collect(void* context, const ts_tile* tile) {
  struct frame* f = (struct frame*)context;
  int y;
  for (y = tile->rect.y0; y < tile->rect.y1; ++y)
    memcpy(f->pixels + ((size_t)y * f->width + tile->rect.x0) * 2, tile->pixels + (size_t)(y - tile->rect.y0) * tile->stride,
           (size_t)(tile->rect.x1 - tile->rect.x0) * 2);
  f->tiles++;
  return 1;
}

/* Buffers from malloc: 16-aligned on the test hosts, so the workspace size is exact. */
static int check(const ts_blob* v1, const ts_compressed_blob* c, const ts_params* p, int w, int h,
                 const ts_blob_descriptor* expected) {
  size_t tile = 0, work = 0, scratch_size = 0, cwork = 0, ctile = 0;
  uint32_t offset = 0;
  ts_buffers b;
  struct frame a, z;
  void* scratch;
  int ok = 1;
  ts_status s;
  if (ts_tile_buffer_size(v1, p, &tile) != TS_OK || ts_workspace_size(v1, p, &work) != TS_OK) return 0;
  if (ts_compressed_tile_buffer_size(c, p, &ctile) != TS_OK || ctile != tile) return 0;
  if (ts_compressed_scratch_size(c, p, &scratch_size) != TS_OK) return 0;
  scratch = malloc(scratch_size);
  s = ts_compressed_workspace_size(c, p, scratch, scratch_size, &cwork, &offset);
  free(scratch);
  if (s != TS_OK) {
    fprintf(stderr, "ts_compressed_workspace_size: %s at byte %u\n", ts_status_text(s), (unsigned)offset);
    return 0;
  }
  if (expected && (cwork != expected->workspace_bytes || ctile != expected->tile_buffer_bytes)) {
    fprintf(stderr, "descriptor: tile buffer %lu, workspace %lu; measured %lu, %lu\n",
            (unsigned long)expected->tile_buffer_bytes, (unsigned long)expected->workspace_bytes, (unsigned long)ctile,
            (unsigned long)cwork);
    return 0;
  }
  a.pixels = calloc((size_t)w * h, 2);
  z.pixels = calloc((size_t)w * h, 2);
  a.width = z.width = w;
  a.tiles = z.tiles = 0;
  memset(&b, 0, sizeof b);
  b.tile[0] = malloc(tile);
  b.tile_size = tile;
  b.workspace = malloc(work);
  b.workspace_size = work;
  if (ts_render_frame(v1, p, &b, collect, &a) != TS_OK) ok = 0;
  free(b.workspace);
  b.workspace = malloc(cwork);
  b.workspace_size = cwork - 1;
  if (ts_render_compressed(c, p, &b, collect, &z, &offset) != TS_WORKSPACE_TOO_SMALL) ok = 0;
  z.tiles = 0;
  b.workspace_size = cwork;
  s = ts_render_compressed(c, p, &b, collect, &z, &offset);
  if (s != TS_OK || z.tiles != a.tiles || memcmp(a.pixels, z.pixels, (size_t)w * h * 2) != 0) ok = 0;
  printf("tiles %ux%u: compressed render %s (%s), workspace %zu bytes (v1 %zu)\n", (unsigned)p->tile_width,
         (unsigned)p->tile_height, ok ? "identical" : "DIFFERS", ts_status_text(s), cwork, work);
  free(b.tile[0]);
  free(b.workspace);
  free(a.pixels);
  free(z.pixels);
  return ok;
}

int main(int argc, char** argv) {
  FILE* in;
  long size;
  uint8_t* bytes;
  ts_blob v1;
  ts_compressed_blob c;
  ts_params p = TS_PARAMS_INIT;
  int ok = 1;
  if (argc != 2 || !(in = fopen(argv[1], "rb"))) return 64;
  fseek(in, 0, SEEK_END);
  size = ftell(in);
  fseek(in, 0, SEEK_SET);
  bytes = malloc((size_t)size);
  if (fread(bytes, 1, (size_t)size, in) != (size_t)size) return 74;
  fclose(in);
  if (ts_open(bytes, (size_t)size, &v1, NULL) != TS_OK) return 1;
  if (ts_open_compressed(demo_compressed.bytes, demo_compressed.size, &c, NULL) != TS_OK) return 2;
  if (ts_open_compressed(bytes, (size_t)size, &c, NULL) != TS_BAD_MAGIC) return 3;
  if (ts_open_compressed(demo_compressed.bytes, demo_compressed.size, &c, NULL) != TS_OK) return 2;
  if (demo_compressed.size != DEMO_COMPRESSED_BYTES || demo_compressed.format != TS_RGB565_BE ||
      demo_compressed.tile_width != 32 || demo_compressed.tile_height != 32 || demo_compressed.output_width != 768 ||
      demo_compressed.output_height != 512)
    return 4;
  p.format = TS_RGB565_BE;
  p.tile_width = p.tile_height = 32;
  ok &= check(&v1, &c, &p, 768, 512, &demo_compressed);
  p.tile_width = 0;
  p.tile_height = 16;
  ok &= check(&v1, &c, &p, 768, 512, NULL);
  free(bytes);
  return ok ? 0 : 1;
}
