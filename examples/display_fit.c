/* SPDX-License-Identifier: MIT */
/* A landscape picture on a portrait 240 x 320 panel without distorting it: TS_FIT_INSIDE scales the
   768 x 512 image by one factor (239 / 767) so that all of it shows, centred, and the rows above and
   below it (80 each) get the background colour. TS_FIT_FILL would instead cover the panel and crop
   the sides. The core writes every panel pixel, border included, in bands of 16 rows.

   The blob is the one of display_zoom (kodim23_zoom.c: bilinear, RGB565 big-endian); its header's
   bounds hold for every output up to 960 x 640, any fit and bands up to 320 x 16, so the static
   buffers below are big enough here too.

   Usage on the host: display_fit [out.ppm]. Exit 0 when the panel was filled exactly once. */
#include <stdio.h>

#include "display.h"
#include "kodim23_zoom.h"

#define PANEL_WIDTH 240
#define PANEL_HEIGHT 320

static uint8_t band_buffer[KODIM23_ZOOM_TILE_BUFFER_MAX_BYTES];
static uint8_t workspace[KODIM23_ZOOM_WORKSPACE_MAX_BYTES];

static void send_band(void* context, const ts_tile* band) {
  long* pixels = (long*)context;
  const int width = band->rect.x1 - band->rect.x0, height = band->rect.y1 - band->rect.y0;
  int y;
  display_set_window(band->rect.x0, band->rect.y0, band->rect.x1, band->rect.y1);
  for (y = 0; y < height; ++y) display_write(band->pixels + (long)y * band->stride, (size_t)width * 2);
  *pixels += (long)width * height;
}

int main(int argc, char** argv) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  long pixels = 0;
  ts_status s = ts_open(kodim23_zoom.bytes, kodim23_zoom.size, &blob, NULL);
  if (s != TS_OK) {
    printf("ts_open: %s\n", ts_status_text(s));
    return 1;
  }
  params.output_width = PANEL_WIDTH;
  params.output_height = PANEL_HEIGHT;
  params.fit = TS_FIT_INSIDE;
  params.background[0] = params.background[1] = params.background[2] = 40; /* a dark grey border (R, G, B) */
  params.tile_height = 16; /* tile width 0: bands of the panel's width */
  params.format = TS_RGB565_BE;

  display_init(PANEL_WIDTH, PANEL_HEIGHT);
  s = ts_render(&blob, &params, band_buffer, sizeof band_buffer, workspace, sizeof workspace, send_band, &pixels);
  if (s != TS_OK) {
    printf("ts_render: %s\n", ts_status_text(s));
    return 1;
  }
  printf("display_fit: 768x512 inside a %dx%d panel, %ld pixels sent\n", PANEL_WIDTH, PANEL_HEIGHT, pixels);
  if (pixels != (long)PANEL_WIDTH * PANEL_HEIGHT) return 1;
  if (argc > 1 && display_save_ppm(argv[1]) != 0) {
    printf("cannot write %s\n", argv[1]);
    return 73;
  }
  return 0;
}
