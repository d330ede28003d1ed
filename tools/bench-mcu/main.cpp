// SPDX-License-Identifier: MIT
// bench_mcu: runs firmware_core on an emulated Cortex-M4 (m4_emulator.h) and reports
// instructions, modelled cycles, stack, RAM and flash per configuration, with the pixels checked
// against the host build of the core. docs/MCU_BENCH.md describes the model and the matrix.
//   bench_mcu run --elf-dir <dir> [matrix options]   one JSON line per configuration, then a summary
//   bench_mcu calibrate <calibrate.elf>              the hand-counted loops must count exactly
#include <CLI/CLI.hpp>
#include <cxxabi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "bench_meshes.h"
#include "bench_protocol.h"
#include "common/errors.h"
#include "common/tool_main.h"
#include "core_bridge/compress.h"
#include "core_bridge/core_stack.h"
#include "core_bridge/pack.h"
#include "io/atomic_file.h"
#include "m4_emulator.h"
#include "panel_table.h"
#include "tile_hash.h"
#include "tristream/render.h"

using namespace tristream;
using namespace tristream::bench_mcu;
using json = nlohmann::ordered_json;

namespace {

constexpr std::uint32_t stack_paint = 0xA5C3E1F0u;

struct Tiling {
  std::string name;
  int w, h;  // 0: the output's side
};

Tiling parse_tiling(const std::string& s) {
  if (s == "tiles32") return {s, 32, 32};
  if (s == "bands16") return {s, 0, 16};
  if (s == "frame") return {s, 0, 0};
  throw UsageError("unknown tiling '" + s + "' (expected tiles32, bands16 or frame)");
}

struct Size {
  int w = 0, h = 0;  // 0: native
};

Size parse_output(const std::string& s) {
  if (s == "native") return {};
  int w = 0, h = 0;
  char x = 0;
  std::istringstream in(s);
  if (!(in >> w >> x >> h) || x != 'x' || w < 2 || h < 2 || w > core::config::max_dimension ||
      h > core::config::max_dimension || !in.eof())
    throw UsageError("output '" + s + "': expected native or WxH");
  return {w, h};
}

struct CoreSize {
  bool known = false;
  std::uint32_t text = 0, data = 0, bss = 0;
};

CoreSize read_size(const std::string& path) {
  std::ifstream in(path);
  CoreSize s;
  if (in >> s.text >> s.data >> s.bss) s.known = true;
  return s;
}

// One benchmark program (a core at one optimisation level with one method) on its emulator.
struct Program {
  ElfImage elf;
  std::unique_ptr<M4Emulator> emu;
  std::unique_ptr<M4Emulator> checker;  // per-instruction counting, with --check-counts
  CoreSize core, full, compressed;  // compressed: the compressed-blob decoder (not in core or full)
};

struct Digest {
  std::uint32_t a = 0, b = 0, tiles = 0;
  bool operator==(const Digest&) const = default;
};

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

// The same render with the host (x86-64) build of the core.
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

struct Outcome {
  bool ran = false;
  std::string skipped;
  RunCounts open_counts;  // bench_open: open_blob or open_compressed_blob, as ts_open
  RunCounts counts;
  bench_result result{};
  std::uint32_t stack_bytes = 0;
};

// Opens, prepares and renders one configuration on `emu`; the open and the render are counted, the
// stack is painted before the render.
Outcome run_on(M4Emulator& emu, const ElfImage& elf, const std::vector<std::uint8_t>& blob, const bench_params& p) {
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
    throw std::runtime_error("M4: open failed: " + std::string(core::status_text(core::Status(o.result.status))));
  emu.call(elf.symbol("bench_prepare").address, top);
  emu.read(result_at, &o.result, sizeof o.result);
  if (o.result.stage != BENCH_STAGE_PREPARED) {
    if (o.result.status == BENCH_STATUS_NO_ROOM) {
      o.skipped = "tile buffer " + std::to_string(o.result.tile_buffer_bytes) + " + workspace " +
                  std::to_string(o.result.workspace_bytes) + " bytes do not fit the " +
                  std::to_string(o.result.arena_bytes) + " bytes of RAM left";
      return o;
    }
    throw std::runtime_error("M4: prepare failed: " + std::string(core::status_text(core::Status(o.result.status))));
  }
  emu.fill(limit, stack_paint, (top - limit) / 4);
  o.counts = emu.call(elf.symbol("bench_render").address, top);
  emu.read(result_at, &o.result, sizeof o.result);
  if (o.result.stage != BENCH_STAGE_RENDERED)
    throw std::runtime_error("M4: render failed: " + std::string(core::status_text(core::Status(o.result.status))));
  std::vector<std::uint32_t> stack((top - limit) / 4);
  emu.read(limit, stack.data(), stack.size() * 4);
  std::size_t lowest = 0;
  while (lowest < stack.size() && stack[lowest] == stack_paint) ++lowest;
  if (lowest == 0) throw std::runtime_error("M4: the stack overflowed its reserve");
  o.stack_bytes = o.result.sp_before_render - (limit + std::uint32_t(lowest) * 4);
  o.ran = true;
  return o;
}

json counts_json(const Counts& c) {
  json j;
  j["instructions"] = c.instructions;
  j["cycles"] = c.cycles;
  return j;
}

std::string demangled(const std::string& name) {
  int status = 0;
  char* d = abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status);
  if (!d) return name;
  std::string s(d);
  std::free(d);
  return s;
}

double per(std::uint64_t v, double n) { return n > 0 ? double(v) / n : 0; }
double round2(double v) { return std::round(v * 100) / 100; }

struct Row {
  std::string mesh, output, tiling, method, opt;
  bool dither;
  bool compressed;
  double cycles_per_pixel;
  std::uint32_t stack;
  std::size_t blob_bytes;
  std::uint64_t open_cycles;
};

std::string fmt(double v, const char* f = "%.0f") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The human summary: cycles per pixel side by side, and the ratios between configurations.
void print_summary(const std::vector<Row>& rows, const std::vector<std::string>& meshes,
                   const std::vector<std::string>& outputs, const std::vector<Tiling>& tilings) {
  auto find = [&](const std::string& mesh, const std::string& out, const std::string& tiling,
                  const std::string& method, const std::string& opt, bool dither) -> const Row* {
    for (const Row& r : rows)
      if (r.mesh == mesh && r.output == out && r.tiling == tiling && r.method == method && r.opt == opt &&
          r.dither == dither && !r.compressed)
        return &r;
    return nullptr;
  };
  auto cell = [&](const Row* r) { return r ? fmt(r->cycles_per_pixel) : std::string("-"); };
  auto ratio = [&](const Row* a, const Row* b) {
    return a && b && b->cycles_per_pixel > 0 ? fmt(a->cycles_per_pixel / b->cycles_per_pixel, "%.2f")
                                              : std::string("-");
  };
  std::printf("\nModelled Cortex-M4 cycles per output pixel, RGB565 BE (zero wait states)\n");
  std::printf("%-9s %-8s %-8s | %-22s | %-22s | %-11s | %-11s | %-11s | %s\n", "mesh", "output", "tiling",
              "bilinear O2 / Os", "zienkiewicz O2 / Os", "zienk/bil", "Os/O2 b z", "dither b z", "stack O2 Os");
  for (const std::string& mesh : meshes)
    for (const std::string& out : outputs)
      for (const Tiling& t : tilings) {
        const Row* b2 = find(mesh, out, t.name, "bilinear", "O2", false);
        const Row* bs = find(mesh, out, t.name, "bilinear", "Os", false);
        const Row* z2 = find(mesh, out, t.name, "zienkiewicz", "O2", false);
        const Row* zs = find(mesh, out, t.name, "zienkiewicz", "Os", false);
        const Row* b2d = find(mesh, out, t.name, "bilinear", "O2", true);
        const Row* z2d = find(mesh, out, t.name, "zienkiewicz", "O2", true);
        if (!b2 && !z2 && !bs && !zs) continue;
        std::uint32_t s2 = 0, ss = 0;  // the largest stack of the row, per optimisation level
        for (const Row& r : rows)
          if (r.mesh == mesh && r.output == out && r.tiling == t.name && !r.compressed) {
            std::uint32_t& s = r.opt == "O2" ? s2 : ss;
            s = std::max(s, r.stack);
          }
        auto bytes = [](std::uint32_t b) { return b ? std::to_string(b) : std::string("-"); };
        std::printf("%-9s %-8s %-8s | %10s %11s | %10s %11s | %11s | %5s %5s | %5s %5s | %5s %5s\n", mesh.c_str(),
                    out.c_str(), t.name.c_str(), cell(b2).c_str(), cell(bs).c_str(), cell(z2).c_str(),
                    cell(zs).c_str(), ratio(z2, b2).c_str(), ratio(bs, b2).c_str(), ratio(zs, z2).c_str(),
                    ratio(b2d, b2).c_str(), ratio(z2d, z2).c_str(), bytes(s2).c_str(), bytes(ss).c_str());
      }
  // What opening each blob costs (open_blob checks every byte of a v1 blob and its CRC-32;
  // open_compressed_blob the header and the layer table), once per mesh, method, level and kind.
  std::printf("\nModelled Cortex-M4 cycles of ts_open (open_blob, open_compressed_blob)\n");
  std::printf("%-9s %-12s %-3s %-10s | %9s %11s %15s\n", "mesh", "method", "opt", "blob", "bytes", "cycles",
              "cycles per byte");
  std::vector<const Row*> opened;
  for (const Row& r : rows) {
    bool seen = false;
    for (const Row* o : opened)
      seen |= o->mesh == r.mesh && o->method == r.method && o->opt == r.opt && o->compressed == r.compressed;
    if (seen) continue;
    opened.push_back(&r);
    std::printf("%-9s %-12s %-3s %-10s | %9zu %11llu %15s\n", r.mesh.c_str(), r.method.c_str(), r.opt.c_str(),
                r.compressed ? "compressed" : "v1", r.blob_bytes, static_cast<unsigned long long>(r.open_cycles),
                fmt(per(r.open_cycles, double(r.blob_bytes)), "%.2f").c_str());
  }
  // The compressed blobs against the v1 blobs of the same meshes (rendered from the streams).
  bool any = false;
  for (const Row& r : rows) any |= r.compressed;
  if (!any) return;
  std::printf("\nCompressed blob rendered from its streams against its v1 blob, cycles per pixel (ratio)\n");
  std::printf("%-9s %-8s %-8s %-12s %-3s %-6s | %8s %10s %6s | %s\n", "mesh", "output", "tiling", "method", "opt",
              "dither", "v1", "compressed", "ratio", "stack v1 compressed");
  for (const Row& c : rows) {
    if (!c.compressed) continue;
    const Row* v = find(c.mesh, c.output, c.tiling, c.method, c.opt, c.dither);
    std::printf("%-9s %-8s %-8s %-12s %-3s %-6s | %8s %10s %6s | %u %u\n", c.mesh.c_str(), c.output.c_str(),
                c.tiling.c_str(), c.method.c_str(), c.opt.c_str(), c.dither ? "on" : "off", cell(v).c_str(),
                cell(&c).c_str(), ratio(&c, v).c_str(), v ? unsigned(v->stack) : 0u, unsigned(c.stack));
  }
}

int run(const std::string& elf_dir, const std::vector<std::string>& meshes, const std::vector<std::string>& methods,
        const std::vector<std::string>& opts, const std::vector<std::string>& dithers,
        const std::vector<std::string>& outputs, const std::vector<std::string>& tiling_names,
        const std::vector<std::string>& blob_kinds, bool check_counts,
        bool check_stack, int profile, const std::string& address_profile, bool stack_chain) {
  std::string address_lines;  // --profile-addresses: "configuration address cycles" per block
  std::vector<Tiling> tilings;
  for (const std::string& t : tiling_names) tilings.push_back(parse_tiling(t));
  std::vector<Size> sizes;
  for (const std::string& o : outputs) sizes.push_back(parse_output(o));
  for (const std::string& m : methods) parse_core_method(m);
  for (const std::string& o : opts)
    if (o != "O2" && o != "Os") throw UsageError("unknown optimisation '" + o + "' (expected O2 or Os)");
  for (const std::string& d : dithers)
    if (d != "off" && d != "on") throw UsageError("dither '" + d + "': expected off or on");
  for (const std::string& k : blob_kinds)
    if (k != "v1" && k != "compressed") throw UsageError("blob '" + k + "': expected v1 or compressed");
  std::map<std::string, Program> programs;
  auto program = [&](const std::string& opt, const std::string& method) -> Program& {
    const std::string key = opt + "_" + method;
    auto it = programs.find(key);
    if (it != programs.end()) return it->second;
    Program& p = programs[key];
    p.elf = read_elf(elf_dir + "/bench_" + key + ".elf");
    p.emu = std::make_unique<M4Emulator>(p.elf);
    p.emu->set_address_profile(!address_profile.empty());
    p.emu->set_stack_chain(stack_chain);
    if (check_counts) p.checker = std::make_unique<M4Emulator>(p.elf, true);
    p.core = read_size(elf_dir + "/ts_core_" + key + ".size");
    p.full = read_size(elf_dir + "/ts_core_" + opt + "_full.size");
    p.compressed = read_size(elf_dir + "/ts_core_" + key + ".compressed.size");
    return p;
  };
  std::vector<Row> rows;
  std::vector<PanelRow> panel_rows;  // -O2 without dithering: what a display gets
  bool all_equal = true, stacks_within = true;
  for (const std::string& mesh_name : meshes) {
    const Triangulation tri = make_mesh(mesh_name);
    for (const std::string& method : methods) {
      const std::vector<std::uint8_t> v1_blob = pack_blob(tri, parse_core_method(method), mesh_name);
      if (v1_blob.size() > rom_size) throw DataError(mesh_name + ": blob larger than the emulated flash for blobs");
      const std::vector<std::uint8_t>& blob = v1_blob;
      core::Blob opened;
      if (core::open_blob(blob.data(), blob.size(), &opened) != core::Status::ok)
        throw DataError(mesh_name + ": the host core rejects the packed blob");
      std::uint64_t triangles = 0;
      for (int l = 0; l < opened.layer_count; ++l) triangles += opened.layers[l].triangle_count;
      // The same mesh compressed by the host compressor: its pixels are checked against the v1
      // blob's host render (they must be bit-identical).
      const std::vector<std::uint8_t> compressed_blob = compress_blob(v1_blob, mesh_name);
      for (const std::string& kind : blob_kinds)
      for (std::size_t oi = 0; oi < sizes.size(); ++oi)
        for (const Tiling& t : tilings)
          for (const std::string& opt : opts)
            for (const std::string& d : dithers) {
              const bool is_compressed = kind == "compressed";
              const std::vector<std::uint8_t>& run_blob = is_compressed ? compressed_blob : v1_blob;
              Program& prog = program(opt, method);
              bench_params p{};
              p.blob_address = rom_base;
              p.blob_size = std::uint32_t(run_blob.size());
              p.output_width = std::uint16_t(sizes[oi].w);
              p.output_height = std::uint16_t(sizes[oi].h);
              p.tile_width = std::uint16_t(t.w);
              p.tile_height = std::uint16_t(t.h);
              p.format = std::uint8_t(core::PixelFormat::rgb565_be);
              p.dither = d == "on";
              const int ow = sizes[oi].w ? sizes[oi].w : opened.width, oh = sizes[oi].h ? sizes[oi].h : opened.height;
              const std::string out_name = std::to_string(ow) + "x" + std::to_string(oh);
              json j;
              j["mesh"] = mesh_name;
              j["blob"] = kind;
              j["blob_bytes"] = run_blob.size();
              j["triangles"] = triangles;
              j["domain"] = std::to_string(opened.width) + "x" + std::to_string(opened.height);
              j["output"] = out_name;
              j["tiling"] = t.name;
              j["tile"] = {t.w ? t.w : ow, t.h ? t.h : oh};
              j["method"] = method;
              j["opt"] = opt;
              j["format"] = "rgb565be";
              j["dither"] = p.dither != 0;
              const Outcome o = run_on(*prog.emu, prog.elf, run_blob, p);
              if (!o.ran) {
                j["skipped"] = o.skipped;
                std::printf("%s\n", j.dump().c_str());
                std::fflush(stdout);
                continue;
              }
              const Digest m4{o.result.hash_a, o.result.hash_b, o.result.tiles};
              const Digest host = host_digest(blob, p);
              const double pixels = double(ow) * oh;
              const Counts& oc = o.open_counts.counted;
              j["open_instructions"] = oc.instructions;
              j["open_cycles"] = oc.cycles;
              j["open_cycles_per_byte"] = round2(per(oc.cycles, double(run_blob.size())));
              const Counts& c = o.counts.counted;
              j["instructions"] = c.instructions;
              j["cycles"] = c.cycles;
              j["instructions_per_pixel"] = round2(per(c.instructions, pixels));
              j["cycles_per_pixel"] = round2(per(c.cycles, pixels));
              j["instructions_per_triangle"] = round2(per(c.instructions, double(triangles)));
              j["cycles_per_triangle"] = round2(per(c.cycles, double(triangles)));
              json classes;
              for (int k = 0; k < class_count; ++k) classes[class_name(k)] = c.by_class[k];
              j["instruction_classes"] = classes;
              j["taken_branches"] = c.taken_branches;
              j["division_cycles_beyond_2"] = c.divide_cycles;
              j["sink"] = counts_json(o.counts.excluded);
              j["tiles"] = o.result.tiles;
              j["stack_bytes"] = o.stack_bytes;
              j["tile_buffer_bytes"] = o.result.tile_buffer_bytes;
              j["workspace_bytes"] = o.result.workspace_bytes;
              const std::uint32_t static_ram = prog.core.known ? prog.core.data + prog.core.bss : 0;
              j["static_ram_bytes"] = prog.core.known ? json(static_ram) : json(nullptr);
              j["ram_bytes"] = o.result.tile_buffer_bytes + o.result.workspace_bytes + o.stack_bytes + static_ram;
              j["flash_core_bytes"] = prog.core.known ? json(prog.core.text) : json(nullptr);
              j["flash_core_full_bytes"] = prog.full.known ? json(prog.full.text) : json(nullptr);
              j["flash_compressed_decoder_bytes"] = prog.compressed.known ? json(prog.compressed.text) : json(nullptr);
              j["pixels_equal_host"] = m4 == host;
              all_equal &= m4 == host;
              if (check_stack) {
                const bool within = o.stack_bytes <= (is_compressed ? core_compressed_stack_bytes(opened.method)
                                                                    : core_stack_bytes(opened.method));
                j["stack_within_core_stack_bytes"] = within;
                stacks_within &= within;
              }
              if (check_counts) {
                const Outcome slow = run_on(*prog.checker, prog.elf, run_blob, p);
                const Counts& s = slow.counts.counted;
                const Counts& so = slow.open_counts.counted;
                const bool same = s.instructions == c.instructions && s.cycles == c.cycles &&
                                  so.instructions == oc.instructions && so.cycles == oc.cycles &&
                                  slow.counts.excluded.instructions == o.counts.excluded.instructions &&
                                  slow.counts.excluded.cycles == o.counts.excluded.cycles;
                j["per_instruction_counts_equal"] = same;
                all_equal &= same;
              }
              if (profile > 0) {
                std::vector<std::pair<std::uint64_t, std::size_t>> f;
                for (std::size_t i = 0; i < o.counts.function_cycles.size(); ++i)
                  if (o.counts.function_cycles[i]) f.push_back({o.counts.function_cycles[i], i});
                std::sort(f.rbegin(), f.rend());
                json top = json::array();
                for (std::size_t i = 0; i < f.size() && int(i) < profile; ++i)
                  top.push_back({{"function", demangled(prog.emu->functions()[f[i].second].name)},
                                 {"cycles_share", round2(100.0 * double(f[i].first) / double(c.cycles))}});
                j["profile_percent"] = top;
              }
              if (stack_chain) {
                // The calls live at the high-water mark, deepest first: the function running, then
                // those whose return addresses were on the stack (M4Emulator: a stale word in a
                // frame's unused slot can look like one too), each with the depth below render's
                // SP where its frame ended (the running one) or its return address was.
                const std::uint32_t top = prog.elf.symbol("__stack_top").address;
                const std::uint32_t before = top - o.result.sp_before_render;
                json chain = json::array();
                for (const RunCounts::Frame& f : o.counts.stack_chain)
                  if (f.depth > before)
                    chain.push_back({{"function", demangled(prog.emu->functions()[f.function].name)},
                                     {"stack_bytes", f.depth - before}});
                j["stack_chain"] = chain;
              }
              if (!address_profile.empty()) {
                const std::string name = mesh_name + (is_compressed ? " compressed " : " ") + out_name + " " + t.name +
                                         " " + method + " " + opt + (p.dither ? " dither" : " plain");
                const std::vector<std::uint64_t>& b = o.counts.block_runs;
                char line[96];
                for (std::size_t i = 0; i < b.size(); ++i) {
                  if (!b[i]) continue;
                  const std::uint32_t address = flash_base + 2 * std::uint32_t(i);
                  std::uint32_t size = 0, cost = 0;
                  prog.emu->block_cost(address, &size, &cost);
                  std::snprintf(line, sizeof line, "\t0x%08x\t%u\t%llu\t%llu\n", unsigned(address), unsigned(size),
                                static_cast<unsigned long long>(b[i]), static_cast<unsigned long long>(b[i] * cost));
                  address_lines += name + line;
                }
              }
              std::printf("%s\n", j.dump().c_str());
              std::fflush(stdout);
              rows.push_back({mesh_name, out_name, t.name, method, opt, p.dither != 0, is_compressed,
                              per(c.cycles, pixels), o.stack_bytes, run_blob.size(), oc.cycles});
              if (opt == "O2" && !p.dither)
                panel_rows.push_back({mesh_name, out_name, t.name, method, kind, ow, oh, c.cycles});
            }
    }
  }
  std::vector<std::string> out_names;
  for (const Row& r : rows)
    if (std::find(out_names.begin(), out_names.end(), r.output) == out_names.end()) out_names.push_back(r.output);
  print_summary(rows, meshes, out_names, tilings);
  print_panel_table(panel_rows);
  for (const std::string& method : methods) {
    std::uint32_t most = 0, most_compressed = 0;
    for (const Row& r : rows)
      if (r.method == method) (r.compressed ? most_compressed : most) = std::max(r.compressed ? most_compressed : most, r.stack);
    std::printf("largest stack high-water mark, %s: %u bytes (core_stack_bytes: %zu)\n", method.c_str(), most,
                core_stack_bytes(parse_core_method(method)));
    if (most_compressed)
      std::printf("largest stack high-water mark, %s, compressed: %u bytes (core_compressed_stack_bytes: %zu)\n",
                  method.c_str(), most_compressed, core_compressed_stack_bytes(parse_core_method(method)));
  }
  if (!all_equal) std::fprintf(stderr, "bench_mcu: the emulated M4 differs from the host (pixels or counts)\n");
  if (!stacks_within)
    std::fprintf(stderr, "bench_mcu: a stack high-water mark exceeds core_stack_bytes (core_bridge/core_stack.h)\n");
  if (!address_profile.empty()) write_file_atomically(address_profile, address_lines);
  return all_equal && stacks_within ? 0 : 1;
}

// The calibration loops of m4/calibrate.S: a table of {name, function, r0, instructions, cycles},
// ended by a zero function; each is run with block counting and with per-instruction counting.
int calibrate(const std::string& path) {
  const ElfImage elf = read_elf(path);
  M4Emulator fast(elf), slow(elf, true);
  const std::uint32_t table = elf.symbol("calibration_cases").address;
  const std::uint32_t top = elf.symbol("__stack_top").address;
  int failures = 0, cases = 0;
  for (std::uint32_t at = table;; at += 20) {
    const std::vector<std::uint8_t> raw = elf.read(at, 20);
    std::uint32_t e[5];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    std::string name;
    for (std::uint32_t a = e[0];; ++a) {
      const char ch = char(elf.read(a, 1)[0]);
      if (!ch) break;
      name += ch;
    }
    const RunCounts f = fast.call(e[1] & ~1u, top, {e[2]});
    const RunCounts s = slow.call(e[1] & ~1u, top, {e[2]});
    const bool ok = f.counted.instructions == e[3] && f.counted.cycles == e[4] &&
                    s.counted.instructions == e[3] && s.counted.cycles == e[4];
    std::printf("%-26s instructions %8llu (expected %8u, per instruction %8llu)  cycles %8llu (expected %8u, per "
                "instruction %8llu)  %s\n",
                name.c_str(), (unsigned long long)f.counted.instructions, e[3],
                (unsigned long long)s.counted.instructions, (unsigned long long)f.counted.cycles, e[4],
                (unsigned long long)s.counted.cycles, ok ? "ok" : "MISMATCH");
    failures += !ok;
    ++cases;
  }
  if (cases == 0) throw DataError(path + ": no calibration cases");
  std::printf("%d of %d calibration cases exact\n", cases - failures, cases);
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Run firmware_core on an emulated Cortex-M4: instructions, modelled cycles, stack, RAM, flash,\n"
               "and the pixels against the host build (docs/MCU_BENCH.md)."};
  app.require_subcommand(1);
  CLI::App* run_cmd = app.add_subcommand("run", "Benchmark a matrix of configurations");
  std::string elf_dir;
  std::vector<std::string> meshes = mesh_names(), methods = {"bilinear", "zienkiewicz"}, opts = {"O2", "Os"},
                           dithers = {"off", "on"}, outputs = {"native", "320x240", "240x240"},
                           tilings = {"tiles32", "bands16", "frame"}, blob_kinds = {"v1", "compressed"};
  bool check_counts = false, check_stack = false;
  int profile = 0;
  std::string address_profile;
  bool stack_chain = false;
  run_cmd->add_option("--elf-dir", elf_dir, "Build directory of tools/bench-mcu/m4 (build-m4.sh)")->required();
  run_cmd->add_option("--meshes", meshes, "kodim23, scene4k, grid40k")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--methods", methods, "bilinear, zienkiewicz")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--opts", opts, "O2, Os")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--dither", dithers, "off, on")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--outputs", outputs, "native or WxH")->delimiter(',')->capture_default_str();
  run_cmd->add_option("--tilings", tilings, "tiles32, bands16, frame (the frame where it fits the RAM)")
      ->delimiter(',')
      ->capture_default_str();
  run_cmd->add_option("--blobs", blob_kinds,
                      "v1, compressed (the same mesh compressed by the host, rendered from its streams)")
      ->delimiter(',')
      ->capture_default_str();
  run_cmd->add_flag("--check-counts", check_counts,
                    "Run each configuration again counting per instruction; the counts must be equal");
  run_cmd->add_flag("--check-stack", check_stack, "Fail when a stack high-water mark exceeds core_stack_bytes");
  run_cmd->add_option("--profile", profile, "Add the N functions with the most cycles to each line");
  run_cmd->add_option("--profile-addresses", address_profile,
                      "Write every block run (configuration, start address, bytes, runs, static cycles; tab-separated) to "
                      "this file, for addr2line on a build with -g");
  run_cmd->add_flag("--stack-chain", stack_chain,
                    "Add the calls live at the stack's high-water mark to each line (reads SP at every block: slower)");
  CLI::App* cal_cmd = app.add_subcommand("calibrate", "Count the calibration loops and compare with their table");
  std::string cal_elf;
  cal_cmd->add_option("elf", cal_elf, "calibrate.elf")->required();
  return run_tool("bench_mcu", app, argc, argv, [&]() -> int {
    if (*cal_cmd) return calibrate(cal_elf);
    return run(elf_dir, meshes, methods, opts, dithers, outputs, tilings, blob_kinds, check_counts, check_stack, profile,
               address_profile, stack_chain);
  });
}
