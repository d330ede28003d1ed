// SPDX-License-Identifier: MIT
#include "reference/methods/bilinear.h"

#include "reference/coverage.h"

namespace tristream {

void render_bilinear(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  const Topology topo = build_topology(mesh);
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const int nc = mesh.value_count;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    for_each_owned_pixel(mesh, topo, t, map, [&](int i, int j, double l0, double l1, double l2) {
      for (int c = 0; c < nc; ++c)
        out.at(i, j, c) = l0 * mesh.value(v[0], c) + l1 * mesh.value(v[1], c) + l2 * mesh.value(v[2], c);
    });
  }
}

}  // namespace tristream
