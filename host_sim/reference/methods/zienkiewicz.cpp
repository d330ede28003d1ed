// SPDX-License-Identifier: MIT
#include "reference/methods/zienkiewicz.h"

#include <vector>

#include "reference/coverage.h"

namespace tristream {

ZienkiewiczCoefficients zienkiewicz_coefficients(const Point& a, const Point& b, const Point& c, double ai,
                                                 double bi, double ci, const Gradient& ga, const Gradient& gb,
                                                 const Gradient& gc) {
  const double abx = b.x - a.x, aby = b.y - a.y;
  const double bcx = c.x - b.x, bcy = c.y - b.y;
  const double cax = a.x - c.x, cay = a.y - c.y;
  return {{ai, abx * ga.gx + aby * ga.gy, abx * gb.gx + aby * gb.gy,  //
           bi, bcx * gb.gx + bcy * gb.gy, bcx * gc.gx + bcy * gc.gy,  //
           ci, cax * gc.gx + cay * gc.gy, cax * ga.gx + cay * ga.gy}};
}

double zienkiewicz_value(const ZienkiewiczCoefficients& k, double a, double b, double c) {
  const auto& u = k.u;
  const double k1 = 2 * a * b * c;
  const double k2 = a * b * c / 2;
  return u[0] * (a * a * (3 - 2 * a) + k1) + u[1] * (a * a * b + k2) - u[2] * (a * b * b + k2) +
         u[3] * (b * b * (3 - 2 * b) + k1) + u[4] * (b * b * c + k2) - u[5] * (b * c * c + k2) +
         u[6] * (c * c * (3 - 2 * c) + k1) + u[7] * (c * c * a + k2) - u[8] * (c * a * a + k2);
}

void render_zienkiewicz(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  const Topology topo = build_topology(mesh);
  const PixelMapping map(domain_width, domain_height, out.width, out.height, options.fit_n, options.fit_d);
  const int nc = mesh.value_count;
  std::vector<std::vector<Gradient>> gradients;
  for (int c = 0; c < nc; ++c) gradients.push_back(vertex_gradients(mesh, topo, c));

  std::vector<ZienkiewiczCoefficients> k(nc);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    for (int c = 0; c < nc; ++c)
      k[c] = zienkiewicz_coefficients(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.value(v[0], c),
                                      mesh.value(v[1], c), mesh.value(v[2], c), gradients[c][v[0]],
                                      gradients[c][v[1]], gradients[c][v[2]]);
    for_each_owned_pixel(mesh, topo, t, map, [&](int i, int j, double l0, double l1, double l2) {
      for (int c = 0; c < nc; ++c) out.at(i, j, c) = zienkiewicz_value(k[c], l0, l1, l2);
    });
  }
}

}  // namespace tristream
