/* SPDX-License-Identifier: MIT */
#pragma once
// Least-squares vertex values: for fixed positions and triangles, the values that minimise
// the squared error of the linear interpolant over every pixel of the domain.
#include "encoder/planes.h"
#include "model/triangulation.h"

namespace tristream::encoder {

struct LeastSquaresReport {
  int iterations = 0;      // conjugate-gradient iterations of the last channel
  double residual = 0;     // relative residual |b - Ax| / |b| reached, worst channel
};

// Replaces mesh.values by the least-squares fit to `target` (same channel count), each
// clamped to [0, 255] and, with `round_values`, rounded to an integer (8-bit values). Vertices must be pixel
// positions and the triangles must tile the rectangle [0, W-1] x [0, H-1] of `target`.
// Solves the normal equations (a sparse sampled mass matrix, positive definite because every
// vertex is itself a pixel) by Jacobi-preconditioned conjugate gradients, starting from the
// current values.
LeastSquaresReport fit_least_squares(Mesh& mesh, const Planes& target, bool round_values = true);

// Sum over every pixel and channel of the squared error of the linear interpolant of `mesh`
// against `target` (no rounding, no clamping).
double linear_squared_error(const Mesh& mesh, const Planes& target);

}  // namespace tristream::encoder
