// SPDX-License-Identifier: MIT
// libFuzzer target: the .tri reader must accept or reject any bytes with a DataError, and a
// file it accepts must write back and read again to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "common/errors.h"
#include "io/tri_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;  // large inputs add time, not paths
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const tristream::Triangulation tri = tristream::parse_tri(text, "fuzz.tri");
    const std::string once = tristream::format_tri(tri);
    const std::string twice = tristream::format_tri(tristream::parse_tri(once, "fuzz-roundtrip.tri"));
    if (once != twice) std::abort();
  } catch (const tristream::DataError&) {
  }
  return 0;
}
