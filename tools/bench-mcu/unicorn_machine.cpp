// SPDX-License-Identifier: MIT
#include "unicorn_machine.h"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <stdexcept>

namespace tristream::bench_mcu {

void UnicornMachine::check(int error, const char* what) {
  if (error != UC_ERR_OK)
    throw std::runtime_error(std::string("unicorn: ") + what + ": " + uc_strerror(uc_err(error)));
}

UnicornMachine::UnicornMachine(const ElfImage& elf, int arch, int mode, int cpu_model) : elf_(elf) {
  check(uc_open(uc_arch(arch), uc_mode(mode), &uc_), "open");
  try {
    if (cpu_model >= 0) check(uc_ctl_set_cpu_model(uc_, cpu_model), "select the CPU model");
    check(uc_mem_map(uc_, flash_base, flash_size, UC_PROT_READ | UC_PROT_EXEC), "map flash");
    check(uc_mem_map(uc_, ram_base, ram_size, UC_PROT_READ | UC_PROT_WRITE), "map RAM");
    check(uc_mem_map(uc_, rom_base, rom_size, UC_PROT_READ), "map the blob region");
    for (const ElfSegment& s : elf.segments) {
      const bool in_flash =
          s.address >= flash_base && std::uint64_t(s.address) + s.memory_size <= flash_base + flash_size;
      const bool in_ram = s.address >= ram_base && std::uint64_t(s.address) + s.memory_size <= ram_base + ram_size;
      if (!in_flash && !in_ram)
        throw std::runtime_error(elf.path + ": a segment lies outside the board's flash and RAM");
      if (s.executable && !in_flash) throw std::runtime_error(elf.path + ": code outside flash");
    }
    reset_data();
    halt_ = elf.symbol("bench_halt").address;
  } catch (...) {
    uc_close(uc_);
    throw;
  }
  functions_ = elf.functions;
  functions_.push_back({0, 0, "(no symbol)"});
  block_index_.assign(flash_size / 2, -1);
}

UnicornMachine::~UnicornMachine() { uc_close(uc_); }

void UnicornMachine::write(std::uint32_t address, const void* data, std::size_t size) {
  check(uc_mem_write(uc_, address, data, size), "write memory");
}

void UnicornMachine::read(std::uint32_t address, void* data, std::size_t size) {
  check(uc_mem_read(uc_, address, data, size), "read memory");
}

void UnicornMachine::fill(std::uint32_t address, std::uint32_t word, std::size_t words) {
  const std::vector<std::uint32_t> v(words, word);
  write(address, v.data(), v.size() * 4);
}

void UnicornMachine::reset_data() {
  for (const ElfSegment& s : elf_.segments) {
    std::vector<std::uint8_t> bytes = s.bytes;
    bytes.resize(s.memory_size, 0);
    write(s.address, bytes.data(), bytes.size());
  }
}

void UnicornMachine::set_excluded(std::uint32_t begin, std::uint32_t end) {
  exclude_begin_ = begin;
  exclude_end_ = end;
}

void UnicornMachine::start_call(const std::vector<std::uint32_t>& args, int first_register, const char* what) {
  if (args.size() > 4) throw std::runtime_error("call: at most 4 register arguments");
  run_ = RunCounts{};
  run_.function_cycles.assign(functions_.size(), 0);
  run_.function_entries.assign(functions_.size(), 0);
  if (address_profile_) run_.block_runs.assign(flash_size / 2, 0);
  error_.clear();
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::uint32_t v = args[i];
    check(uc_reg_write(uc_, first_register + int(i), &v), what);
  }
}

std::uint32_t UnicornMachine::function_of(std::uint32_t address) const {
  auto it = std::upper_bound(functions_.begin(), functions_.end() - 1, address,
                             [](std::uint32_t a, const ElfFunction& f) { return a < f.begin; });
  if (it != functions_.begin()) {
    --it;
    if (address < it->end) return std::uint32_t(it - functions_.begin());
  }
  return std::uint32_t(functions_.size() - 1);
}

void UnicornMachine::fail(const std::string& message) {
  if (error_.empty()) error_ = message;
  uc_emu_stop(uc_);
}

}  // namespace tristream::bench_mcu
