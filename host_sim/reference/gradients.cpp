// SPDX-License-Identifier: MIT
#include "reference/gradients.h"

#include <cmath>

namespace tristream {

std::vector<Gradient> vertex_gradients(const Mesh& mesh, const Topology& topo, int value_index) {
  if (!mesh.has_gradients()) return estimated_vertex_gradients(mesh, topo, value_index);
  std::vector<Gradient> out(mesh.vertex_count());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = {mesh.gradient(v, value_index, 0), mesh.gradient(v, value_index, 1)};
  return out;
}

std::vector<Gradient> estimated_vertex_gradients(const Mesh& mesh, const Topology& topo, int value_index) {
  const std::size_t nv = mesh.vertex_count();
  std::vector<Gradient> out(nv);
  // Unit normal of each triangle in (x, y, I) space, oriented so n_I > 0 (Mesh winding
  // makes the doubled area, which is n_I, positive), and the triangle's area.
  struct Normal {
    double x, y, i, area;
  };
  std::vector<Normal> normals(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const Point& a = mesh.points[v[0]];
    const Point& b = mesh.points[v[1]];
    const Point& c = mesh.points[v[2]];
    const double ai = mesh.value(v[0], value_index);
    const double ux = b.x - a.x, uy = b.y - a.y, ui = mesh.value(v[1], value_index) - ai;
    const double wx = c.x - a.x, wy = c.y - a.y, wi = mesh.value(v[2], value_index) - ai;
    const double nx = uy * wi - ui * wy;
    const double ny = ui * wx - ux * wi;
    const double ni = ux * wy - uy * wx;
    const double len = std::sqrt(nx * nx + ny * ny + ni * ni);
    normals[t] = {nx / len, ny / len, ni / len, 0.5 * ni};
  }
  for (std::size_t v = 0; v < nv; ++v) {
    double sx = 0, sy = 0, si = 0;
    for (std::uint32_t k = topo.vertex_start[v]; k < topo.vertex_start[v + 1]; ++k) {
      const Normal& n = normals[topo.vertex_triangles[k]];
      sx += n.area * n.x;
      sy += n.area * n.y;
      si += n.area * n.i;
    }
    if (si > 0) out[v] = {-sx / si, -sy / si};
  }
  return out;
}

}  // namespace tristream
