/* SPDX-License-Identifier: MIT */
#pragma once
// Circumcentres of triangles in double precision (no exact arithmetic: callers that decide
// with them, such as incircle tests, use geometry/predicates.h instead). Both forms are finite
// whenever the three points are not collinear; they round differently, and each caller keeps
// the one its results were made with.
#include "model/triangulation.h"

namespace tristream {

// The circumcentre of (a, b, c), formed relative to a and added back.
inline Point circumcentre(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double r = 0.5 / (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) * r, a.y + (bx * c2 - cx * b2) * r};
}

// The circumcentre of (o, a, b) minus o: the offset from o, without the final addition (the
// Sibson weights need offsets from the query point).
[[gnu::always_inline]] inline Point circumcentre_from(const Point& o, const Point& a, const Point& b) {
  const double ax = a.x - o.x, ay = a.y - o.y;
  const double bx = b.x - o.x, by = b.y - o.y;
  const double r = 0.5 / (ax * by - ay * bx);
  const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
  return {(by * a2 - ay * b2) * r, (ax * b2 - bx * a2) * r};
}

}  // namespace tristream
