/* SPDX-License-Identifier: MIT */
/* A 320 x 240 panel showing part of a larger picture, zoomed: the core renders the image at 1.25
   times its size (960 x 640 output pixels) but only the 320 x 240 viewport the panel shows, in
   bands of 16 rows of the viewport's width. Nothing outside the viewport is computed.

   The blob is a C array made at build time by
     tripack kodim23.rgb.tri -o kodim23_zoom.c -m bilinear -f rgb565be --width 960 --height 640
             --tile-width 320 --tile-height 16
   (examples/CMakeLists.txt). Its header's bounds hold for every output up to 960 x 640, every
   viewport of it and tiles up to 320 x 16: panning or zooming out never needs bigger buffers.

   Usage on the host: display_zoom [out.ppm]. Exit 0 when the panel was filled exactly once. */
#include <stdio.h>

#include "display.h"
#include "kodim23_zoom.h"

#define PANEL_WIDTH 320
#define PANEL_HEIGHT 240

static uint8_t band_buffer[KODIM23_ZOOM_TILE_BUFFER_MAX_BYTES];
static uint8_t workspace[KODIM23_ZOOM_WORKSPACE_MAX_BYTES];

struct panel_view {
  int x0, y0;   /* the output pixel at the panel's top-left corner */
  long pixels;  /* pixels sent */
};

/* Tiles arrive in output coordinates; the panel's window is the tile moved by the viewport's corner. */
static void send_band(void* context, const ts_tile* band) {
  struct panel_view* view = (struct panel_view*)context;
  const int width = band->rect.x1 - band->rect.x0, height = band->rect.y1 - band->rect.y0;
  int y;
  display_set_window(band->rect.x0 - view->x0, band->rect.y0 - view->y0, band->rect.x1 - view->x0,
                     band->rect.y1 - view->y0);
  for (y = 0; y < height; ++y) display_write(band->pixels + (long)y * band->stride, (size_t)width * 2);
  view->pixels += (long)width * height;
}

int main(int argc, char** argv) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  struct panel_view view = {0, 0, 0};
  size_t band_bytes = 0, workspace_bytes = 0;
  ts_status s = ts_open(kodim23_zoom.bytes, kodim23_zoom.size, &blob, NULL);
  if (s != TS_OK) {
    printf("ts_open: %s\n", ts_status_text(s));
    return 1;
  }
  /* The whole image as 960 x 640 output pixels (corner to corner: 1.25 times 768 x 512, nearly). */
  params.output_width = 960;
  params.output_height = 640;
  /* The panel shows the 320 x 240 output pixels from (470, 110): the red macaw's head. */
  view.x0 = 470;
  view.y0 = 110;
  params.viewport.x0 = view.x0;
  params.viewport.y0 = view.y0;
  params.viewport.x1 = view.x0 + PANEL_WIDTH;
  params.viewport.y1 = view.y0 + PANEL_HEIGHT;
  params.tile_width = PANEL_WIDTH;
  params.tile_height = 16;
  params.format = TS_RGB565_BE;

  if (ts_tile_buffer_size(&blob, &params, &band_bytes) != TS_OK ||
      ts_workspace_size(&blob, &params, &workspace_bytes) != TS_OK)
    return 1;
  printf("display_zoom: %dx%d of a 960x640 zoom in %dx16 bands: band buffer %lu bytes (static %lu), workspace %lu "
         "bytes (static %lu)\n",
         PANEL_WIDTH, PANEL_HEIGHT, PANEL_WIDTH, (unsigned long)band_bytes, (unsigned long)sizeof band_buffer,
         (unsigned long)workspace_bytes, (unsigned long)sizeof workspace);

  display_init(PANEL_WIDTH, PANEL_HEIGHT);
  s = ts_render(&blob, &params, band_buffer, sizeof band_buffer, workspace, sizeof workspace, send_band, &view);
  if (s != TS_OK) {
    printf("ts_render: %s\n", ts_status_text(s));
    return 1;
  }
  if (view.pixels != (long)PANEL_WIDTH * PANEL_HEIGHT) {
    printf("sent %ld pixels for a panel of %d\n", view.pixels, PANEL_WIDTH * PANEL_HEIGHT);
    return 1;
  }
  if (argc > 1 && display_save_ppm(argv[1]) != 0) {
    printf("cannot write %s\n", argv[1]);
    return 73;
  }
  return 0;
}
