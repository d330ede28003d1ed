// SPDX-License-Identifier: MIT
// Fuzz target of the mesh check (geometry/mesh_check.h): points on a 16 x 16 lattice (many
// collinear and touching cases) and triangles from the input's bytes; find_mesh_defect must
// agree with the brute force of every pair (tests/support/mesh_brute_force.h).
// Bytes: 0 the point count (3..34); then a byte per point (x = low 4 bits, y = high 4 bits,
// duplicates dropped); then 3 bytes per triangle (indices modulo the point count).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "../support/mesh_brute_force.h"
#include "geometry/mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tristream;
  if (size < 1) return 0;
  const std::size_t n = 3 + data[0] % 32;
  if (size < 1 + n) return 0;
  std::vector<Point> points;
  std::vector<char> taken(256, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t b = data[1 + i];
    if (taken[b]) continue;
    taken[b] = 1;
    points.push_back(Point{double(b & 15), double(b >> 4)});
  }
  if (points.size() < 3) return 0;
  std::vector<Triangle> triangles;
  for (std::size_t k = 1 + n; k + 3 <= size && triangles.size() < 64; k += 3) {
    Triangle t;
    for (int j = 0; j < 3; ++j) t.v[j] = std::uint32_t(data[k + j] % points.size());
    if (t.v[0] != t.v[1] && t.v[1] != t.v[2] && t.v[0] != t.v[2]) triangles.push_back(t);
  }
  triangles = testing::positive(points, triangles);
  const bool expected = testing::brute_force_defect(points, triangles);
  if (find_mesh_defect(points, triangles).has_value() != expected) {
    std::fprintf(stderr, "fuzz_mesh_check: the sweep says %s, the brute force %s\n", expected ? "valid" : "defect",
                 expected ? "defect" : "valid");
    std::abort();
  }
  return 0;
}
