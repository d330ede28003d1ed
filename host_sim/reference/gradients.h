/* SPDX-License-Identifier: MIT */
#pragma once
// Vertex gradients: the mesh's own (Mesh::gradients: a .tri file's `gradients` section, the
// encoder's fit for zienkiewicz or clough-tocher) when it has them, else estimated from the surface
// (x, y, value) as thesis Eq. 3.2 (docs/CONVENTIONS.md): the unit normals of the triangles around a
// vertex, weighted by their areas, summed; gradient = (-n_x / n_I, -n_y / n_I). Zienkiewicz and
// Clough-Tocher share them, and the packer stores them in fixed point for the core.
#include <vector>

#include "model/topology.h"
#include "model/triangulation.h"

namespace tristream {

struct Gradient {
  double gx = 0;
  double gy = 0;
};

// One gradient per vertex for value channel `value_index`: the stored ones, else the estimate, in
// which a vertex in no triangle gets 0.
std::vector<Gradient> vertex_gradients(const Mesh& mesh, const Topology& topo, int value_index);

// The estimate alone, whatever the mesh stores.
std::vector<Gradient> estimated_vertex_gradients(const Mesh& mesh, const Topology& topo, int value_index);

}  // namespace tristream
