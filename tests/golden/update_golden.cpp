// SPDX-License-Identifier: MIT
// update_golden: the explicit update command of the golden images. Repacks every golden blob
// from its .tri file and re-renders every case into its PNG (tests/golden/README.md).
#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "core_bridge/pack.h"
#include "golden_cases.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/tri_file.h"

using namespace tristream;

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : TRISTREAM_SOURCE_DIR "/tests/golden";
  try {
    std::set<std::string> packed;
    for (const golden::Case& c : golden::cases()) {
      const std::string blob_path = dir + "/" + golden::blob_name(c);
      if (packed.insert(blob_path).second) {
        const Triangulation tri = read_tri_file(dir + "/" + c.tri + ".tri");
        const auto blob = pack_blob(tri, parse_core_method(c.method), c.tri);
        write_file_atomically(blob_path, std::string_view(reinterpret_cast<const char*>(blob.data()), blob.size()));
        std::printf("%s: %zu bytes\n", blob_path.c_str(), blob.size());
      }
      const std::string blob_text = read_file(blob_path);
      golden::Pixels px;
      const core::Status s =
          golden::render(c, std::vector<std::uint8_t>(blob_text.begin(), blob_text.end()), &px);
      if (s != core::Status::ok) {
        std::fprintf(stderr, "update_golden: %s: %s\n", c.name, core::status_text(s));
        return 70;
      }
      Image img(px.width, px.height, px.channels);
      img.pixels = px.data;
      write_png(dir + "/" + c.name + ".png", img);
      std::printf("%s/%s.png: %dx%d\n", dir.c_str(), c.name, px.width, px.height);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "update_golden: %s\n", e.what());
    return 1;
  }
  return 0;
}
