// SPDX-License-Identifier: MIT
// The benchmark program for the emulated Cortex-M4: renders the blob the harness mapped, with the
// parameters it wrote (bench_protocol.h), into buffers carved from the RAM between the static
// data and the stack (bench.ld), and digests every tile in bench_sink. No heap, no start-up code:
// the harness loads the segments, sets SP and calls bench_open (counted apart: what ts_open costs),
// bench_prepare, then bench_render. A compressed
// blob (magic "TSTC") is rendered from its streams: prepare measures its workspace with the arena
// as the measure's scratch (workspace_size decodes the streams once), render draws it. The RISC-V
// build (../riscv) compiles this same file.
#include <stddef.h>
#include <stdint.h>

#include "bench_protocol.h"
#include "tile_hash.h"
#include "tristream/compressed_blob.h"
#include "tristream/render.h"

using namespace tristream::core;

extern "C" {
bench_params bench_params_in;
bench_result bench_result_out;
extern uint8_t __arena_start[];
extern uint8_t __arena_end[];
void bench_open();
void bench_prepare();
void bench_render();
void bench_sink(void* context, const Tile* tile);
}

namespace {

Blob blob;
CompressedBlob compressed;
bool is_compressed = false;
RenderParams params;
uint8_t* tile_buffer;
uint8_t* workspace;
tile_hash digest;

}  // namespace

// Opens the blob as ts_open / ts_open_compressed do (the C calls are these plus a copy).
extern "C" void bench_open() {
  bench_result& r = bench_result_out;
  r = bench_result{};
  const bench_params& in = bench_params_in;
  const void* bytes = reinterpret_cast<const void*>(uintptr_t(in.blob_address));
  is_compressed = is_compressed_blob(bytes, in.blob_size);
  Status s = is_compressed ? open_compressed_blob(bytes, in.blob_size, &compressed) : open_blob(bytes, in.blob_size, &blob);
  r.status = uint32_t(s);
  if (s == Status::ok) r.stage = BENCH_STAGE_OPENED;
}

extern "C" void bench_prepare() {
  bench_result& r = bench_result_out;
  if (r.stage != BENCH_STAGE_OPENED) return;
  const bench_params& in = bench_params_in;
  Status s = Status::ok;
  params = RenderParams{};
  params.output_width = in.output_width;
  params.output_height = in.output_height;
  params.tile_width = in.tile_width;
  params.tile_height = in.tile_height;
  params.format = PixelFormat(in.format);
  params.dither = in.dither != 0;
  for (int c = 0; c < 3; ++c) params.background[c] = in.background[c];
  size_t tile_bytes = 0, work_bytes = 0;
  r.arena_bytes = uint32_t(__arena_end - __arena_start);
  if (is_compressed) {
    size_t scratch_bytes = 0;
    s = tile_buffer_size(compressed, params, &tile_bytes);
    if (s == Status::ok) s = measure_scratch_size(compressed, params, &scratch_bytes);
    if (s == Status::ok && scratch_bytes > r.arena_bytes) {
      r.status = BENCH_STATUS_NO_ROOM;
      return;
    }
    if (s == Status::ok) s = workspace_size(compressed, params, __arena_start, scratch_bytes, &work_bytes);
  } else {
    s = tile_buffer_size(blob, params, &tile_bytes);
    if (s == Status::ok) s = workspace_size(blob, params, &work_bytes);
  }
  r.status = uint32_t(s);
  if (s != Status::ok) return;
  r.tile_buffer_bytes = uint32_t(tile_bytes);
  r.workspace_bytes = uint32_t(work_bytes);
  const size_t tile_rounded = (tile_bytes + 7) & ~size_t(7);
  if (tile_rounded + work_bytes > r.arena_bytes) {
    r.status = BENCH_STATUS_NO_ROOM;
    return;
  }
  tile_buffer = __arena_start;
  workspace = __arena_start + tile_rounded;
  r.stage = BENCH_STAGE_PREPARED;
}

// The harness counts this function's instructions apart from the core's: it stands for the
// display transfer a firmware would start here. A leaf (tile_hash.h is inline).
extern "C" __attribute__((noinline)) void bench_sink(void* context, const Tile* tile) {
  tile_hash_tile(static_cast<tile_hash*>(context), tile->pixels, tile->stride, tile->rect.x0, tile->rect.y0,
                 tile->rect.x1, tile->rect.y1, bytes_per_pixel(tile->format));
}

extern "C" void bench_render() {
  bench_result& r = bench_result_out;
  if (r.stage != BENCH_STAGE_PREPARED) return;
  tile_hash_init(&digest);
  uint32_t sp;
#if defined(__riscv)
  __asm__ volatile("mv %0, sp" : "=r"(sp));
#else
  __asm__ volatile("mov %0, sp" : "=r"(sp));
#endif
  r.sp_before_render = sp;
  const Status s = is_compressed ? render(compressed, params, tile_buffer, r.tile_buffer_bytes, workspace,
                                         r.workspace_bytes, bench_sink, &digest)
                                  : render(blob, params, tile_buffer, r.tile_buffer_bytes, workspace, r.workspace_bytes,
                                           bench_sink, &digest);
  r.status = uint32_t(s);
  if (s != Status::ok) return;
  r.tiles = digest.tiles;
  r.hash_a = digest.a;
  r.hash_b = digest.b;
  r.stage = BENCH_STAGE_RENDERED;
}
