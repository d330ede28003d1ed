/* SPDX-License-Identifier: MIT */
/* The memory interface between the bench-mcu harness (host) and the benchmark program it runs on
   the emulated Cortex-M4 (m4/bench_main.cpp). The harness writes a bench_params into the
   program's bench_params_in, calls bench_open(), bench_prepare() and bench_render(), and reads the
   bench_result in bench_result_out. Both sides are little-endian
   with 4-byte alignment of uint32_t, so the layouts are the same (checked by the asserts). */
#ifndef TRISTREAM_BENCH_MCU_PROTOCOL_H
#define TRISTREAM_BENCH_MCU_PROTOCOL_H

#include <stdint.h>

typedef struct bench_params {
  uint32_t blob_address;  /* where the harness mapped the blob (read-only memory) */
  uint32_t blob_size;
  uint16_t output_width;  /* 0: the blob's size */
  uint16_t output_height;
  uint16_t tile_width;    /* 0: the output width (bands) */
  uint16_t tile_height;   /* 0: the output height */
  uint8_t format;         /* tristream::core::PixelFormat */
  uint8_t dither;
  uint8_t background[3];
  uint8_t reserved[3];
} bench_params;

/* Stages the program reached; a failing call leaves the stage of the last success. */
enum { BENCH_STAGE_NONE = 0, BENCH_STAGE_OPENED = 1, BENCH_STAGE_PREPARED = 2, BENCH_STAGE_RENDERED = 3 };

/* Why prepare failed besides a core status: the buffers do not fit the RAM left for them. */
#define BENCH_STATUS_NO_ROOM 0x100u

typedef struct bench_result {
  uint32_t stage;
  uint32_t status;             /* tristream::core::Status of the last call, or BENCH_STATUS_NO_ROOM */
  uint32_t tile_buffer_bytes;
  uint32_t workspace_bytes;
  uint32_t arena_bytes;        /* RAM between the static data and the reserved stack */
  uint32_t sp_before_render;   /* SP just before the call of render: the stack the core uses is below it */
  uint32_t tiles;              /* tiles the sink received */
  uint32_t hash_a;             /* tile_hash.h over every tile */
  uint32_t hash_b;
} bench_result;

#ifdef __cplusplus
static_assert(sizeof(bench_params) == 24, "bench_params layout");
static_assert(sizeof(bench_result) == 36, "bench_result layout");
#endif

#endif
