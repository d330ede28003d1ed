/* SPDX-License-Identifier: MIT */
/* A picture on an SPI panel without a framebuffer: the core renders the blob in bands of 16 rows
   into one static band buffer, and each band goes to the panel as soon as it is ready.

   The blob is a C array made at build time by
     tripack kodim23.rgb.tri -o kodim23.c -m zienkiewicz -f rgb565be --tile-width 0 --tile-height 16
   (examples/CMakeLists.txt). kodim23.h declares the descriptor `kodim23` and the largest band buffer
   and workspace any render of it in bands up to 16 rows needs, so the buffers below are static
   and always big enough; nothing is allocated.

   Usage on the host: display_bands [out.ppm]. Exit 0 when every band arrived in order. */
#include <stdio.h>

#include "display.h"
#include "kodim23.h"

static uint8_t band_buffer[KODIM23_TILE_BUFFER_MAX_BYTES];
static uint8_t workspace[KODIM23_WORKSPACE_MAX_BYTES];

/* The sink: the core calls it with each finished band and reuses band_buffer once it returns, so
   the transfer completes before returning (with DMA, wait for it here). */
static void send_band(void* context, const ts_tile* band) {
  int* next_row = (int*)context;
  int y;
  if (band->rect.y0 != *next_row) return; /* bands come top to bottom; main checks the count */
  *next_row = band->rect.y1;
  display_set_window(band->rect.x0, band->rect.y0, band->rect.x1, band->rect.y1);
  /* The rows are contiguous when stride is the band's width: one transfer. Written per row so
     the code stays right for any stride. */
  for (y = 0; y < band->rect.y1 - band->rect.y0; ++y)
    display_write(band->pixels + (long)y * band->stride, (size_t)(band->rect.x1 - band->rect.x0) * 2);
}

int main(int argc, char** argv) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  uint32_t error_offset = 0;
  size_t band_bytes = 0, workspace_bytes = 0;
  int next_row = 0;
  ts_status s;

  /* Validate the blob once; it stays in flash and is read in place by every render. */
  s = ts_open(kodim23.bytes, kodim23.size, &blob, &error_offset);
  if (s != TS_OK) {
    printf("ts_open: %s (byte %lu)\n", ts_status_text(s), (unsigned long)error_offset);
    return 1;
  }

  /* Output size 0 x 0: the blob's own (768 x 512). Bands: tile width 0 (the whole width), 16 rows. */
  params.tile_height = 16;
  params.format = TS_RGB565_BE; /* what the panel takes on the wire: RGB565, high byte first */
  params.dither = 1;            /* ordered dithering hides the banding of 5- and 6-bit channels */

  /* What this render needs exactly (the static buffers hold the bound for every render). */
  if (ts_tile_buffer_size(&blob, &params, &band_bytes) != TS_OK ||
      ts_workspace_size(&blob, &params, &workspace_bytes) != TS_OK)
    return 1;
  printf(
      "display_bands: %u x %u in 16-row bands: band buffer %lu bytes (static %lu), workspace %lu bytes (static %lu)\n",
      (unsigned)kodim23.width, (unsigned)kodim23.height, (unsigned long)band_bytes, (unsigned long)sizeof band_buffer,
      (unsigned long)workspace_bytes, (unsigned long)sizeof workspace);

  display_init(kodim23.width, kodim23.height);
  s = ts_render(&blob, &params, band_buffer, sizeof band_buffer, workspace, sizeof workspace, send_band, &next_row);
  if (s != TS_OK) {
    printf("ts_render: %s\n", ts_status_text(s));
    return 1;
  }
  if (next_row != kodim23.height) {
    printf("bands out of order: reached row %d of %u\n", next_row, (unsigned)kodim23.height);
    return 1;
  }
  if (argc > 1 && display_save_ppm(argv[1]) != 0) {
    printf("cannot write %s\n", argv[1]);
    return 73;
  }
  return 0;
}
