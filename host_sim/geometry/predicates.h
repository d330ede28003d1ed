/* SPDX-License-Identifier: MIT */
#pragma once
// Exact geometric predicates on double coordinates: a floating-point filter, then an exact
// fallback in expansion arithmetic (Shewchuk, "Adaptive precision floating-point arithmetic
// and fast robust geometric predicates", 1997).
//
// Exactness: the SIGN of each result is exact whenever no intermediate product overflows or
// underflows. That is guaranteed when every coordinate is zero or has a magnitude in
// [2^-200, 2^200] (about [6e-61, 1.6e60]); integer pixel coordinates are far inside. The
// magnitude of a non-zero result is only an approximation.
#include "model/triangulation.h"

namespace tristream {

// Twice the signed area of triangle abc: (b - a) x (c - a). Positive when c lies to the
// left of a->b in a y-up frame, which in the y-down image frame is clockwise on screen;
// this is the winding of Mesh triangles (Mesh::normalize_winding). Zero iff collinear.
double orient2d(const Point& a, const Point& b, const Point& c);

// Positive when d lies strictly inside the circle through a, b, c and orient2d(a, b, c) > 0
// (the Mesh winding); negative when d is strictly outside that circle. The sign flips when
// orient2d(a, b, c) < 0. Zero iff a, b, c, d are cocircular (or a, b, c collinear and d on
// their line).
double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace tristream
