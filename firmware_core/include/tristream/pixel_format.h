/* SPDX-License-Identifier: MIT */
#pragma once
// Output pixel formats, as bytes in memory (the order a display or file expects).
#include <stdint.h>

namespace tristream::core {

enum class PixelFormat : uint8_t {
  l8 = 0,         // 1 byte: grey (BT.601 luma of colour blobs)
  rgb888 = 1,     // 3 bytes: R, G, B
  rgb565_le = 2,  // 2 bytes: (R5 << 11 | G6 << 5 | B5), low byte first
  rgb565_be = 3,  // 2 bytes: the same word, high byte first (the wire order of SPI displays)
  xrgb8888 = 4,   // 4 bytes: the word (0xFF << 24 | R << 16 | G << 8 | B), low byte first: B, G, R, 0xFF
  coverage8 = 5,  // 1 byte, for tests: starts at 0, every write of a triangle adds 1
};

inline constexpr int pixel_format_count = 6;

// Bytes per pixel; 0 for an unknown format.
constexpr int bytes_per_pixel(PixelFormat f) {
  switch (f) {
    case PixelFormat::l8: return 1;
    case PixelFormat::rgb888: return 3;
    case PixelFormat::rgb565_le: return 2;
    case PixelFormat::rgb565_be: return 2;
    case PixelFormat::xrgb8888: return 4;
    case PixelFormat::coverage8: return 1;
  }
  return 0;
}

}  // namespace tristream::core
