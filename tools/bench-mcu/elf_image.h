/* SPDX-License-Identifier: MIT */
#pragma once
// A 32-bit little-endian ARM or RISC-V ELF executable as the harness needs it: the loadable
// segments (at their run addresses), the symbols, and the Thumb code ranges (from the $t / $d
// mapping symbols; none for RISC-V).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tristream::bench_mcu {

struct ElfSegment {
  std::uint32_t address = 0;        // run address (p_vaddr)
  std::uint32_t memory_size = 0;    // bytes past the file's are zero
  std::vector<std::uint8_t> bytes;  // the file's bytes
  bool executable = false;
};

struct ElfSymbol {
  std::uint32_t address = 0;  // functions: without the Thumb bit
  std::uint32_t size = 0;
  bool function = false;
};

struct CodeRange {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
};

struct ElfFunction {
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  std::string name;
};

struct ElfImage {
  std::string path;
  std::uint16_t machine = 0;  // e_machine: EM_ARM or EM_RISCV
  std::vector<ElfSegment> segments;
  std::map<std::string, ElfSymbol> symbols;
  // Every function symbol, local ones of one name included, sorted; one without a size (assembly)
  // extends to the next function.
  std::vector<ElfFunction> functions;
  std::vector<CodeRange> thumb_code;  // instructions only (literal pools excluded), sorted

  // Throws DataError naming the file when the symbol is missing.
  const ElfSymbol& symbol(const std::string& name) const;
  // The bytes at [address, address + size) from the segments; throws if not all in one segment.
  std::vector<std::uint8_t> read(std::uint32_t address, std::uint32_t size) const;
};

// Throws DataError ("<path>: byte N: ...") for a file that is not such an executable, and
// InputError when it cannot be read.
ElfImage read_elf(const std::string& path);

}  // namespace tristream::bench_mcu
