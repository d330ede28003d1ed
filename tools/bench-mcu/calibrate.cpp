// SPDX-License-Identifier: MIT
#include "calibrate.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "common/errors.h"
#include "elf_image.h"
#include "m4_emulator.h"

namespace tristream::bench_mcu {

namespace {

std::string string_at(const ElfImage& elf, std::uint32_t address) {
  std::string s;
  for (std::uint32_t a = address;; ++a) {
    const char ch = char(elf.read(a, 1)[0]);
    if (!ch) return s;
    s += ch;
  }
}

// The calls of refusal_cases (name, function, r0, expected text; ended by a zero function) must
// each throw an error containing the expected text. Returns the number that did not.
int refusals(const ElfImage& elf, Core core) {
  if (!elf.symbols.count("refusal_cases")) return 0;
  M4Emulator emu(elf, false, core);
  const std::uint32_t top = elf.symbol("__stack_top").address;
  int failures = 0;
  for (std::uint32_t at = elf.symbol("refusal_cases").address;; at += 16) {
    const std::vector<std::uint8_t> raw = elf.read(at, 16);
    std::uint32_t e[4];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    const std::string expected = string_at(elf, e[3]);
    std::string error = "(no error)";
    try {
      emu.call(e[1] & ~1u, top, {e[2]});
    } catch (const std::runtime_error& x) {
      error = x.what();
    }
    const bool ok = error.find(expected) != std::string::npos;
    std::printf("%-26s refused: %s  %s\n", string_at(elf, e[0]).c_str(), error.c_str(), ok ? "ok" : "MISMATCH");
    failures += !ok;
    emu.reset_data();
  }
  return failures;
}

}  // namespace

// The calibration loops of m4/calibrate.S: a table of {name, function, r0, instructions, cycles},
// ended by a zero function; each is run with block counting and with per-instruction counting.
int calibrate(const std::string& path, Core core) {
  const ElfImage elf = read_elf(path);
  M4Emulator fast(elf, false, core), slow(elf, true, core);
  const std::uint32_t table = elf.symbol("calibration_cases").address;
  const std::uint32_t top = elf.symbol("__stack_top").address;
  int failures = 0, cases = 0;
  for (std::uint32_t at = table;; at += 20) {
    const std::vector<std::uint8_t> raw = elf.read(at, 20);
    std::uint32_t e[5];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    const std::string name = string_at(elf, e[0]);
    const RunCounts f = fast.call(e[1] & ~1u, top, {e[2]});
    const RunCounts s = slow.call(e[1] & ~1u, top, {e[2]});
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
  const int refused_wrongly = refusals(elf, core);
  return failures || refused_wrongly ? 1 : 0;
}

}  // namespace tristream::bench_mcu
