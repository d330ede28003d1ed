/* SPDX-License-Identifier: MIT */
/* The host's stand-in for an SPI panel (display.h): the pixels the panel would show, in memory,
   written out as a PPM. A board has no such copy of the frame: that is what the core avoids. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "display.h"

static uint8_t* panel; /* width * height RGB565 words, big-endian, as sent */
static int panel_width, panel_height;
static int win_x0, win_y0, win_x1, win_y1;
static long cursor; /* next pixel of the window, row-major */

void display_init(int width, int height) {
  panel_width = width;
  panel_height = height;
  panel = (uint8_t*)calloc((size_t)width * (size_t)height, 2);
  if (!panel) {
    fprintf(stderr, "display: out of memory\n");
    exit(70);
  }
}

void display_set_window(int x0, int y0, int x1, int y1) {
  win_x0 = x0;
  win_y0 = y0;
  win_x1 = x1;
  win_y1 = y1;
  cursor = 0;
}

void display_write(const uint8_t* bytes, size_t size) {
  const long width = win_x1 - win_x0;
  size_t i;
  for (i = 0; i + 1 < size; i += 2, ++cursor) {
    const long x = win_x0 + cursor % width, y = win_y0 + cursor / width;
    if (x < 0 || y < 0 || x >= panel_width || y >= panel_height || y >= win_y1) {
      fprintf(stderr, "display: pixel (%ld, %ld) outside the window or the panel\n", x, y);
      exit(70);
    }
    panel[2 * ((size_t)y * (size_t)panel_width + (size_t)x)] = bytes[i];
    panel[2 * ((size_t)y * (size_t)panel_width + (size_t)x) + 1] = bytes[i + 1];
  }
}

/* A DMA transfer on the host: the bytes are taken when it ends (display_wait), and a copy made at
   its start proves nobody wrote them in between, as a real transfer would have sent them. */
static const uint8_t* dma_bytes;
static uint8_t* dma_copy;
static size_t dma_size;

void display_write_start(const uint8_t* bytes, size_t size) {
  if (dma_bytes) {
    fprintf(stderr, "display: a transfer started while another is running\n");
    exit(70);
  }
  dma_copy = (uint8_t*)malloc(size ? size : 1);
  if (!dma_copy) {
    fprintf(stderr, "display: out of memory\n");
    exit(70);
  }
  memcpy(dma_copy, bytes, size);
  dma_bytes = bytes;
  dma_size = size;
}

void display_wait(void) {
  if (!dma_bytes) return;
  if (memcmp(dma_bytes, dma_copy, dma_size) != 0) {
    fprintf(stderr, "display: the buffer of a running transfer was written\n");
    exit(70);
  }
  display_write(dma_bytes, dma_size);
  free(dma_copy);
  dma_copy = NULL;
  dma_bytes = NULL;
}

int display_save_ppm(const char* path) {
  FILE* f = fopen(path, "wb");
  long i;
  if (!f) return 1;
  fprintf(f, "P6\n%d %d\n255\n", panel_width, panel_height);
  for (i = 0; i < (long)panel_width * panel_height; ++i) {
    /* RGB565 to 8 bits per channel, rounded: the decoding trisim uses for core frames. */
    const unsigned word = (unsigned)panel[2 * i] << 8 | panel[2 * i + 1];
    const unsigned r = word >> 11, g = (word >> 5) & 63, b = word & 31;
    fputc((int)((r * 255 + 15) / 31), f);
    fputc((int)((g * 255 + 31) / 63), f);
    fputc((int)((b * 255 + 15) / 31), f);
  }
  return fclose(f) != 0;
}
