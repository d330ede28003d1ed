// SPDX-License-Identifier: MIT
#include "panel_table.h"

#include <cstdio>

namespace tristream::bench_mcu {

double frame_milliseconds(std::uint64_t cycles, int mhz) { return double(cycles) / (double(mhz) * 1000.0); }

double spi_milliseconds(int width, int height, int mhz) {
  return double(width) * double(height) * 16.0 / (double(mhz) * 1000.0);
}

void print_panel_table(const std::vector<PanelRow>& rows) {
  if (rows.empty()) return;
  std::printf("\nMilliseconds per frame on a Cortex-M4 at its clock (modelled cycles, zero wait states), "
              "RGB565 BE; SPI: the frame's bytes at the bus clock\n");
  std::printf("%-9s %-8s %-8s %-12s %-10s |", "mesh", "output", "tiling", "method", "blob");
  for (int mhz : panel_clocks_mhz) std::printf(" %4d MHz", mhz);
  std::printf(" |");
  for (int mhz : spi_clocks_mhz) std::printf(" SPI %2d MHz", mhz);
  std::printf("\n");
  for (const PanelRow& r : rows) {
    std::printf("%-9s %-8s %-8s %-12s %-10s |", r.mesh.c_str(), r.output.c_str(), r.tiling.c_str(), r.method.c_str(),
                r.blob.c_str());
    for (int mhz : panel_clocks_mhz) std::printf(" %8.1f", frame_milliseconds(r.cycles, mhz));
    std::printf(" |");
    for (int mhz : spi_clocks_mhz) std::printf(" %10.1f", spi_milliseconds(r.width, r.height, mhz));
    std::printf("\n");
  }
}

}  // namespace tristream::bench_mcu
