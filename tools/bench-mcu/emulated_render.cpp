// SPDX-License-Identifier: MIT
#include "emulated_render.h"

#include <stdexcept>

#include "tile_hash.h"
#include "tristream/render.h"

namespace tristream::bench_mcu {

namespace {

constexpr std::uint32_t stack_paint = 0xA5C3E1F0u;

void host_sink(void* context, const core::Tile* t) {
  tile_hash_tile(static_cast<tile_hash*>(context), t->pixels, t->stride, t->rect.x0, t->rect.y0, t->rect.x1,
                 t->rect.y1, core::bytes_per_pixel(t->format));
}

core::RenderParams render_params(const bench_params& p) {
  core::RenderParams r;
  r.output_width = p.output_width;
  r.output_height = p.output_height;
  r.tile_width = p.tile_width;
  r.tile_height = p.tile_height;
  r.format = core::PixelFormat(p.format);
  r.dither = p.dither != 0;
  for (int c = 0; c < 3; ++c) r.background[c] = p.background[c];
  return r;
}

}  // namespace

Digest host_digest(const std::vector<std::uint8_t>& blob, const bench_params& p) {
  core::Blob b;
  if (core::open_blob(blob.data(), blob.size(), &b) != core::Status::ok) throw std::runtime_error("host: open_blob");
  const core::RenderParams r = render_params(p);
  std::size_t tile_bytes = 0, work_bytes = 0;
  if (core::tile_buffer_size(b, r, &tile_bytes) != core::Status::ok ||
      core::workspace_size(b, r, &work_bytes) != core::Status::ok)
    throw std::runtime_error("host: buffer sizes");
  std::vector<std::uint8_t> tile(tile_bytes), work(work_bytes);
  tile_hash h;
  tile_hash_init(&h);
  const core::Status s = core::render(b, r, tile.data(), tile.size(), work.data(), work.size(), host_sink, &h);
  if (s != core::Status::ok) throw std::runtime_error(std::string("host: render: ") + core::status_text(s));
  return {h.a, h.b, h.tiles};
}

Outcome run_on(Emulator& emu, const ElfImage& elf, const std::vector<std::uint8_t>& blob, const bench_params& p) {
  const std::uint32_t top = elf.symbol("__stack_top").address, limit = elf.symbol("__stack_limit").address;
  const std::uint32_t params_at = elf.symbol("bench_params_in").address,
                      result_at = elf.symbol("bench_result_out").address;
  emu.reset_data();
  emu.write(rom_base, blob.data(), blob.size());
  emu.write(params_at, &p, sizeof p);
  const ElfSymbol& sink = elf.symbol("bench_sink");
  emu.exclude(sink.address, sink.address + sink.size);
  Outcome o;
  o.open_counts = emu.call(elf.symbol("bench_open").address, top);
  emu.read(result_at, &o.result, sizeof o.result);
  if (o.result.stage != BENCH_STAGE_OPENED)
    throw std::runtime_error("the emulated core: open failed: " +
                             std::string(core::status_text(core::Status(o.result.status))));
  emu.call(elf.symbol("bench_prepare").address, top);
  emu.read(result_at, &o.result, sizeof o.result);
  if (o.result.stage != BENCH_STAGE_PREPARED) {
    if (o.result.status == BENCH_STATUS_NO_ROOM) {
      o.skipped = "tile buffer " + std::to_string(o.result.tile_buffer_bytes) + " + workspace " +
                  std::to_string(o.result.workspace_bytes) + " bytes do not fit the " +
                  std::to_string(o.result.arena_bytes) + " bytes of RAM left";
      return o;
    }
    throw std::runtime_error("the emulated core: prepare failed: " +
                             std::string(core::status_text(core::Status(o.result.status))));
  }
  emu.fill(limit, stack_paint, (top - limit) / 4);
  o.counts = emu.call(elf.symbol("bench_render").address, top);
  emu.read(result_at, &o.result, sizeof o.result);
  if (o.result.stage != BENCH_STAGE_RENDERED)
    throw std::runtime_error("the emulated core: render failed: " +
                             std::string(core::status_text(core::Status(o.result.status))));
  std::vector<std::uint32_t> stack((top - limit) / 4);
  emu.read(limit, stack.data(), stack.size() * 4);
  std::size_t lowest = 0;
  while (lowest < stack.size() && stack[lowest] == stack_paint) ++lowest;
  if (lowest == 0) throw std::runtime_error("the emulated core: the stack overflowed its reserve");
  o.stack_bytes = o.result.sp_before_render - (limit + std::uint32_t(lowest) * 4);
  o.ran = true;
  return o;
}

}  // namespace tristream::bench_mcu
