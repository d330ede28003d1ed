// SPDX-License-Identifier: MIT
#include "calibrate.h"

#include <cstdio>
#include <cstring>
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

// The image's fault_cases, if it has them: {name, function, first argument}, ended by a zero
// function; each must stop with the harness's misaligned-access error, counting per block and per
// instruction. Returns the cases that did not.
int run_fault_cases(const ElfImage& elf, Emulator& fast, Emulator& slow, std::uint32_t top) {
  if (!elf.symbols.count("fault_cases")) return 0;
  int failures = 0;
  for (std::uint32_t at = elf.symbol("fault_cases").address;; at += 12) {
    const std::vector<std::uint8_t> raw = elf.read(at, 12);
    std::uint32_t e[3];
    std::memcpy(e, raw.data(), sizeof e);
    if (e[1] == 0) break;
    for (Emulator* emu : {&fast, &slow}) {
      std::string error = "no error";
      try {
        emu->call(e[1], top, {e[2]});
      } catch (const std::runtime_error& x) {
        error = x.what();
      }
      const bool ok = error.find("misaligned") != std::string::npos;
      std::printf("%-26s %s  %s\n", string_at(elf, e[0]).c_str(), error.c_str(), ok ? "ok" : "EXPECTED A FAULT");
      failures += !ok;
    }
  }
  return failures;
}

}  // namespace

// The calibration loops of m4/calibrate.S or riscv/calibrate.S (by the ELF's machine): a table of
// {name, function, first argument, instructions, cycles}, ended by a zero function; each is run
// with block counting and with per-instruction counting. Then the fault cases, if any.
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
  failures += run_fault_cases(elf, *fast, *slow, top);
  return failures ? 1 : 0;
}

}  // namespace tristream::bench_mcu
