// SPDX-License-Identifier: MIT
#include "elf_image.h"

#include <elf.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

#include "common/errors.h"

namespace tristream::bench_mcu {

namespace {

template <typename T>
T read_at(const std::vector<std::uint8_t>& file, std::size_t offset, const std::string& path, const char* what) {
  if (offset > file.size() || file.size() - offset < sizeof(T))
    throw DataError(path + ": byte " + std::to_string(offset) + ": " + what + " past the end of the file");
  T t;
  std::memcpy(&t, file.data() + offset, sizeof(T));
  return t;
}

}  // namespace

const ElfSymbol& ElfImage::symbol(const std::string& name) const {
  const auto it = symbols.find(name);
  if (it == symbols.end()) throw DataError(path + ": no symbol " + name);
  return it->second;
}

std::vector<std::uint8_t> ElfImage::read(std::uint32_t address, std::uint32_t size) const {
  for (const ElfSegment& s : segments)
    if (address >= s.address && std::uint64_t(address) + size <= std::uint64_t(s.address) + s.bytes.size())
      return {s.bytes.begin() + (address - s.address), s.bytes.begin() + (address - s.address) + size};
  throw DataError(path + ": address " + std::to_string(address) + " is not in a loaded segment");
}

ElfImage read_elf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open");
  const std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto eh = read_at<Elf32_Ehdr>(file, 0, path, "ELF header");
  if (std::memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0 || eh.e_ident[EI_CLASS] != ELFCLASS32 ||
      eh.e_ident[EI_DATA] != ELFDATA2LSB || (eh.e_machine != EM_ARM && eh.e_machine != EM_RISCV) ||
      eh.e_type != ET_EXEC)
    throw DataError(path + ": byte 0: expected a 32-bit little-endian ARM or RISC-V executable");
  ElfImage image;
  image.path = path;
  image.machine = eh.e_machine;
  for (int i = 0; i < eh.e_phnum; ++i) {
    const std::size_t at = eh.e_phoff + std::size_t(i) * eh.e_phentsize;
    const auto ph = read_at<Elf32_Phdr>(file, at, path, "program header");
    if (ph.p_type != PT_LOAD || ph.p_memsz == 0) continue;
    if (ph.p_offset > file.size() || file.size() - ph.p_offset < ph.p_filesz || ph.p_filesz > ph.p_memsz)
      throw DataError(path + ": byte " + std::to_string(at) + ": segment outside the file");
    ElfSegment s;
    s.address = ph.p_vaddr;
    s.memory_size = ph.p_memsz;
    s.bytes.assign(file.begin() + ph.p_offset, file.begin() + ph.p_offset + ph.p_filesz);
    s.executable = (ph.p_flags & PF_X) != 0;
    image.segments.push_back(std::move(s));
  }
  // Symbols, and the mapping symbols that mark where code and data start in each section.
  struct Mapping {
    std::uint32_t address;
    std::uint16_t section;
    bool code;
  };
  std::vector<Mapping> mappings;
  std::vector<Elf32_Shdr> sections;
  for (int i = 0; i < eh.e_shnum; ++i)
    sections.push_back(read_at<Elf32_Shdr>(file, eh.e_shoff + std::size_t(i) * eh.e_shentsize, path, "section header"));
  for (const Elf32_Shdr& sh : sections) {
    if (sh.sh_type != SHT_SYMTAB) continue;
    if (sh.sh_link >= sections.size()) throw DataError(path + ": symbol table without strings");
    const Elf32_Shdr& strings = sections[sh.sh_link];
    for (std::uint32_t off = 0; off + sizeof(Elf32_Sym) <= sh.sh_size; off += sizeof(Elf32_Sym)) {
      const auto sym = read_at<Elf32_Sym>(file, sh.sh_offset + off, path, "symbol");
      if (sym.st_name >= strings.sh_size) throw DataError(path + ": symbol name outside the string table");
      const char* name = reinterpret_cast<const char*>(file.data() + strings.sh_offset + sym.st_name);
      const std::string n(name, strnlen(name, strings.sh_size - sym.st_name));
      if (sym.st_shndx == SHN_UNDEF || sym.st_shndx >= SHN_LORESERVE) {
        if (sym.st_shndx == SHN_ABS && !n.empty()) image.symbols[n] = {sym.st_value, sym.st_size, false};
        continue;
      }
      if (n == "$t" || n.rfind("$t.", 0) == 0 || n == "$d" || n.rfind("$d.", 0) == 0) {
        mappings.push_back({sym.st_value & ~1u, sym.st_shndx, n[1] == 't'});
        continue;
      }
      if (n.empty() || ELF32_ST_TYPE(sym.st_info) == STT_SECTION || ELF32_ST_TYPE(sym.st_info) == STT_FILE) continue;
      const bool function = ELF32_ST_TYPE(sym.st_info) == STT_FUNC;
      if (function) image.functions.push_back({sym.st_value & ~1u, (sym.st_value & ~1u) + sym.st_size, n});
      // Local symbols of one name in several files: the first one wins; the harness only looks
      // up the program's own global symbols by name.
      image.symbols.emplace(n, ElfSymbol{function ? sym.st_value & ~1u : sym.st_value, sym.st_size, function});
    }
  }
  std::sort(image.functions.begin(), image.functions.end(),
            [](const ElfFunction& a, const ElfFunction& b) { return a.begin < b.begin; });
  for (std::size_t i = 0; i < image.functions.size(); ++i)
    if (image.functions[i].end == image.functions[i].begin && i + 1 < image.functions.size())
      image.functions[i].end = image.functions[i + 1].begin;
  std::sort(mappings.begin(), mappings.end(), [](const Mapping& a, const Mapping& b) {
    return a.section != b.section ? a.section < b.section : a.address < b.address;
  });
  for (std::size_t i = 0; i < mappings.size(); ++i) {
    if (!mappings[i].code) continue;
    const Elf32_Shdr& sh = sections[mappings[i].section];
    std::uint32_t end = sh.sh_addr + sh.sh_size;
    if (i + 1 < mappings.size() && mappings[i + 1].section == mappings[i].section) end = mappings[i + 1].address;
    if (end > mappings[i].address) image.thumb_code.push_back({mappings[i].address, end});
  }
  std::sort(image.thumb_code.begin(), image.thumb_code.end(),
            [](const CodeRange& a, const CodeRange& b) { return a.begin < b.begin; });
  return image;
}

}  // namespace tristream::bench_mcu
