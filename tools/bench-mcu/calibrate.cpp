// SPDX-License-Identifier: MIT
#include "calibrate.h"

#include <cstdio>
#include <cstring>
#include <vector>

#include "common/errors.h"
#include "elf_image.h"
#include "emulator.h"

namespace tristream::bench_mcu {

// The calibration loops of m4/calibrate.S or riscv/calibrate.S (by the ELF's machine): a table of
// {name, function, first argument, instructions, cycles}, ended by a zero function; each is run
// with block counting and with per-instruction counting.
int calibrate(const std::string& path) {
  const ElfImage elf = read_elf(path);
  const std::unique_ptr<Emulator> fast = make_emulator(cpu_of(elf), elf, false);
  const std::unique_ptr<Emulator> slow = make_emulator(cpu_of(elf), elf, true);
  const std::uint32_t table = elf.symbol("calibration_cases").address;
  const std::uint32_t top = elf.symbol("__stack_top").address;
  int failures = 0, cases = 0;
  for (std::uint32_t at = table;; at += 20) {
    const std::vector<std::uint8_t> raw = elf.read(at, 20);
    std::uint32_t e[5];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    std::string name;
    for (std::uint32_t a = e[0];; ++a) {
      const char ch = char(elf.read(a, 1)[0]);
      if (!ch) break;
      name += ch;
    }
    const RunCounts f = fast->call(e[1] & ~1u, top, {e[2]});
    const RunCounts s = slow->call(e[1] & ~1u, top, {e[2]});
    const bool ok = f.counted.instructions == e[3] && f.counted.cycles == e[4] &&
                    s.counted.instructions == e[3] && s.counted.cycles == e[4];
    std::printf("%-26s instructions %8llu (expected %8u, per instruction %8llu)  cycles %8llu (expected %8u, per "
                "instruction %8llu)  %s\n",
                name.c_str(), (unsigned long long)f.counted.instructions, e[3],
                (unsigned long long)s.counted.instructions, (unsigned long long)f.counted.cycles, e[4],
                (unsigned long long)s.counted.cycles, ok ? "ok" : "MISMATCH");
    failures += !ok;
    ++cases;
  }
  if (cases == 0) throw DataError(path + ": no calibration cases");
  std::printf("%d of %d calibration cases exact\n", cases - failures, cases);
  return failures ? 1 : 0;
}

}  // namespace tristream::bench_mcu
