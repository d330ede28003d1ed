#pragma once
// The mapping of domain positions to output positions when the output has another size than the
// triangulation: corner to corner, rounded to nearest, in position_fx.
#include <stdint.h>

namespace tristream::core::detail {
namespace {

// Domain position_fx -> output position_fx, corner to corner, rounded to nearest.
struct Mapping {
  int64_t nx = 1, dx = 1, ny = 1, dy = 1;
  bool identity = true;

  int32_t x(int32_t v) const { return identity ? v : int32_t((v * nx + dx / 2) / dx); }
  int32_t y(int32_t v) const { return identity ? v : int32_t((v * ny + dy / 2) / dy); }
};

}  // namespace
}  // namespace tristream::core::detail
