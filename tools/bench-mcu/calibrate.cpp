// SPDX-License-Identifier: MIT
#include "calibrate.h"

#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include "common/errors.h"
#include "elf_image.h"
#include "emulator.h"

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

// The image's refusal_cases, if it has them: {name, function, first argument, the error's
// expected text}, ended by a zero function; each call must stop the run with an error containing
// that text, counting per block and per instruction. Returns the cases that did not.
int refusals(const ElfImage& elf, Emulator& fast, Emulator& slow, std::uint32_t top) {
  if (!elf.symbols.count("refusal_cases")) return 0;
  int failures = 0;
  for (std::uint32_t at = elf.symbol("refusal_cases").address;; at += 16) {
    const std::vector<std::uint8_t> raw = elf.read(at, 16);
    std::uint32_t e[4];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    const std::string expected = string_at(elf, e[3]);
    for (Emulator* emu : {&fast, &slow}) {
      const char* counting = emu == &fast ? "per block" : "per instruction";
      std::string error = "(no error)";
      try {
        emu->call(e[1] & ~1u, top, {e[2]});
      } catch (const std::runtime_error& x) {
        error = x.what();
      }
      const bool ok = error.find(expected) != std::string::npos;
      std::printf("%-26s %-15s refused: %s  %s\n", string_at(elf, e[0]).c_str(), counting, error.c_str(),
                  ok ? "ok" : "MISMATCH");
      failures += !ok;
      emu->reset_data();
    }
  }
  return failures;
}

}  // namespace

// The calibration loops of m4/calibrate.S, m0plus/calibrate.S or riscv/calibrate.S: a table of
// {name, function, first argument, instructions, cycles}, ended by a zero function; each is run
// with block counting and with per-instruction counting. Then the refusal cases, if any.
int calibrate(const std::string& path, Core core) {
  const ElfImage elf = read_elf(path);
  const std::unique_ptr<Emulator> fast = make_emulator(core, elf, false);
  const std::unique_ptr<Emulator> slow = make_emulator(core, elf, true);
  const std::uint32_t table = elf.symbol("calibration_cases").address;
  const std::uint32_t top = elf.symbol("__stack_top").address;
  int failures = 0, cases = 0;
  for (std::uint32_t at = table;; at += 20) {
    const std::vector<std::uint8_t> raw = elf.read(at, 20);
    std::uint32_t e[5];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    const std::string name = string_at(elf, e[0]);
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
  failures += refusals(elf, *fast, *slow, top);
  return failures ? 1 : 0;
}

}  // namespace tristream::bench_mcu
