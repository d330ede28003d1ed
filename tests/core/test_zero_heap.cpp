// SPDX-License-Identifier: MIT
// The core never allocates: open, size and render run under counting replacements of
// operator new and malloc, and the counters must not move.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <dlfcn.h>
#include <new>

#include "core_support.h"

namespace {
std::atomic<long> allocations{0};
std::atomic<bool> counting{false};
}  // namespace

// Out of line: inlined into a new-expression, GCC pairs the new-expression with the free() below
// and warns (-Wmismatched-new-delete), although replacement operators may use malloc and free.
__attribute__((noinline)) void* operator new(std::size_t n) {
  if (counting) ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
__attribute__((noinline)) void operator delete(void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete(void* p, std::size_t) noexcept { std::free(p); }
__attribute__((noinline)) void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

extern "C" {
// malloc hook through the dynamic linker: counts every call made while counting is on.
void* malloc(std::size_t n) {
  using Fn = void* (*)(std::size_t);
  static Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "malloc"));
  if (counting) ++allocations;
  return real(n);
}
}

using namespace tristream;
using namespace tristream::testing;

TEST_CASE("open, size and render allocate nothing") {
  for (core::Method method : {core::Method::bilinear, core::Method::zienkiewicz}) {
    Triangulation layered;
    layered.width = 50;
    layered.height = 40;
    layered.space = ColorSpace::ycbcr;
    for (int c = 0; c < 3; ++c) layered.layers.push_back(random_lattice_mesh(50, 40, 80, 9 + c, 10));
    for (const Triangulation& tri :
         {single_mesh(random_lattice_mesh(50, 40, 100, 3, 20, 3), 50, 40, ColorSpace::rgb), layered}) {
      const std::vector<std::uint8_t> bytes = pack_blob(tri, method);
      std::vector<std::uint8_t> tile(32 * 32 * 4), work(64 * 1024);
      long tiles = 0;
      allocations = 0;
      counting = true;
      core::Blob blob;
      core::Status s = core::open_blob(bytes.data(), bytes.size(), &blob);
      core::RenderParams p;
      p.tile_width = p.tile_height = 16;
      p.format = core::PixelFormat::rgb565_be;
      p.dither = true;
      std::size_t need = 0;
      if (s == core::Status::ok) s = core::workspace_size(blob, p, &need);
      if (s == core::Status::ok)
        s = core::render(
            blob, p, tile.data(), tile.size(), work.data(), work.size(),
            [](void* c, const core::Tile*) { ++*static_cast<long*>(c); }, &tiles);
      counting = false;
      REQUIRE(s == core::Status::ok);
      CHECK(tiles == 4 * 3);
      CHECK(allocations == 0);
    }
  }
  // The counters work: an allocation while counting is seen.
  allocations = 0;
  counting = true;
  std::vector<int>* v = new std::vector<int>(100);
  counting = false;
  delete v;
  CHECK(allocations >= 2);
}
