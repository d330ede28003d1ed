// SPDX-License-Identifier: MIT
// The v1 blob's CRC-32 (blob.h): the CRC itself against known values and a bit-at-a-time
// reference; every single-bit flip of whole blobs refused by ts_open with its status and offset;
// a blob of version 1 (packed before the checksum) refused with TS_BAD_VERSION and a host message
// that says what to do.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <string>

#include "../support/blob_seal.h"
#include "common/errors.h"
#include "core_bridge/unpack.h"
#include "core_support.h"
#include "crc32.h"
#include "io/atomic_file.h"
#include "io/tri_file.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

// CRC-32/ISO-HDLC one bit at a time, from its definition (reflected polynomial 0xEDB88320).
std::uint32_t crc_by_bits(const std::uint8_t* p, std::size_t n) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc & 1) ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
  }
  return ~crc;
}

std::uint32_t crc_of(const std::string& s) {
  return core::detail::crc32(0, reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
}

std::uint32_t get32(const std::vector<std::uint8_t>& b, std::size_t at) {
  return b[at] | b[at + 1] << 8 | b[at + 2] << 16 | std::uint32_t(b[at + 3]) << 24;
}

ts_status open(const std::vector<std::uint8_t>& bytes, std::uint32_t* offset) {
  std::vector<std::uint8_t> exact(bytes);  // exactly sized: ASan sees any read past the end
  ts_blob blob;
  *offset = 0xFFFFFFFFu;
  return ts_open(exact.data(), exact.size(), &blob, offset);
}

// Small blobs of every shape: grey and RGB, both methods, one mesh and three layers.
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> small_blobs() {
  Triangulation layered;
  layered.width = 20;
  layered.height = 14;
  layered.space = ColorSpace::ycbcr;
  for (int c = 0; c < 3; ++c) {
    layered.layers.push_back(random_subpixel_mesh(20, 14, 8 + 3 * c, 40 + std::uint32_t(c), true, 1));
    layered.layers.back().name = std::string(1, "ybr"[c]);
  }
  const Triangulation grey = single_mesh(random_subpixel_mesh(24, 16, 14, 7, true, 1), 24, 16);
  const Triangulation rgb = single_mesh(random_subpixel_mesh(24, 16, 12, 8, true, 3), 24, 16, ColorSpace::rgb);
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> out;
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    const std::string method = m == core::Method::bilinear ? " bilinear" : " zienkiewicz";
    out.push_back({"grey" + method, pack_blob(grey, m)});
    out.push_back({"rgb" + method, pack_blob(rgb, m)});
    out.push_back({"ycbcr layers" + method, pack_blob(layered, m)});
  }
  return out;
}

}  // namespace

TEST_CASE("the CRC is CRC-32/ISO-HDLC") {
  CHECK(crc_of("") == 0u);
  CHECK(crc_of("123456789") == 0xCBF43926u);  // the catalogue's check value
  CHECK(crc_of("a") == 0xE8B7BE43u);
  CHECK(crc_of("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
  // Any length and alignment, and continued in pieces, as the bit-at-a-time definition.
  std::mt19937 rng(11);
  std::vector<std::uint8_t> data(600);
  for (auto& b : data) b = std::uint8_t(rng());
  for (std::size_t start = 0; start < 8; ++start)
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(5),
                          std::size_t(63), std::size_t(64), std::size_t(65), std::size_t(591)}) {
      INFO("start " << start << ", " << n << " bytes");
      const std::uint32_t want = crc_by_bits(data.data() + start, n);
      CHECK(core::detail::crc32(0, data.data() + start, n) == want);
      const std::size_t half = n / 3;
      CHECK(core::detail::crc32(core::detail::crc32(0, data.data() + start, half), data.data() + start + half,
                                n - half) == want);
    }
}

TEST_CASE("a packed blob records the CRC-32 of its bytes but the checksum field") {
  for (const auto& [name, b] : small_blobs()) {
    INFO(name);
    REQUIRE(get32(b, 4) == 0x00400000u + core::blob_version);  // version 2, header size 64
    std::vector<std::uint8_t> rest(b.begin(), b.begin() + 36);
    rest.insert(rest.end(), b.begin() + 40, b.end());
    CHECK(get32(b, core::blob_checksum_offset) == crc_by_bits(rest.data(), rest.size()));
    for (std::size_t k = 40; k < core::blob_header_size; ++k) CHECK(b[k] == 0);
  }
}

TEST_CASE("ts_open refuses every single-bit flip of a blob, with its status and offset") {
  for (const auto& [name, good] : small_blobs()) {
    INFO(name << ", " << good.size() << " bytes");
    std::uint32_t at = 0;
    REQUIRE(open(good, &at) == TS_OK);
    const std::uint32_t total = get32(good, 8);
    int refused = 0, bits = 0;
    for (std::size_t byte = 0; byte < good.size(); ++byte)
      for (int bit = 0; bit < 8; ++bit) {
        std::vector<std::uint8_t> b(good);
        b[byte] ^= std::uint8_t(1u << bit);
        const ts_status s = open(b, &at);
        ++bits;
        refused += s != TS_OK;
        if (byte < 4) {
          if (s != TS_BAD_MAGIC || at != 0)
            FAIL_CHECK("bit " << bit << " of byte " << byte << ": " << s << " at " << at);
        } else if (byte < 6) {
          if (s != TS_BAD_VERSION || at != 4)
            FAIL_CHECK("bit " << bit << " of byte " << byte << ": " << s << " at " << at);
        } else if (byte < 8) {
          if (s != TS_BAD_HEADER || at != 6)
            FAIL_CHECK("bit " << bit << " of byte " << byte << ": " << s << " at " << at);
        } else if (byte < 12) {
          // The total size: beyond the bytes given (truncated), or a shorter range whose CRC differs.
          const bool longer = get32(b, 8) > total;
          if (longer ? (s != TS_TRUNCATED || at != 8) : (s != TS_BAD_CHECKSUM || at != 36))
            FAIL_CHECK("bit " << bit << " of byte " << byte << ": " << s << " at " << at);
        } else if (s != TS_BAD_CHECKSUM || at != core::blob_checksum_offset) {
          FAIL_CHECK("bit " << bit << " of byte " << byte << ": " << s << " at " << at);
        }
      }
    CHECK(refused == bits);
  }
}

TEST_CASE("damage of random bytes and runs is refused as a checksum mismatch") {
  const auto good = pack_blob(single_mesh(random_subpixel_mesh(60, 40, 120, 5, true, 3), 60, 40, ColorSpace::rgb),
                              core::Method::zienkiewicz);
  std::mt19937 rng(17);
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<std::uint8_t> b(good);
    // A run of up to 8 bytes anywhere past the total-size field, each changed.
    const std::size_t start = 12 + rng() % (b.size() - 12), n = 1 + rng() % 8;
    for (std::size_t k = start; k < std::min(b.size(), start + n); ++k) b[k] ^= std::uint8_t(1 + rng() % 255);
    std::uint32_t at = 0;
    const ts_status s = open(b, &at);
    if (s != TS_BAD_CHECKSUM || at != core::blob_checksum_offset)
      FAIL_CHECK("trial " << trial << ": bytes " << start << " + " << n << ": " << s << " at " << at);
  }
}

TEST_CASE("a blob of version 1 (before the checksum) is refused with TS_BAD_VERSION, and the host says why") {
  // The golden grey blob as the packer wrote it before the checksum (version 1, bytes 36..39 zero).
  const std::string path = TRISTREAM_SOURCE_DIR "/tests/core/version1-grey-bilinear.bin";
  const std::string file = read_file(path);
  const std::vector<std::uint8_t> old(file.begin(), file.end());
  REQUIRE(old.size() > 64);
  REQUIRE(get32(old, 4) == 0x00400001u);
  std::uint32_t at = 0;
  CHECK(open(old, &at) == TS_BAD_VERSION);
  CHECK(at == 4);
  try {
    (void)unpack_blob(old, "old.bin");
    FAIL("a version 1 blob was read");
  } catch (const DataError& e) {
    CHECK(std::string(e.what()) ==
          "old.bin: byte 4: version 1 blob without checksum: pack it again with tripack (this core reads version 2)");
  }
  // Version 2 is version 1 with the checksum: the packer makes these bytes, the version and the
  // checksum changed, of the .tri the old blob was packed from.
  std::vector<std::uint8_t> now(old);
  now[4] = 2;
  REQUIRE(seal_blob(now.data(), now.size()));
  CHECK(open(now, &at) == TS_OK);
  CHECK(pack_blob(read_tri_file(TRISTREAM_SOURCE_DIR "/tests/golden/grey.tri"), core::Method::bilinear) == now);
}

TEST_CASE("the host's message for a checksum mismatch names the byte and both CRCs") {
  auto b = pack_blob(single_mesh(random_subpixel_mesh(24, 16, 14, 7, true, 1), 24, 16), core::Method::bilinear);
  const std::uint32_t recorded = get32(b, 36);
  b[100] ^= 4;
  char want[160];
  std::snprintf(want, sizeof want,
                "x.bin: byte 36: checksum mismatch: the blob is damaged (the header records CRC-32 0x%08X, bytes "
                "0..%zu have 0x%08X)",
                unsigned(recorded), b.size() - 1, unsigned(core::blob_checksum(b.data(), std::uint32_t(b.size()))));
  try {
    (void)open_blob_or_throw(b, "x.bin");
    FAIL("a damaged blob was opened");
  } catch (const DataError& e) {
    CHECK(std::string(e.what()) == want);
  }
}
