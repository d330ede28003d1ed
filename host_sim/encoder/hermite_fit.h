/* SPDX-License-Identifier: MIT */
#pragma once
// Least-squares values and gradients for the methods that interpolate vertex values and vertex
// gradients (Zienkiewicz's cubic, Clough-Tocher): for fixed positions and triangles, the values and
// gradients that minimise the squared error of that method's interpolant over every pixel of the
// domain. Both interpolants are linear in the data (three values and three gradients a
// triangle), so the fit is a sparse linear least-squares problem; its basis is taken from the
// reference renderers themselves (reference/methods/), so the fit minimises exactly what the
// reference and the core draw.
#include <cstdint>

#include "encoder/planes.h"
#include "model/triangulation.h"

namespace tristream::encoder {

enum class HermiteMethod : std::uint8_t { zienkiewicz, clough_tocher };

struct HermiteFitOptions {
  HermiteMethod method = HermiteMethod::zienkiewicz;
  // Gradients are rounded to multiples of 2^-(12 - step_bits) values per pixel: the core stores
  // them with 12 fraction bits, and the compressed stream codes them in units of this step
  // (docs/COMPRESSED_BLOB.md). 0 keeps all 12 bits. 9 (1/8 value per pixel) cost 0.002 dB on
  // grey boat and 0.008 dB on colour kodim23 at 1 % vertices (10: 0.013 and 0.032; 11: 0.026 and
  // 0.11); the compressed stream then spends 9 bits less per component than for step 0.
  int gradient_step_bits = 9;
  // Weight of the pull of each gradient towards the surface estimate (reference/gradients.h),
  // relative to the gradient's own diagonal term: it keeps the system positive definite whatever
  // the mesh. Small, because a gradient's data term can be a thousand times weaker than its
  // diagonal once the neighbouring values are free (1e-3 moved a fit of linear data by up to
  // 0.6 per pixel); 1e-6 and 1e-4 give boat and airplane at 1 % the same PSNR within 0.001 dB.
  double regularisation = 1e-6;
};

struct HermiteFitReport {
  int iterations = 0;   // conjugate-gradient iterations of both solves, summed over channels
  double residual = 0;  // worst relative residual |b - Ax| / |b| reached
};

// Replaces mesh.values (rounded to integers in [0, 255]) and sets mesh.gradients (rounded to the
// step, within +-32767 values per pixel, the core's range). Vertices must be pixel positions and
// the triangles, positively oriented, must tile [0, W-1] x [0, H-1] of `target`. Values and
// gradients are first fitted together, then the values rounded and the gradients fitted again
// to them. Deterministic.
HermiteFitReport fit_hermite(Mesh& mesh, const Planes& target, const HermiteFitOptions& options = {});

// Sum over every pixel and channel of the squared error of the method's interpolant of `mesh`
// (values and gradients as stored; estimated gradients when the mesh has none) against `target`,
// unrounded and unclamped.
double hermite_squared_error(const Mesh& mesh, const Planes& target, HermiteMethod method);

}  // namespace tristream::encoder
