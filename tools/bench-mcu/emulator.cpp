// SPDX-License-Identifier: MIT
#include "emulator.h"

#include "common/errors.h"
#include "riscv_emulator.h"

namespace tristream::bench_mcu {

namespace {

// An emulator class with the interface's member functions (not virtual) behind the interface.
template <typename E>
class Adapted final : public Emulator {
 public:
  template <typename... More>
  Adapted(const ElfImage& elf, bool per_instruction, More... more) : e_(elf, per_instruction, more...) {}
  void write(std::uint32_t address, const void* data, std::size_t size) override { e_.write(address, data, size); }
  void read(std::uint32_t address, void* data, std::size_t size) override { e_.read(address, data, size); }
  void fill(std::uint32_t address, std::uint32_t word, std::size_t words) override { e_.fill(address, word, words); }
  void reset_data() override { e_.reset_data(); }
  void exclude(std::uint32_t begin, std::uint32_t end) override { e_.exclude(begin, end); }
  RunCounts call(std::uint32_t function, std::uint32_t stack_top, const std::vector<std::uint32_t>& args) override {
    return e_.call(function, stack_top, args);
  }
  const std::vector<ElfFunction>& functions() const override { return e_.functions(); }
  void set_address_profile(bool on) override { e_.set_address_profile(on); }
  void set_stack_chain(bool on) override { e_.set_stack_chain(on); }
  void block_cost(std::uint32_t address, std::uint32_t* size, std::uint32_t* cycles) const override {
    e_.block_cost(address, size, cycles);
  }

 private:
  E e_;
};

}  // namespace

std::unique_ptr<Emulator> make_emulator(Core core, const ElfImage& elf, bool per_instruction) {
  if (elf.machine != core_machine(core))
    throw DataError(elf.path + ": not a program for the " + core_title(core) + " (another architecture)");
  if (core == Core::rv32imc) return std::make_unique<Adapted<riscv::RiscvEmulator>>(elf, per_instruction);
  return std::make_unique<Adapted<M4Emulator>>(elf, per_instruction, core);
}

}  // namespace tristream::bench_mcu
