/* SPDX-License-Identifier: MIT */
/* The display the examples draw on, as an SPI panel driver would offer it (ST7789, ILI9341):
   choose a window of the panel, then stream the window's pixels row by row, RGB565 high byte
   first. On a board these are the driver's calls; on the host, host_display.c keeps the panel's
   pixels in memory and writes them as a PPM file, so the examples run as they are. */
#ifndef EXAMPLES_DISPLAY_H
#define EXAMPLES_DISPLAY_H

#include <stddef.h>
#include <stdint.h>

/* The panel's size in pixels. */
void display_init(int width, int height);
/* Columns x0..x1-1 and rows y0..y1-1 receive the next pixels (CASET, RASET, then RAMWR). */
void display_set_window(int x0, int y0, int x1, int y1);
/* Sends `size` bytes of RGB565 big-endian pixels into the window, filling it row by row. Returns
   when the bytes may be overwritten (a blocking SPI transfer, or a DMA transfer waited for). */
void display_write(const uint8_t* bytes, size_t size);
/* DMA: starts sending `size` bytes into the window and returns at once; the bytes must stay
   unchanged until display_wait returns. At most one transfer at a time. */
void display_write_start(const uint8_t* bytes, size_t size);
/* Waits for the transfer display_write_start began (returns at once if there is none). */
void display_wait(void);
/* Host only: writes what the panel shows to `path` as a binary PPM. Returns 0 on success. */
int display_save_ppm(const char* path);

#endif
