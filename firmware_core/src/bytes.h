/* SPDX-License-Identifier: MIT */
#pragma once
// Little-endian loads and stores of unaligned bytes, the only ones of the core and of the host's
// packer and unpacker (wire_layout.h names where they go). Compilers turn the loads into single
// loads; the stores are one memcpy each on a little-endian target with unaligned access, which
// compilers do not always make of the byte stores.
#include <stdint.h>
#include <string.h>

// Whether a halfword or word store to an address of unknown alignment is one instruction. Not on
// ARMv6-M (Cortex-M0+), which has no unaligned access: there GCC makes such a memcpy of 2 or 4
// bytes a call of the C library's memcpy (about 43 cycles in it on the M0+ for 2 bytes), so the
// stores are byte stores.
#if defined(__ARM_ARCH) && !defined(__ARM_FEATURE_UNALIGNED)
#define TS_UNALIGNED_STORES 0
#else
#define TS_UNALIGNED_STORES 1
#endif

namespace tristream::core::detail {

inline uint16_t load_u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
// load_u16 of an even address: one halfword load on every target, ARMv6-M included (where
// load_u16, its address's alignment unknown, is two byte loads). For the tile path's reads of a
// blob's u16 arrays (sections 4-aligned in a blob at an even address: blob_address_fits) and of
// the band store's (4-aligned in the workspace).
inline uint16_t load_u16_even(const uint8_t* p) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && !TS_UNALIGNED_STORES
  uint16_t x;
  memcpy(&x, __builtin_assume_aligned(p, 2), 2);
  return x;
#else
  return load_u16(p);
#endif
}
// Whether a blob at `address` suits this core: any address where halfword loads take any address
// (`unaligned_access`: TS_UNALIGNED_STORES), else an even one (load_u16_even).
constexpr bool blob_address_fits(uintptr_t address, bool unaligned_access) {
  return unaligned_access || (address & 1) == 0;
}
inline uint32_t load_u32(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
inline int32_t load_i32(const uint8_t* p) { return int32_t(load_u32(p)); }

// Stores the low 16 bits of v.
inline void store_u16(uint8_t* p, uint32_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
  const uint16_t x = uint16_t(v);
  memcpy(p, &x, 2);
#else
  p[0] = uint8_t(v & 0xFFu);
  p[1] = uint8_t((v >> 8) & 0xFFu);
#endif
}
inline void store_u32(uint8_t* p, uint32_t v) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && TS_UNALIGNED_STORES
  memcpy(p, &v, 4);
#else
  store_u16(p, v & 0xFFFFu);
  store_u16(p + 2, v >> 16);
#endif
}
inline void store_i32(uint8_t* p, int32_t v) { store_u32(p, uint32_t(v)); }

}  // namespace tristream::core::detail
