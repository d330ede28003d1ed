/* SPDX-License-Identifier: MIT */
#pragma once
// CRC-32/ISO-HDLC, the CRC of zlib, PNG and Ethernet: polynomial 0x04C11DB7 reflected
// (0xEDB88320), initial value and final XOR 0xFFFFFFFF. crc32(0, "123456789", 9) is 0xCBF43926.
#include <stddef.h>
#include <stdint.h>

#include "tristream/config.h"  // first: in a C++ mode before C++17 its #error says so

namespace tristream::core::detail {

// The CRC of `n` bytes continued from `crc`, the CRC of the bytes before them (0 for none):
// crc32(crc32(0, a, na), b, nb) is the CRC of a followed by b.
uint32_t crc32(uint32_t crc, const uint8_t* bytes, size_t n);

}  // namespace tristream::core::detail
