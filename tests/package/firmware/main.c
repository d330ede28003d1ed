/* SPDX-License-Identifier: MIT */
/* A firmware-shaped consumer of an installed Cortex-M core (tests/package/check_preset.sh): a v1
   blob (ok.c) and a compressed one (okc.c), each rendered through its descriptor into static
   buffers sized by its header's bounds. Linked, not run: the test is of the build set-up. */
#include "ok.h"
#include "okc.h"

static uint8_t tile[OK_TILE_BUFFER_MAX_BYTES];
static uint8_t work[OK_WORKSPACE_MAX_BYTES];
static uint8_t ctile[OKC_TILE_BUFFER_MAX_BYTES];
static uint8_t cwork[OKC_WORKSPACE_MAX_BYTES];
static uint32_t checksum;

static void sink(void* context, const ts_tile* t) {
  (void)context;
  checksum += t->pixels[0];
}

static int frame_sink(void* context, const ts_tile* t) {
  sink(context, t);
  return 1;
}

static void params_of(const ts_blob_descriptor* d, ts_params* p) {
  ts_params_init(p);
  p->output_width = d->output_width;
  p->output_height = d->output_height;
  p->tile_width = d->tile_width;
  p->tile_height = d->tile_height;
  p->format = d->format;
}

int main(void) {
  ts_blob blob;
  ts_compressed_blob cblob;
  ts_params p = TS_PARAMS_INIT;
  ts_buffers b;
  ts_status s;
  params_of(&ok, &p);
  s = ts_open(ok.bytes, ok.size, &blob, 0);
  if (s == TS_OK) s = ts_render(&blob, &p, tile, sizeof tile, work, sizeof work, sink, 0);
  params_of(&okc, &p);
  b.tile[0] = ctile;
  b.tile[1] = 0;
  b.tile_size = sizeof ctile;
  b.workspace = cwork;
  b.workspace_size = sizeof cwork;
  if (s == TS_OK) s = ts_open_compressed(okc.bytes, okc.size, &cblob, 0);
  if (s == TS_OK) s = ts_render_compressed(&cblob, &p, &b, frame_sink, 0, 0);
  return s == TS_OK && checksum != 0 ? 0 : 1;
}
