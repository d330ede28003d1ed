/* SPDX-License-Identifier: MIT */
/* Firmware-shaped use of the core on Cortex-M4: a blob in flash, static tile buffer and
   workspace, tiles pushed to a display stub. Links no allocator (checked by build.sh). */
#include <stddef.h>
#include <stdint.h>

#include "tristream/tristream.h"

extern const uint8_t golden_blob[];
extern const size_t golden_blob_size;

static uint8_t tile_buffer[32 * 32 * 2];
static uint8_t workspace[8 * 1024];
volatile uint32_t display_checksum;

static void send_to_display(void* context, const ts_tile* tile) {
  uint32_t sum = *(uint32_t*)context;
  for (int32_t y = 0; y < tile->rect.y1 - tile->rect.y0; ++y)
    for (int32_t x = 0; x < 2 * (tile->rect.x1 - tile->rect.x0); ++x)
      sum = sum * 31u + tile->pixels[y * tile->stride + x];
  *(uint32_t*)context = sum;
}

int main(void) {
  ts_blob blob;
  ts_params params = TS_PARAMS_INIT;
  uint32_t sum = 0;
  if (ts_open(golden_blob, golden_blob_size, &blob, NULL) != TS_OK) return 1;
  params.tile_width = 32;
  params.tile_height = 32;
  params.format = TS_RGB565_BE;
  params.dither = 1;
  if (ts_render(&blob, &params, tile_buffer, sizeof tile_buffer, workspace, sizeof workspace, send_to_display, &sum) !=
      TS_OK)
    return 2;
  display_checksum = sum;
  return 0;
}
