// SPDX-License-Identifier: MIT
#include "model/triangulation.h"

#include <utility>

namespace tristream {

int channel_count(ColorSpace space) { return space == ColorSpace::grey ? 1 : 3; }

std::string_view to_string(ColorSpace space) {
  switch (space) {
    case ColorSpace::grey: return "grey";
    case ColorSpace::rgb: return "rgb";
    case ColorSpace::ycbcr: return "ycbcr";
  }
  return "?";
}

double Mesh::doubled_area(std::size_t t) const {
  const Point& a = points[triangles[t].v[0]];
  const Point& b = points[triangles[t].v[1]];
  const Point& c = points[triangles[t].v[2]];
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

std::vector<std::uint32_t> Mesh::used_vertices() const {
  std::vector<char> used(vertex_count(), 0);
  for (const Triangle& t : triangles)
    for (std::uint32_t v : t.v) used[v] = 1;
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < vertex_count(); ++v)
    if (used[v]) order.push_back(v);
  return order;
}

void Mesh::normalize_winding() {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (doubled_area(t) < 0) std::swap(triangles[t].v[1], triangles[t].v[2]);
}

}  // namespace tristream
