// SPDX-License-Identifier: MIT
#include "reference/methods/patch/control.h"

namespace tristream {
namespace {

// The vertex of neighbour triangle n that is not on its shared edge with (a, b).
std::uint32_t apex(const Mesh& mesh, std::uint32_t n, std::uint32_t a, std::uint32_t b) {
  for (std::uint32_t v : mesh.triangles[n].v)
    if (v != a && v != b) return v;
  return mesh.triangles[n].v[0];  // unreachable for a valid topology
}

}  // namespace

bool patch_control(const Mesh& mesh, const Topology& topo, std::uint32_t t, const PixelMapping& map,
                   PatchControl& out) {
  const auto& v = mesh.triangles[t].v;
  const std::uint32_t n_ab = topo.neighbour[3 * t + 0];
  const std::uint32_t n_bc = topo.neighbour[3 * t + 1];
  const std::uint32_t n_ca = topo.neighbour[3 * t + 2];
  if (n_ab == no_neighbour || n_bc == no_neighbour || n_ca == no_neighbour) return false;
  const std::array<std::uint32_t, 6> vertex{apex(mesh, n_ca, v[2], v[0]), apex(mesh, n_ab, v[0], v[1]),
                                            apex(mesh, n_bc, v[1], v[2]), v[0], v[1], v[2]};
  out.channels = mesh.value_count;
  out.value.resize(6 * std::size_t(out.channels));
  for (int k = 0; k < 6; ++k) {
    const Point& p = mesh.points[vertex[k]];
    out.domain[k] = p;
    out.pixel[k] = {p.x / map.sx, p.y / map.sy};
    for (int c = 0; c < out.channels; ++c) out.value[k * out.channels + c] = mesh.value(vertex[k], c);
  }
  return true;
}

}  // namespace tristream
