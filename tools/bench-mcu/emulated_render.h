/* SPDX-License-Identifier: MIT */
#pragma once
// One configuration of the matrix rendered twice: on an emulated core (run_on: counted, its stack
// measured) and with the host build of the core (host_digest), whose pixels the emulated core's
// must equal. Both reduce the pixels to a tile_hash.h digest.
#include <cstdint>
#include <string>
#include <vector>

#include "bench_protocol.h"
#include "elf_image.h"
#include "emulator.h"

namespace tristream::bench_mcu {

struct Digest {
  std::uint32_t a = 0, b = 0, tiles = 0;
  bool operator==(const Digest&) const = default;
};

// The same render with the host (x86-64) build of the core.
Digest host_digest(const std::vector<std::uint8_t>& blob, const bench_params& p);

struct Outcome {
  bool ran = false;
  std::string skipped;
  RunCounts open_counts;  // bench_open: open_blob or open_compressed_blob, as ts_open
  RunCounts counts;
  bench_result result{};
  std::uint32_t stack_bytes = 0;
};

// Opens, prepares and renders one configuration on `emu`; the open and the render are counted, the
// stack is painted before the render. A configuration whose buffers do not fit the emulated RAM is
// skipped (ran false, `skipped` says why); a failing call of the core throws.
Outcome run_on(Emulator& emu, const ElfImage& elf, const std::vector<std::uint8_t>& blob, const bench_params& p);

}  // namespace tristream::bench_mcu
