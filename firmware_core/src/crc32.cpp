// SPDX-License-Identifier: MIT
#include "crc32.h"

#include "bytes.h"

namespace tristream::core::detail {

namespace {

constexpr uint32_t reflected_polynomial = 0xEDB88320u;

// The CRC register after shifting the low four bits of `value` through the polynomial.
constexpr uint32_t nibble_step(uint32_t value) {
  for (int k = 0; k < 4; ++k) value = (value >> 1) ^ (reflected_polynomial & (0u - (value & 1u)));
  return value;
}

// Four bits a lookup: 64 bytes of table, not the 1 KB of a byte a lookup, which is faster where
// the table reads cost no wait states (docs/FORMAT.md, "The checksum", weighs the choices).
struct NibbleTable {
  uint32_t v[16];
};
constexpr NibbleTable make_table() {
  NibbleTable t{};
  for (uint32_t i = 0; i < 16; ++i) t.v[i] = nibble_step(i);
  return t;
}
constexpr NibbleTable table = make_table();

}  // namespace

uint32_t crc32(uint32_t crc, const uint8_t* p, size_t n) {
  crc = ~crc;
  // A word a load (unaligned loads are single loads on the M4), its eight nibbles written out (a
  // helper function is a call a nibble at -Os).
  for (; n >= 4; n -= 4, p += 4) {
    crc ^= load_u32(p);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
  }
  for (; n; --n) {
    crc ^= *p++;
    crc = table.v[crc & 15] ^ (crc >> 4);
    crc = table.v[crc & 15] ^ (crc >> 4);
  }
  return ~crc;
}

}  // namespace tristream::core::detail
