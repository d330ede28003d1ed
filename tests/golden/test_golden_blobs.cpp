// SPDX-License-Identifier: MIT
// The golden blobs are what the packer makes of the golden .tri files today (so the golden
// test cannot silently run on stale blobs).
#include <catch2/catch.hpp>

#include "core_bridge/pack.h"
#include "golden_cases.h"
#include "io/atomic_file.h"
#include "io/tri_file.h"

using namespace tristream;

TEST_CASE("golden blobs match the packer's output") {
  const std::string dir = TRISTREAM_SOURCE_DIR "/tests/golden";
  for (const golden::Case& c : golden::cases()) {
    INFO(golden::blob_name(c));
    const auto blob = pack_blob(read_tri_file(dir + "/" + c.tri + ".tri"), parse_core_method(c.method), c.tri);
    const std::string stored = read_file(dir + "/" + golden::blob_name(c));
    CHECK(std::string(blob.begin(), blob.end()) == stored);
  }
}
