/* SPDX-License-Identifier: MIT */
#pragma once
// The mapping of domain positions to output positions when the output has another size than the
// triangulation: corner to corner, rounded to nearest, in position_fx.
#include <stdint.h>

#include "tristream/config.h"

namespace tristream::core::detail {
namespace {

// Domain position_fx -> output position_fx, corner to corner, rounded to nearest:
// v' = floor((v n + floor(d / 2)) / d) with n = W' - 1, d = W - 1 (per axis). Raw positions are
// at most 65536 and n, d below 2^12 (max_dimension), so v n + d / 2 < 2^28: unsigned 32-bit
// arithmetic, one hardware division on Cortex-M4 (64-bit division is a library call there).
struct Mapping {
  uint32_t nx = 1, dx = 1, ny = 1, dy = 1;
  bool identity = true;

  int32_t x(int32_t v) const { return identity ? v : int32_t((uint32_t(v) * nx + dx / 2) / dx); }
  int32_t y(int32_t v) const { return identity ? v : int32_t((uint32_t(v) * ny + dy / 2) / dy); }
};
static_assert(uint64_t(65536) * (config::max_dimension - 1) + config::max_dimension / 2 < (uint64_t(1) << 32),
              "mapped positions must be computed in 32 bits");

}  // namespace
}  // namespace tristream::core::detail
