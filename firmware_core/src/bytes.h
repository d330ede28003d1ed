/* SPDX-License-Identifier: MIT */
#pragma once
// Little-endian reads of unaligned bytes; compilers turn them into single loads.
#include <stdint.h>

namespace tristream::core::detail {

inline uint16_t load_u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
inline uint32_t load_u32(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
inline int32_t load_i32(const uint8_t* p) { return int32_t(load_u32(p)); }

}  // namespace tristream::core::detail
