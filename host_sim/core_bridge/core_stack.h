/* SPDX-License-Identifier: MIT */
#pragma once
// The stack the core needs on a Cortex-M4, for the RAM figures (tripack, docs/FIXED_POINT.md):
// per method, the largest high-water mark `make bench-mcu` measured below render()'s caller
// (painted stack; arm-none-eabi-g++ -O2 and -Os; RGB565 big-endian; single-mesh RGB blobs; every
// mesh, tiling, output size and dithering of its matrix), rounded up to 64 bytes. It includes a
// leaf sink's frame; a firmware adds the frames of its own sink beyond that. bench_mcu
// --check-stack (the bench_mcu_pixels test, and make bench-mcu) fails when a measured mark
// exceeds it, so it is raised, or the core's stack lowered, when the core changes.
#include <cstddef>

#include "tristream/blob.h"

namespace tristream {

inline constexpr std::size_t core_stack_bytes_bilinear = 1280;     // measured 1,248 (-O2), 1,188 (-Os)
inline constexpr std::size_t core_stack_bytes_zienkiewicz = 1536;  // measured 1,500 (-O2), 1,500 (-Os)

constexpr std::size_t core_stack_bytes(core::Method method) {
  return method == core::Method::zienkiewicz ? core_stack_bytes_zienkiewicz : core_stack_bytes_bilinear;
}

// The same for a compressed blob rendered from its streams (render.h): the decoder's frames
// below the band advance, besides the tile path's. Measured by make bench-mcu (--blobs compressed).
inline constexpr std::size_t core_compressed_stack_bytes_bilinear = 1408;     // measured 1,376 (-O2), 1,292 (-Os)
inline constexpr std::size_t core_compressed_stack_bytes_zienkiewicz = 1728;  // measured 1,628 (-O2), 1,604 (-Os)

constexpr std::size_t core_compressed_stack_bytes(core::Method method) {
  return method == core::Method::zienkiewicz ? core_compressed_stack_bytes_zienkiewicz
                                             : core_compressed_stack_bytes_bilinear;
}

}  // namespace tristream
