/* SPDX-License-Identifier: MIT */
#pragma once
// Zienkiewicz's cubic over each triangle (thesis §3.2, Eq. 3.3 as restored in docs/CONVENTIONS.md),
// from vertex values and the vertex gradients of reference/gradients.h.
#include <array>

#include "reference/gradients.h"
#include "reference/render.h"

namespace tristream {

// The nine coefficients u1..u9 of Eq. 3.3 for triangle (A, B, C) = (v0, v1, v2).
struct ZienkiewiczCoefficients {
  std::array<double, 9> u{};
};

ZienkiewiczCoefficients zienkiewicz_coefficients(const Point& a, const Point& b, const Point& c, double ai,
                                                 double bi, double ci, const Gradient& ga, const Gradient& gb,
                                                 const Gradient& gc);

// f(a, b, c) of Eq. 3.3 at barycentric coordinates (la, lb, lc).
double zienkiewicz_value(const ZienkiewiczCoefficients& k, double la, double lb, double lc);

void render_zienkiewicz(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options,
                        Field& out);

}  // namespace tristream
