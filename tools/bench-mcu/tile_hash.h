/* SPDX-License-Identifier: MIT */
/* A 64-bit digest of the tiles a render delivers, computed the same way by the benchmark program
   on the emulated Cortex-M4 and by the host build of the core: each tile's rectangle, then its
   rows' bytes (width * bytes per pixel from each row). Two independent 32-bit hashes (FNV-1a, and
   a multiplicative one seeded differently), so equal digests mean equal pixels, tile order and
   tile shapes up to a 2^-64 accident. */
#ifndef TRISTREAM_BENCH_MCU_TILE_HASH_H
#define TRISTREAM_BENCH_MCU_TILE_HASH_H

#include <stdint.h>

typedef struct tile_hash {
  uint32_t a;
  uint32_t b;
  uint32_t tiles;
} tile_hash;

static inline void tile_hash_init(tile_hash* h) {
  h->a = 2166136261u;
  h->b = 0x9E3779B9u;
  h->tiles = 0;
}

static inline void tile_hash_byte(tile_hash* h, uint32_t byte) {
  h->a = (h->a ^ byte) * 16777619u;
  h->b = (h->b + byte + 1u) * 2654435761u;
}

static inline void tile_hash_word(tile_hash* h, uint32_t w) {
  for (int i = 0; i < 4; ++i) tile_hash_byte(h, (w >> (8 * i)) & 0xFFu);
}

/* rect: x0, y0, x1, y1 (half-open, output pixels); rows of (x1 - x0) * bytes_per_pixel bytes. */
static inline void tile_hash_tile(tile_hash* h, const uint8_t* pixels, int32_t stride, int32_t x0, int32_t y0,
                                  int32_t x1, int32_t y1, int32_t bytes_per_pixel) {
  tile_hash_word(h, (uint32_t)x0);
  tile_hash_word(h, (uint32_t)y0);
  tile_hash_word(h, (uint32_t)x1);
  tile_hash_word(h, (uint32_t)y1);
  const int32_t row_bytes = (x1 - x0) * bytes_per_pixel;
  for (int32_t y = 0; y < y1 - y0; ++y) {
    const uint8_t* row = pixels + y * stride;
    for (int32_t i = 0; i < row_bytes; ++i) tile_hash_byte(h, row[i]);
  }
  h->tiles += 1;
}

#endif
