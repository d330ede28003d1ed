// SPDX-License-Identifier: MIT
#include "reference/domain.h"

#include <algorithm>
#include <cmath>

#include "geometry/predicates.h"

namespace tristream {

bool is_locally_delaunay(const Mesh& mesh, const Topology& topo) {
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (topo.vertex_start[v] == topo.vertex_start[v + 1]) return false;  // in no triangle
  // Integer coordinates in [0, 4096]: incircle's determinant (relative to d, as in
  // geometry/predicates.cpp) has no rounding (differences <= 2^12, each of its three terms
  // below 2^50), so its sign is the exact predicate's.
  bool small = true;
  for (const Point& q : mesh.points)
    small = small && q.x >= 0 && q.x <= 4096 && q.y >= 0 && q.y <= 4096 && q.x == std::uint32_t(q.x) &&
            q.y == std::uint32_t(q.y);
  auto inside = [small](const Point& a, const Point& b, const Point& c, const Point& d) {
    if (!small) return incircle(a, b, c, d) > 0;
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
    const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady) > 0;
  };
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t n = topo.neighbour[3 * t + e];
      if (n == no_neighbour || n < t) continue;  // each interior edge once
      std::uint32_t opposite = 0;
      for (std::uint32_t w : mesh.triangles[n].v)
        if (w != v[e] && w != v[(e + 1) % 3]) opposite = w;
      if (inside(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[opposite])) return false;
    }
  }
  return true;
}

std::vector<std::uint32_t> owning_triangles(const Mesh& mesh, const Topology& topo, const PixelMapping& map) {
  const int width = map.out_width;
  std::vector<std::uint32_t> owner(std::size_t(width) * map.out_height, no_neighbour);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t].v;
    const Point* corner[3] = {&mesh.points[v[0]], &mesh.points[v[1]], &mesh.points[v[2]]};
    // The same ownership rule as for_each_owned_pixel: inclusive[k][e] with k = 0 elsewhere,
    // 1 in column 0, 2 in row 0, 3 at pixel (0, 0).
    bool inclusive[4][3];
    for (int k = 0; k < 4; ++k)
      for (int e = 0; e < 3; ++e)
        inclusive[k][e] = topo.is_boundary_edge(t, e) ||
                          owns_edge_points(*corner[e], *corner[(e + 1) % 3], k & 1 ? 1 : -1, k & 2 ? 1 : -1);
    auto inside = [&](int i, int j) {
      const Point p = map.sample(i, j);
      const bool* incl = inclusive[(i == 0 ? 1 : 0) + (j == 0 ? 2 : 0)];
      for (int e = 0; e < 3; ++e) {
        const double o = orient2d(*corner[e], *corner[(e + 1) % 3], p);
        if (!(o > 0 || (o == 0 && incl[e]))) return false;
      }
      return true;
    };
    const double xmin = std::min({corner[0]->x, corner[1]->x, corner[2]->x});
    const double xmax = std::max({corner[0]->x, corner[1]->x, corner[2]->x});
    // Rows whose sample y lies in [ymin, ymax] (with a margin far above rounding).
    const double ymin = std::min({corner[0]->y, corner[1]->y, corner[2]->y});
    const double ymax = std::max({corner[0]->y, corner[1]->y, corner[2]->y});
    const int j0 = std::max(map.first_row(ymin), int(std::ceil(ymin / map.sy - 1e-7)));
    const int j1 = std::min(map.last_row(ymax), int(std::floor(ymax / map.sy + 1e-7)));
    // x = a.x + (y - a.y) * slope on each edge line; the kind of bound it gives.
    double slope[3];
    int kind[3];  // +1: upper bound on x, -1: lower bound, 0: horizontal edge
    for (int e = 0; e < 3; ++e) {
      const Point& a = *corner[e];
      const Point& b = *corner[(e + 1) % 3];
      const double dy = b.y - a.y;
      kind[e] = dy > 0 ? 1 : dy < 0 ? -1 : 0;
      slope[e] = dy != 0 ? (b.x - a.x) / dy : 0.0;
    }
    const double inv_sx = 1.0 / map.sx;
    // The estimates below are within about 1e-12 (domain units) of the exact edge lines, far
    // inside these margins (relative to the sample spacing).
    constexpr double near = 1e-7;
    const double near_x = near * map.sx;
    // Column 0 has its own tie rule, so it is tested alone; the span search runs over
    // columns >= 1, where all sample points share one rule and the owned set is an interval.
    const bool has_column0 = map.first_column(xmin) == 0;
    const int i_min = std::max(1, map.first_column(xmin)), i_max = map.last_column(xmax);
    for (int j = j0; j <= j1; ++j) {
      std::uint32_t* row = owner.data() + std::size_t(j) * width;
      if (has_column0 && inside(0, j)) row[0] = t;
      if (i_min > i_max) continue;
      // The row's span from the edge lines in floating point. The estimate is within 1e-9
      // pixel of the true ends, so only an end that close to a sample point (a sample point
      // on an edge or at a vertex) needs an exact test, of that one pixel.
      const double y = map.sample(0, j).y;
      const bool* incl = inclusive[j == 0 ? 2 : 0];
      double lo = xmin, hi = xmax;
      double bound[3] = {0, 0, 0};  // x of each sloped edge's line on this row
      bool empty = false;
      for (int e = 0; e < 3; ++e) {
        const Point& a = *corner[e];
        if (kind[e] != 0) {
          bound[e] = a.x + (y - a.y) * slope[e];
          if (kind[e] > 0) hi = std::min(hi, bound[e]);
          else lo = std::max(lo, bound[e]);
        } else {
          const Point& b = *corner[(e + 1) % 3];
          const double f = (b.x - a.x) * (y - a.y);  // exact sign: the row against a horizontal edge
          if (f < 0 || (f == 0 && !incl[e])) empty = true;
        }
      }
      if (empty) continue;
      // Whether column i (>= 1) of this row is owned: edges whose line is clearly away from
      // the sample point are decided by the estimate, the others by an exact orient2d.
      auto owned = [&](int i) {
        const Point p = map.sample(i, j);
        for (int e = 0; e < 3; ++e) {
          if (kind[e] == 0) continue;  // decided above for the whole row
          const double d = kind[e] > 0 ? bound[e] - p.x : p.x - bound[e];  // >= 0: inside
          if (d > near_x) continue;
          if (d < -near_x) return false;
          const double o = orient2d(*corner[e], *corner[(e + 1) % 3], p);
          if (!(o > 0 || (o == 0 && incl[e]))) return false;
        }
        return true;
      };
      // lo and hi lie in the bounding box, so the columns fit an int; ceil and floor by
      // truncation (std::ceil is a library call without SSE4.1).
      const double l = lo * inv_sx, h = hi * inv_sx;
      int cl = int(l), fh = int(h);
      cl += cl < l;
      fh -= fh > h;
      if (cl > fh + 2) continue;  // no candidate pixel
      int il = std::clamp(cl, i_min, i_max + 1);
      int ih = std::clamp(fh, i_min - 1, i_max);
      if (cl - l < near && il == cl && il <= i_max && !owned(il)) ++il;
      else if (l - (cl - 1) < near && il - 1 == cl - 1 && il - 1 >= i_min && owned(il - 1)) --il;
      if (h - fh < near && ih == fh && ih >= i_min && !owned(ih)) --ih;
      else if (fh + 1 - h < near && ih + 1 == fh + 1 && ih + 1 <= i_max && owned(ih + 1)) ++ih;
      if (il > ih) continue;
      std::fill(row + il, row + ih + 1, t);
    }
  }
  return owner;
}

namespace {

// Twice the area of a mesh's triangles, summed. Exact for coordinates on a fine enough
// binary grid (pixel positions, halves, ...).
double doubled_area(const Mesh& mesh) {
  double sum = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) sum += mesh.doubled_area(t);
  return sum;
}

}  // namespace

bool covers_rectangle(const Mesh& mesh, double xmax, double ymax) {
  int corners = 0;
  for (const Point& p : mesh.points) {
    if (p.x < 0 || p.x > xmax || p.y < 0 || p.y > ymax) return false;
    corners += (p.x == 0 || p.x == xmax) && (p.y == 0 || p.y == ymax);
  }
  return corners == 4 && doubled_area(mesh) == 2 * xmax * ymax;
}

}  // namespace tristream
