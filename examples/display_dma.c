/* SPDX-License-Identifier: MIT */
/* Double buffering for a DMA display pipeline: the core draws each 16-row band into one of two
   static band buffers while the DMA engine sends the band before from the other, in one
   ts_render_frame call (the tiles alternate between ts_buffers.tile[0] and tile[1]).

   The rule that makes this safe (tristream.h, ts_frame_sink): as soon as the sink returns from
   band k, the core draws band k + 1 into the buffer of band k - 1. So the sink first waits for
   the transfer of band k - 1, then starts the transfer of band k and returns at once; after the
   render, the last transfer is waited for. The sink could also return 0 to stop the frame (for
   example when a newer frame is wanted), and ts_render_frame would return TS_STOPPED.

   The blob is the one of display_bands.c (kodim23.h), so the panel must show the same picture.
   Usage on the host: display_dma [out.ppm]. Exit 0 when every band arrived in order. */
#include <stdio.h>

#include "display.h"
#include "kodim23.h"

static uint8_t band_buffers[2][KODIM23_TILE_BUFFER_MAX_BYTES];
static uint8_t workspace[KODIM23_WORKSPACE_MAX_BYTES];

struct progress {
  int next_row;
  int bands;
};

static int send_band(void* context, const ts_tile* band) {
  struct progress* p = (struct progress*)context;
  if (band->rect.y0 != p->next_row) return 0; /* bands come top to bottom: stop on anything else */
  p->next_row = band->rect.y1;
  ++p->bands;
  display_wait(); /* band k - 1's buffer is drawn into as soon as this returns */
  display_set_window(band->rect.x0, band->rect.y0, band->rect.x1, band->rect.y1);
  /* packed_tiles: the band's rows are back to back, one transfer of the whole band. */
  display_write_start(band->pixels, (size_t)(band->rect.y1 - band->rect.y0) * (size_t)band->stride);
  return 1;
}

int main(int argc, char** argv) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  ts_buffers buffers;
  struct progress progress = {0, 0};
  uint32_t error_offset = 0;
  ts_status s;

  s = ts_open(kodim23.bytes, kodim23.size, &blob, &error_offset);
  if (s != TS_OK) {
    printf("ts_open: %s (byte %lu)\n", ts_status_text(s), (unsigned long)error_offset);
    return 1;
  }
  params.tile_height = 16;
  params.format = TS_RGB565_BE;
  params.dither = 1;
  params.packed_tiles = 1;

  buffers.tile[0] = band_buffers[0];
  buffers.tile[1] = band_buffers[1];
  buffers.tile_size = sizeof band_buffers[0];
  buffers.workspace = workspace;
  buffers.workspace_size = sizeof workspace;

  display_init(kodim23.width, kodim23.height);
  s = ts_render_frame(&blob, &params, &buffers, send_band, &progress);
  display_wait(); /* the last band's transfer */
  if (s != TS_OK) {
    printf("ts_render_frame: %s\n", ts_status_text(s));
    return 1;
  }
  printf("display_dma: %u x %u in %d bands through two band buffers of %lu bytes, workspace %lu bytes\n",
         (unsigned)kodim23.width, (unsigned)kodim23.height, progress.bands, (unsigned long)sizeof band_buffers[0],
         (unsigned long)sizeof workspace);
  if (progress.next_row != kodim23.height) {
    printf("bands out of order: reached row %d of %u\n", progress.next_row, (unsigned)kodim23.height);
    return 1;
  }
  if (argc > 1 && display_save_ppm(argv[1]) != 0) {
    printf("cannot write %s\n", argv[1]);
    return 73;
  }
  return 0;
}
