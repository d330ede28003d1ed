// SPDX-License-Identifier: MIT
// Validation of large meshes of awkward shapes is near-linear (issue 17 item 5). CTest gives this
// test a TIMEOUT that a quadratic check (the fan below has 200,000 triangles whose bounding boxes
// all overlap) could not meet. TRISTREAM_SCALE_TRIANGLES sets the fan's size (default 200000);
// each case prints its time.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/tri_file.h"

using namespace tristream;

namespace {

long fan_size() {
  const char* s = std::getenv("TRISTREAM_SCALE_TRIANGLES");
  return s ? std::strtol(s, nullptr, 10) : 200000;
}

double seconds_to_parse(const std::string& text, Triangulation& out) {
  const auto t0 = std::chrono::steady_clock::now();
  out = parse_tri(text, "scale.tri");
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// `n` rim points on the border of a 65535 x 65535 image, walked around, and one triangle from the
// centre to each pair of neighbours: every triangle meets every other at the centre.
std::string fan(long n) {
  const double side = 65534;
  const double perimeter = 4 * side, step = perimeter / double(n);
  std::string text =
      "tri 1\nsize 65535 65535\nchannels grey\nvertices " + std::to_string(n + 1) + "\n32767 32767 128\n";
  char line[96];
  for (long i = 0; i < n; ++i) {
    const double d = double(i) * step;
    double x, y;
    if (d < side) x = d, y = 0;
    else if (d < 2 * side) x = side, y = d - side;
    else if (d < 3 * side) x = 3 * side - d, y = side;
    else x = 0, y = 4 * side - d;
    std::snprintf(line, sizeof line, "%.17g %.17g %ld\n", x, y, i % 256);
    text += line;
  }
  text += "triangles " + std::to_string(n) + "\n";
  for (long i = 0; i < n; ++i) text += "0 " + std::to_string(1 + i) + " " + std::to_string(1 + (i + 1) % n) + "\n";
  return text;
}

}  // namespace

TEST_CASE("a large fan validates in near-linear time") {
  const long n = fan_size();
  Triangulation tri;
  const double s = seconds_to_parse(fan(n), tri);
  std::printf("fan of %ld triangles: read and validated in %.2f s\n", n, s);
  CHECK(tri.layers.at(0).triangles.size() == std::size_t(n));
}

TEST_CASE("100,000 vertices on one x validate in near-linear time") {
  // x = 0, y = 0, 0.5, 1, ..., and an apex; once as a fan, once through the Delaunay triangulation.
  constexpr long n = 100000;
  for (bool explicit_triangles : {true, false}) {
    std::string text = "tri 1\nsize 2000 60000\nchannels grey\nvertices " + std::to_string(n + 1) + "\n1000 25000 9\n";
    for (long i = 0; i < n; ++i) text += "0 " + std::to_string(i / 2) + (i % 2 ? ".5" : "") + " 1\n";
    if (explicit_triangles) {
      text += "triangles " + std::to_string(n - 1) + "\n";
      for (long i = 1; i < n; ++i) text += "0 " + std::to_string(i) + " " + std::to_string(i + 1) + "\n";
    }
    Triangulation tri;
    const double s = seconds_to_parse(text, tri);
    std::printf("%ld vertices on x = 0 (%s): read and validated in %.2f s\n", n,
                explicit_triangles ? "fan" : "Delaunay", s);
    CHECK(tri.layers.at(0).triangles.size() == std::size_t(n - 1));
  }
}
