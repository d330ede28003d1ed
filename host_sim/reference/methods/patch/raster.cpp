// SPDX-License-Identifier: MIT
#include "reference/methods/patch/raster.h"

#include "model/topology.h"
#include "reference/methods/bilinear.h"

namespace tristream::detail {

PatchCanvas::PatchCanvas(Field& field)
    : field_(field),
      inside_(std::size_t(field.width) * field.height, 0),
      count_(std::size_t(field.width) * field.height, 0) {
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    bool covered = field.channels > 0;
    for (int c = 0; c < field.channels; ++c) covered = covered && !std::isnan(field.v[p * field.channels + c]);
    inside_[p] = covered ? 1 : 0;
  }
}

void PatchCanvas::resolve_thesis() {
  const int nc = field_.channels;
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    if (count_[p] == 0) continue;  // the pre-fill as it is (and no pixel outside the domain counts)
    const double n = double(count_[p]) + 1.0;
    for (int c = 0; c < nc; ++c) field_.v[p * nc + c] /= n;
  }
}

void PatchCanvas::resolve_exact() {
  const int nc = field_.channels;
  for (std::size_t p = 0; p < inside_.size(); ++p) {
    if (count_[p] < 2) continue;  // the pre-fill, or the one patch value as it is
    const double n = double(count_[p]);
    for (int c = 0; c < nc; ++c) field_.v[p * nc + c] /= n;
  }
}

std::vector<std::uint32_t> triangles_by_cell(const Mesh& mesh) {
  static constexpr double cell_units = 16;
  static constexpr double max_cells = 4096;  // per side; points beyond share the last cell
  double x_max = 0, y_max = 0;
  for (const Point& p : mesh.points) x_max = std::max(x_max, p.x), y_max = std::max(y_max, p.y);
  auto index = [](double v) { return std::size_t(std::clamp(v / cell_units, 0.0, max_cells)); };  // NaN: 0
  const std::size_t columns = index(x_max) + 1, rows = index(y_max) + 1;
  auto cell = [&](std::uint32_t t) {
    const Point& p = mesh.points[mesh.triangles[t].v[0]];
    return std::min(rows - 1, index(p.y)) * columns + std::min(columns - 1, index(p.x));
  };
  std::vector<std::uint32_t> start(columns * rows + 1, 0), order(mesh.triangles.size());
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) ++start[cell(t) + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) order[start[cell(t)]++] = t;
  return order;
}

void bilinear_prefill(const Mesh& mesh, const Topology& topo, const std::vector<std::uint32_t>& order,
                      int domain_width, int domain_height, const RenderOptions& options, Field& out) {
  bool exact = out.width == domain_width && out.height == domain_height && options.fit_n == options.fit_d;
  for (std::size_t v = 0; v < mesh.vertex_count() && exact; ++v) {
    const double x = mesh.points[v].x * patch_subpixel_scale, y = mesh.points[v].y * patch_subpixel_scale;
    exact = std::fabs(mesh.points[v].x) <= max_patch_coordinate &&
            std::fabs(mesh.points[v].y) <= max_patch_coordinate && x == std::floor(x) && y == std::floor(y);
  }
  if (!exact) {
    render_bilinear(mesh, domain_width, domain_height, options, out);
    return;
  }
  const int nc = mesh.value_count;
  for (std::uint32_t t : order) {
    const auto& v = mesh.triangles[t].v;
    // Parameters (s, t) = barycentric coordinates of v[0] and v[1].
    MicroVertex a, b, c;
    snap(mesh.points[v[0]].x, mesh.points[v[0]].y, 1, 0, a);
    snap(mesh.points[v[1]].x, mesh.points[v[1]].y, 0, 1, b);
    snap(mesh.points[v[2]].x, mesh.points[v[2]].y, 0, 0, c);
    unsigned inclusive = 0;
    for (int e = 0; e < 3; ++e)
      if (topo.is_boundary_edge(t, e)) inclusive |= 1u << e;
    const double* q0 = &mesh.values[std::size_t(v[0]) * nc];
    const double* q1 = &mesh.values[std::size_t(v[1]) * nc];
    const double* q2 = &mesh.values[std::size_t(v[2]) * nc];
    double* field = out.v.data();
    const std::size_t width = std::size_t(out.width), stride = std::size_t(out.channels);
    rasterize_micro_triangle(
        a, b, c, out.width, out.height,
        [&](int i, int j, double l0, double l1) {
          double* o = field + (std::size_t(j) * width + i) * stride;
          const double l2 = 1 - l0 - l1;
          for (int ch = 0; ch < nc; ++ch) o[ch] = l0 * q0[ch] + l1 * q1[ch] + l2 * q2[ch];
        },
        inclusive);
  }
}

}  // namespace tristream::detail
