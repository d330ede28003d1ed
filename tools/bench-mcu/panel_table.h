// SPDX-License-Identifier: MIT
#pragma once
// What a display gets from the measured cycles: milliseconds per frame at the clock speeds of
// common Cortex-M4 parts, beside the time the frame's RGB565 bytes take on an SPI bus.
#include <cstdint>
#include <string>
#include <vector>

namespace tristream::bench_mcu {

struct PanelRow {
  std::string mesh, output, tiling, method, blob;  // blob: v1 or compressed
  int width = 0, height = 0;                        // output pixels
  std::uint64_t cycles = 0;                         // the frame's modelled cycles
};

// Clocks in MHz: nRF52840 (64), SAMD51 (120), STM32F405/407 (168), STM32F429 (180).
inline constexpr int panel_clocks_mhz[] = {64, 120, 168, 180};
// SPI clocks in MHz a panel controller such as the ST7789 or ILI9341 is commonly driven at.
inline constexpr int spi_clocks_mhz[] = {40, 62};

// Milliseconds `cycles` take at `mhz`.
double frame_milliseconds(std::uint64_t cycles, int mhz);
// Milliseconds of an RGB565 frame (16 bits a pixel) on one SPI data line at `mhz`.
double spi_milliseconds(int width, int height, int mhz);
// The table, one line per row, to stdout.
void print_panel_table(const std::vector<PanelRow>& rows);

}  // namespace tristream::bench_mcu
