// SPDX-License-Identifier: MIT
// Golden images: every case rendered by the core must match its PNG in tests/golden bit for
// bit. A mismatch writes <name>.diff.png (changed pixels white on black) to the working
// directory. The same source runs on x86-64 and, cross-compiled, as a 32-bit ARM binary under
// qemu-arm (firmware_core/cross/run-golden-qemu.sh). Update: see tests/golden/README.md.
// Also built against a core with one pixel format, one method, one colour space and one mesh per
// blob (test_core_golden_config): there the cases it has must still match, and every other case
// must be refused with Status::not_compiled.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_THREAD_LOCALS  // bare-metal newlib (the qemu-arm run) has no thread pointer
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "golden_cases.h"

#ifndef TRISTREAM_GOLDEN_DIR
#define TRISTREAM_GOLDEN_DIR TRISTREAM_SOURCE_DIR "/tests/golden"
#endif

using namespace tristream;

namespace {

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::vector<std::uint8_t> bytes;
  if (FILE* f = std::fopen(path.c_str(), "rb")) {
    std::uint8_t buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.insert(bytes.end(), buf, buf + n);
    std::fclose(f);
  }
  return bytes;
}

}  // namespace

TEST_CASE("golden renders are unchanged") {
  const std::string dir = TRISTREAM_GOLDEN_DIR;
  for (const golden::Case& c : golden::cases()) {
    INFO("case " << c.name);
    const std::vector<std::uint8_t> blob = read_bytes(dir + "/" + golden::blob_name(c));
    REQUIRE(!blob.empty());
    golden::Pixels got;
    const bool bilinear = std::string(c.method) == "bilinear";
    core::Blob opened;
    REQUIRE(core::open_blob(blob.data(), blob.size(), &opened) == core::Status::ok);
    const bool compiled = (core::config::pixel_formats >> int(c.format) & 1) &&
                          (core::config::methods >> (bilinear ? 0 : 1) & 1) &&
                          (core::config::color_spaces >> int(opened.space) & 1) &&
                          (opened.layer_count == 1 || core::config::layered);
    if (!compiled) {
      CHECK(golden::render(c, blob, &got) == core::Status::not_compiled);
      continue;
    }
    REQUIRE(golden::render(c, blob, &got) == core::Status::ok);
    const std::vector<std::uint8_t> png = read_bytes(dir + "/" + c.name + ".png");
    REQUIRE(!png.empty());
    int w = 0, h = 0, n = 0;
    stbi_uc* want = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &n, got.channels);
    REQUIRE(want != nullptr);
    CHECK(w == got.width);
    CHECK(h == got.height);
    std::size_t changed = 0;
    std::vector<std::uint8_t> diff(std::size_t(got.width) * got.height, 0);
    if (w == got.width && h == got.height) {
      for (std::size_t i = 0; i < diff.size(); ++i)
        for (int k = 0; k < got.channels; ++k)
          if (want[i * got.channels + k] != got.data[i * got.channels + k]) diff[i] = 255;
      for (std::uint8_t d : diff) changed += d != 0;
    }
    stbi_image_free(want);
    if (changed) {
      const std::string out = std::string(c.name) + ".diff.png";
      stbi_write_png(out.c_str(), got.width, got.height, 1, diff.data(), got.width);
      WARN("changed pixels written to " << out);
    }
    CHECK(changed == 0);
  }
}
