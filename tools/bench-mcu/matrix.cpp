// SPDX-License-Identifier: MIT
#include "matrix.h"

#include <cxxabi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench_meshes.h"
#include "bench_protocol.h"
#include "common/errors.h"
#include "core_bridge/compress.h"
#include "core_bridge/core_stack.h"
#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "elf_image.h"
#include "emulated_render.h"
#include "emulator.h"
#include "io/atomic_file.h"
#include "m4_emulator.h"
#include "panel_table.h"
#include "summary.h"
#include "tristream/render.h"

namespace tristream::bench_mcu {

namespace {

using json = nlohmann::ordered_json;

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
  std::unique_ptr<Emulator> emu;
  std::unique_ptr<Emulator> checker;  // per-instruction counting, with --check-counts
  CoreSize core, full, compressed;  // compressed: the compressed-blob decoder (not in core or full)
};

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

double round2(double v) { return std::round(v * 100) / 100; }

// The matrix's tilings and output sizes; every name is checked before anything runs.
struct Matrix {
  std::vector<Tiling> tilings;
  std::vector<Size> sizes;
};

Matrix parse_matrix(const RunOptions& o) {
  Matrix m;
  for (const std::string& t : o.tilings) m.tilings.push_back(parse_tiling(t));
  for (const std::string& s : o.outputs) m.sizes.push_back(parse_output(s));
  for (const std::string& method : o.methods) parse_core_method(method);
  for (const std::string& opt : o.opts)
    if (opt != "O2" && opt != "Os") throw UsageError("unknown optimisation '" + opt + "' (expected O2 or Os)");
  for (const std::string& d : o.dithers)
    if (d != "off" && d != "on") throw UsageError("dither '" + d + "': expected off or on");
  for (const std::string& k : o.blob_kinds)
    if (k != "v1" && k != "compressed") throw UsageError("blob '" + k + "': expected v1 or compressed");
  return m;
}

// The cores of --cpus, each once, each with its directory; without --cpus every core whose
// directory is given.
std::vector<Core> parse_cores(const RunOptions& o) {
  std::vector<Core> cores;
  for (const std::string& name : o.cpus) {
    const Core c = parse_core(name);
    if (std::find(cores.begin(), cores.end(), c) != cores.end()) continue;
    if (o.elf_dirs[std::size_t(c)].empty())
      throw UsageError("--cpus " + name + ": --" + name + "-elf-dir is needed (tools/bench-mcu/build-" + name + ".sh)");
    cores.push_back(c);
  }
  if (o.cpus.empty())
    for (Core c : all_cores)
      if (!o.elf_dirs[std::size_t(c)].empty()) cores.push_back(c);
  if (cores.empty()) throw UsageError("no core: give --m4-elf-dir (--elf-dir), --m0plus-elf-dir or --rv32imc-elf-dir");
  if (!o.address_profile.empty() && cores.size() > 1)
    throw UsageError("--profile-addresses profiles one core's programs: choose it with --cpus");
  return cores;
}

// The benchmark programs by core, optimisation level and method, each read when first asked for.
class Programs {
 public:
  explicit Programs(const RunOptions& o) : o_(o) {}
  // `grey`: the program whose core is built for grey blobs (bench_<opt>_<method>_grey.elf).
  Program& get(Core core, const std::string& opt, const std::string& method, bool grey) {
    const std::string key = opt + "_" + method + (grey ? "_grey" : "");
    auto it = programs_.find(core_name(core) + ("/" + key));
    if (it != programs_.end()) return it->second;
    const std::string& dir = o_.elf_dirs[std::size_t(core)];
    Program& p = programs_[core_name(core) + ("/" + key)];
    p.elf = read_elf(dir + "/bench_" + key + ".elf");
    p.emu = make_emulator(core, p.elf, false);
    p.emu->set_address_profile(!o_.address_profile.empty());
    p.emu->set_stack_chain(o_.stack_chain);
    if (o_.check_counts) p.checker = make_emulator(core, p.elf, true);
    p.core = read_size(dir + "/ts_core_" + key + ".size");
    p.full = read_size(dir + "/ts_core_" + opt + "_full.size");
    p.compressed = read_size(dir + "/ts_core_" + key + ".compressed.size");
    return p;
  }

 private:
  const RunOptions& o_;
  std::map<std::string, Program> programs_;
};

// One mesh packed for one method: the blobs its configurations render.
struct MeshBlobs {
  std::string mesh, method;
  std::vector<std::uint8_t> v1;
  // The same mesh compressed by the host compressor: its pixels are checked against the v1
  // blob's host render (they must be bit-identical).
  std::vector<std::uint8_t> compressed;
  core::Blob opened;  // v1, opened by the host core
  std::uint64_t triangles = 0;
};

void pack_mesh(const Triangulation& tri, const std::string& mesh, const std::string& method, MeshBlobs& m) {
  m.mesh = mesh;
  m.method = method;
  m.v1 = pack_blob(tri, parse_core_method(method), mesh);
  if (m.v1.size() > rom_size) throw DataError(mesh + ": blob larger than the emulated flash for blobs");
  if (core::open_blob(m.v1.data(), m.v1.size(), &m.opened) != core::Status::ok)
    throw DataError(mesh + ": the host core rejects the packed blob");
  for (int l = 0; l < m.opened.layer_count; ++l) m.triangles += m.opened.layers[l].triangle_count;
  m.compressed = compress_blob(m.v1, mesh);
}

// One configuration of the matrix: a mesh's blob of one kind, rendered at one output size in one
// tiling by one program, dithered or not.
struct Configuration {
  Core core;
  const MeshBlobs& blobs;
  const std::string& kind;  // v1 or compressed
  Size size;
  const Tiling& tiling;
  const std::string& opt;
  bool dither;
  bool compressed() const { return kind == "compressed"; }
  const std::vector<std::uint8_t>& blob() const { return compressed() ? blobs.compressed : blobs.v1; }
  int width() const { return size.w ? size.w : blobs.opened.width; }
  int height() const { return size.h ? size.h : blobs.opened.height; }
  std::string output_name() const { return std::to_string(width()) + "x" + std::to_string(height()); }
};

bench_params params_of(const Configuration& c) {
  bench_params p{};
  p.blob_address = rom_base;
  p.blob_size = std::uint32_t(c.blob().size());
  p.output_width = std::uint16_t(c.size.w);
  p.output_height = std::uint16_t(c.size.h);
  p.tile_width = std::uint16_t(c.tiling.w);
  p.tile_height = std::uint16_t(c.tiling.h);
  p.format = std::uint8_t(core::PixelFormat::rgb565_be);
  p.dither = c.dither;
  return p;
}

// The line's first keys: what the configuration is.
json configuration_json(const Configuration& c) {
  json j;
  j["cpu"] = core_name(c.core);
  j["mesh"] = c.blobs.mesh;
  j["blob"] = c.kind;
  j["blob_bytes"] = c.blob().size();
  j["triangles"] = c.blobs.triangles;
  j["domain"] = std::to_string(c.blobs.opened.width) + "x" + std::to_string(c.blobs.opened.height);
  j["output"] = c.output_name();
  j["tiling"] = c.tiling.name;
  j["tile"] = {c.tiling.w ? c.tiling.w : c.width(), c.tiling.h ? c.tiling.h : c.height()};
  j["method"] = c.blobs.method;
  j["opt"] = c.opt;
  j["format"] = std::string(pixel_format_name(core::PixelFormat::rgb565_be));
  j["dither"] = c.dither;
  return j;
}

// The counts of the open and the render, per byte, pixel and triangle.
void add_counts(json& j, const Configuration& c, const Outcome& o) {
  const double pixels = double(c.width()) * c.height(), triangles = double(c.blobs.triangles);
  const Counts& oc = o.open_counts.counted;
  j["open_instructions"] = oc.instructions;
  j["open_cycles"] = oc.cycles;
  j["open_cycles_per_byte"] = round2(per(oc.cycles, double(c.blob().size())));
  const Counts& rc = o.counts.counted;
  j["instructions"] = rc.instructions;
  j["cycles"] = rc.cycles;
  j["instructions_per_pixel"] = round2(per(rc.instructions, pixels));
  j["cycles_per_pixel"] = round2(per(rc.cycles, pixels));
  j["instructions_per_triangle"] = round2(per(rc.instructions, triangles));
  j["cycles_per_triangle"] = round2(per(rc.cycles, triangles));
  json classes;
  for (int k = 0; k < class_count; ++k) classes[class_name(k)] = rc.by_class[k];
  j["instruction_classes"] = classes;
  j["taken_branches"] = rc.taken_branches;
  j["division_cycles_beyond_2"] = rc.divide_cycles;
  j["sink"] = counts_json(o.counts.excluded);
  j["tiles"] = o.result.tiles;
}

// Stack, buffers, static RAM and flash (the core's sizes where build-m4.sh left them).
void add_memory(json& j, const Program& prog, const Outcome& o) {
  j["stack_bytes"] = o.stack_bytes;
  j["tile_buffer_bytes"] = o.result.tile_buffer_bytes;
  j["workspace_bytes"] = o.result.workspace_bytes;
  const std::uint32_t static_ram = prog.core.known ? prog.core.data + prog.core.bss : 0;
  j["static_ram_bytes"] = prog.core.known ? json(static_ram) : json(nullptr);
  j["ram_bytes"] = o.result.tile_buffer_bytes + o.result.workspace_bytes + o.stack_bytes + static_ram;
  j["flash_core_bytes"] = prog.core.known ? json(prog.core.text) : json(nullptr);
  j["flash_core_full_bytes"] = prog.full.known ? json(prog.full.text) : json(nullptr);
  j["flash_compressed_decoder_bytes"] = prog.compressed.known ? json(prog.compressed.text) : json(nullptr);
}

// The same configuration counted per instruction must give the same counts.
bool counts_agree(Program& prog, const Configuration& c, const bench_params& p, const Outcome& o) {
  const Outcome slow = run_on(*prog.checker, prog.elf, c.blob(), p);
  const Counts& s = slow.counts.counted;
  const Counts& so = slow.open_counts.counted;
  const Counts& rc = o.counts.counted;
  const Counts& oc = o.open_counts.counted;
  return s.instructions == rc.instructions && s.cycles == rc.cycles && so.instructions == oc.instructions &&
         so.cycles == oc.cycles && slow.counts.excluded.instructions == o.counts.excluded.instructions &&
         slow.counts.excluded.cycles == o.counts.excluded.cycles;
}

// The `profile` functions with the most cycles, with their share of the render's.
json profile_json(const Program& prog, const Outcome& o, int profile) {
  std::vector<std::pair<std::uint64_t, std::size_t>> f;
  for (std::size_t i = 0; i < o.counts.function_cycles.size(); ++i)
    if (o.counts.function_cycles[i]) f.push_back({o.counts.function_cycles[i], i});
  std::sort(f.rbegin(), f.rend());
  json top = json::array();
  for (std::size_t i = 0; i < f.size() && int(i) < profile; ++i)
    top.push_back({{"function", demangled(prog.emu->functions()[f[i].second].name)},
                   {"cycles_share", round2(100.0 * double(f[i].first) / double(o.counts.counted.cycles))},
                   {"entries", o.counts.function_entries[f[i].second]}});
  return top;
}

// The calls live at the high-water mark, deepest first: the function running, then those whose
// return addresses were on the stack (M4Emulator: a stale word in a frame's unused slot can look
// like one too), each with the depth below render's SP where its frame ended (the running one) or
// its return address was.
json stack_chain_json(const Program& prog, const Outcome& o) {
  const std::uint32_t top = prog.elf.symbol("__stack_top").address;
  const std::uint32_t before = top - o.result.sp_before_render;
  json chain = json::array();
  for (const RunCounts::Frame& f : o.counts.stack_chain)
    if (f.depth > before)
      chain.push_back({{"function", demangled(prog.emu->functions()[f.function].name)},
                       {"stack_bytes", f.depth - before}});
  return chain;
}

// --profile-addresses: one line per block that ran, "<configuration>\t0xADDRESS\tbytes\truns\tcycles".
std::string block_lines(const Program& prog, const Configuration& c, const Outcome& o) {
  const std::string name = c.blobs.mesh + (c.compressed() ? " compressed " : " ") + c.output_name() + " " +
                           c.tiling.name + " " + c.blobs.method + " " + c.opt + (c.dither ? " dither" : " plain");
  const std::vector<std::uint64_t>& b = o.counts.block_runs;
  std::string lines;
  char line[96];
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (!b[i]) continue;
    const std::uint32_t address = flash_base + 2 * std::uint32_t(i);
    std::uint32_t size = 0, cost = 0;
    prog.emu->block_cost(address, &size, &cost);
    std::snprintf(line, sizeof line, "\t0x%08x\t%u\t%llu\t%llu\n", unsigned(address), unsigned(size),
                  static_cast<unsigned long long>(b[i]), static_cast<unsigned long long>(b[i] * cost));
    lines += name + line;
  }
  return lines;
}

void print_line(const json& j) {
  std::printf("%s\n", j.dump().c_str());
  std::fflush(stdout);
}

// What the run gathers over its configurations.
struct Results {
  std::vector<Row> rows;
  std::vector<PanelRow> panel_rows;  // -O2 without dithering: what a display gets
  bool all_equal = true, stacks_within = true;
  std::string address_lines;  // --profile-addresses
};

// Runs one configuration on `prog`, prints its line and adds it to `res`.
void run_configuration(const RunOptions& ro, Program& prog, const Configuration& c, Results& res) {
  const bench_params p = params_of(c);
  json j = configuration_json(c);
  const Outcome o = run_on(*prog.emu, prog.elf, c.blob(), p);
  if (!o.ran) {
    j["skipped"] = o.skipped;
    return print_line(j);
  }
  const Digest m4{o.result.hash_a, o.result.hash_b, o.result.tiles};
  const Digest host = host_digest(c.blobs.v1, p);
  add_counts(j, c, o);
  add_memory(j, prog, o);
  j["pixels_equal_host"] = m4 == host;
  res.all_equal &= m4 == host;
  if (ro.check_stack) {
    const core::Method method = c.blobs.opened.method;
    const bool within =
        o.stack_bytes <= (c.compressed() ? core_compressed_stack_bytes(method) : core_stack_bytes(method));
    j["stack_within_core_stack_bytes"] = within;
    // The limits are the Cortex-M4's; another core's stack is reported against them, not held to them.
    if (c.core == Core::m4) res.stacks_within &= within;
  }
  if (ro.check_counts) {
    const bool same = counts_agree(prog, c, p, o);
    j["per_instruction_counts_equal"] = same;
    res.all_equal &= same;
  }
  if (ro.profile > 0) j["profile_percent"] = profile_json(prog, o, ro.profile);
  if (ro.stack_chain) j["stack_chain"] = stack_chain_json(prog, o);
  if (!ro.address_profile.empty()) res.address_lines += block_lines(prog, c, o);
  print_line(j);
  const Counts& rc = o.counts.counted;
  const double pixels = double(c.width()) * c.height();
  res.rows.push_back({c.blobs.mesh, c.output_name(), c.tiling.name, c.blobs.method, c.opt, c.dither, c.compressed(),
                      per(rc.cycles, pixels), o.stack_bytes, c.blob().size(), o.open_counts.counted.cycles});
  if (c.opt == "O2" && !c.dither && c.core == Core::m4)
    res.panel_rows.push_back(
        {c.blobs.mesh, c.output_name(), c.tiling.name, c.blobs.method, c.kind, c.width(), c.height(), rc.cycles});
}

// The summary tables of one core's rows, titled by its name (the panel table: the clocks of
// Cortex-M4 parts, its rows only).
void print_tables(const RunOptions& o, Core core, const Results& res) {
  std::vector<std::string> out_names;
  for (const Row& r : res.rows)
    if (std::find(out_names.begin(), out_names.end(), r.output) == out_names.end()) out_names.push_back(r.output);
  print_summary(res.rows, o.meshes, out_names, o.tilings, core_title(core));
  if (core == Core::m4) print_panel_table(res.panel_rows);
  print_stack_summary(res.rows, o.methods, core_title(core));
}

}  // namespace

int run_matrix(const RunOptions& o) {
  const Matrix matrix = parse_matrix(o);
  const std::vector<Core> cores = parse_cores(o);
  Programs programs(o);
  std::map<Core, Results> by_core;
  for (const std::string& mesh : o.meshes) {
    const Triangulation tri = make_mesh(mesh);
    for (const std::string& method : o.methods) {
      MeshBlobs blobs;
      pack_mesh(tri, mesh, method, blobs);
      for (Core core : cores)
        for (const std::string& kind : o.blob_kinds)
          for (const Size& size : matrix.sizes)
            for (const Tiling& t : matrix.tilings)
              for (const std::string& opt : o.opts)
                for (const std::string& d : o.dithers) {
                  Program& prog = programs.get(core, opt, method, blobs.opened.space == core::ColorSpace::grey);
                  run_configuration(o, prog, Configuration{core, blobs, kind, size, t, opt, d == "on"}, by_core[core]);
                }
    }
  }
  bool all_equal = true, stacks_within = true;
  std::string address_lines;
  for (Core core : cores) {
    const Results& res = by_core[core];
    print_tables(o, core, res);
    if (!res.all_equal)
      std::fprintf(stderr, "bench_mcu: the emulated %s differs from the host (pixels or counts)\n", core_title(core));
    all_equal &= res.all_equal;
    stacks_within &= res.stacks_within;
    address_lines += res.address_lines;
  }
  if (!stacks_within)
    std::fprintf(stderr, "bench_mcu: a stack high-water mark exceeds core_stack_bytes (core_bridge/core_stack.h)\n");
  if (!o.address_profile.empty()) write_file_atomically(o.address_profile, address_lines);
  return all_equal && stacks_within ? 0 : 1;
}

}  // namespace tristream::bench_mcu
