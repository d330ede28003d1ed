/* SPDX-License-Identifier: MIT */
#pragma once
// Linear interpolation over each triangle (thesis §3.1, "bilinear" in its terms).
#include "reference/render.h"

namespace tristream {

void render_bilinear(const Mesh& mesh, int domain_width, int domain_height, const RenderOptions& options, Field& out);

}  // namespace tristream
