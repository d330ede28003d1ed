/* SPDX-License-Identifier: MIT */
#pragma once
// The six control points shared by the Bezier and Coons patches of a triangle (docs/CONVENTIONS.md):
// for triangle (A, B, C) = (v0, v1, v2), P110 = A, P011 = B, P101 = C and the corners are
// the apexes of the edge neighbours: P200 across CA, P020 across AB, P002 across BC.
#include <array>
#include <cstdint>
#include <vector>

#include "model/topology.h"
#include "model/triangulation.h"
#include "reference/coverage.h"

namespace tristream {

enum PatchPoint : int { p200 = 0, p020 = 1, p002 = 2, p110 = 3, p011 = 4, p101 = 5 };

struct PatchControl {
  std::array<Point, 6> domain;  // in the triangulation's units
  std::array<Point, 6> pixel;   // in output pixels (domain / PixelMapping scale)
  int channels = 0;
  std::vector<double> value;  // value[k * channels + c] of control point k
};

// Fills `out` for triangle t. False when t has fewer than three edge neighbours (a border
// triangle, thesis §4.2: it has no patch).
bool patch_control(const Mesh& mesh, const Topology& topo, std::uint32_t t, const PixelMapping& map,
                   PatchControl& out);

}  // namespace tristream
