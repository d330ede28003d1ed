// SPDX-License-Identifier: MIT
#include "summary.h"

#include <algorithm>
#include <cstdio>

#include "core_bridge/core_stack.h"
#include "core_bridge/pack.h"

namespace tristream::bench_mcu {

namespace {

std::string fmt(double v, const char* f = "%.0f") {
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

// The human summary: cycles per pixel side by side, and the ratios between configurations.
void print_summary(const std::vector<Row>& rows, const std::vector<std::string>& meshes,
                   const std::vector<std::string>& outputs, const std::vector<std::string>& tilings, const char* core) {
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
  std::printf("\nModelled %s cycles per output pixel, RGB565 BE (zero wait states)\n", core);
  std::printf("%-9s %-8s %-8s | %-22s | %-22s | %-11s | %-11s | %-11s | %s\n", "mesh", "output", "tiling",
              "bilinear O2 / Os", "zienkiewicz O2 / Os", "zienk/bil", "Os/O2 b z", "dither b z", "stack O2 Os");
  for (const std::string& mesh : meshes)
    for (const std::string& out : outputs)
      for (const std::string& tiling : tilings) {
        const Row* b2 = find(mesh, out, tiling, "bilinear", "O2", false);
        const Row* bs = find(mesh, out, tiling, "bilinear", "Os", false);
        const Row* z2 = find(mesh, out, tiling, "zienkiewicz", "O2", false);
        const Row* zs = find(mesh, out, tiling, "zienkiewicz", "Os", false);
        const Row* b2d = find(mesh, out, tiling, "bilinear", "O2", true);
        const Row* z2d = find(mesh, out, tiling, "zienkiewicz", "O2", true);
        if (!b2 && !z2 && !bs && !zs) continue;
        std::uint32_t s2 = 0, ss = 0;  // the largest stack of the row, per optimisation level
        for (const Row& r : rows)
          if (r.mesh == mesh && r.output == out && r.tiling == tiling && !r.compressed) {
            std::uint32_t& s = r.opt == "O2" ? s2 : ss;
            s = std::max(s, r.stack);
          }
        auto bytes = [](std::uint32_t b) { return b ? std::to_string(b) : std::string("-"); };
        std::printf("%-9s %-8s %-8s | %10s %11s | %10s %11s | %11s | %5s %5s | %5s %5s | %5s %5s\n", mesh.c_str(),
                    out.c_str(), tiling.c_str(), cell(b2).c_str(), cell(bs).c_str(), cell(z2).c_str(),
                    cell(zs).c_str(), ratio(z2, b2).c_str(), ratio(bs, b2).c_str(), ratio(zs, z2).c_str(),
                    ratio(b2d, b2).c_str(), ratio(z2d, z2).c_str(), bytes(s2).c_str(), bytes(ss).c_str());
      }
  // What opening each blob costs (open_blob checks every byte of a v1 blob and its CRC-32;
  // open_compressed_blob the header and the layer table), once per mesh, method, level and kind.
  std::printf("\nModelled %s cycles of ts_open (open_blob, open_compressed_blob)\n", core);
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

void print_stack_summary(const std::vector<Row>& rows, const std::vector<std::string>& methods) {
  for (const std::string& method : methods) {
    std::uint32_t most = 0, most_compressed = 0;
    for (const Row& r : rows) {
      if (r.method != method) continue;
      std::uint32_t& m = r.compressed ? most_compressed : most;
      m = std::max(m, r.stack);
    }
    std::printf("largest stack high-water mark, %s: %u bytes (core_stack_bytes: %zu)\n", method.c_str(), most,
                core_stack_bytes(parse_core_method(method)));
    if (most_compressed)
      std::printf("largest stack high-water mark, %s, compressed: %u bytes (core_compressed_stack_bytes: %zu)\n",
                  method.c_str(), most_compressed, core_compressed_stack_bytes(parse_core_method(method)));
  }
}

}  // namespace tristream::bench_mcu
