/* SPDX-License-Identifier: MIT */
#pragma once
// Clough-Tocher interpolation: a C1 piecewise cubic over the split of each triangle at its
// centroid S into three micro-triangles (V_k, V_k+1, S), each a cubic Bezier triangle. A
// modern comparison point; the thesis does not have it.
//
// Data: vertex values and the vertex gradients of reference/gradients.h (the same as
// zienkiewicz). Ordinates of micro-triangle (V_i, V_j, S), indexed by the powers of
// (lambda_i, lambda_j, lambda_S):
//   300 = f_i, 210 = f_i + g_i.(V_j - V_i)/3, 201 = p_i = f_i + g_i.(S - V_i)/3,
//   111 = e_ij (below), 102 = q_i = (p_i + e_ij + e_ki)/3, 003 = f_S = (q_0 + q_1 + q_2)/3,
// and symmetrically for j. q_i and f_S are the C1 conditions across the inner edges V_i-S.
// Cross-boundary derivative: along each outer edge the derivative normal to the edge is the
// linear interpolation of the normal derivatives of the end gradients, g_i.n and g_j.n. Both
// triangles of an edge compute it from the same data, so the interpolant is C1 across edges;
// along an edge it is the cubic Hermite curve of the end values and tangential derivatives.
// With d = S - M (M the edge midpoint), e = V_j - V_i, g = (g_i + g_j)/2, the derivative along
// d at M must be D = g.d + 1.5 (d.e / |e|^2) ((f_j - f_i) - g.e), which gives
//   e_ij = (b210 + b120)/2 + (2D - g.d)/3.
// Properties (tests): vertex values interpolated; linear data reproduced (the gradients are
// exact for it); quadratics reproduced when the gradients are exact; C1 everywhere.
#include <array>

#include "reference/gradients.h"
#include "reference/render.h"

namespace tristream {

// The ten Bezier ordinates of each of the three cubic pieces of one triangle; piece k lies
// on (V_k, V_k+1, S), ordinates ordered 300, 030, 003, 210, 120, 201, 021, 102, 012, 111 in
// powers of (lambda_k, lambda_k+1, lambda_S).
struct CloughTocherTriangle {
  std::array<std::array<double, 10>, 3> piece{};
};

CloughTocherTriangle clough_tocher_triangle(const std::array<Point, 3>& vertex, const std::array<double, 3>& value,
                                            const std::array<Gradient, 3>& gradient);

// Value at barycentric coordinates (l0, l1, l2) of the triangle (any real point: the piece
// is chosen by the smallest coordinate, and extends polynomially outside).
double clough_tocher_value(const CloughTocherTriangle& ct, double l0, double l1, double l2);

void render_clough_tocher(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                          Field& out);

}  // namespace tristream
