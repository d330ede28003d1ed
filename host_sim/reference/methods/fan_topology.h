#pragma once
// The adjacency of a mesh for the natural and voronoi renderers, built from vertex fans kept
// contiguous: the same Topology as model/topology.h's build_topology() for every mesh whose
// undirected edges are each shared by at most two triangles (what the reader guarantees, and
// what every triangulation has), in about half the time at 13,000 vertices, because matching
// an edge reads only the fan's own packed entries instead of each fan triangle's vertices.
#include "model/topology.h"
#include "model/triangulation.h"

namespace tristream {

// vertex_start and vertex_triangles exactly as build_topology() (each fan in increasing
// triangle order); neighbour[3 * t + e]: the other triangle with the edge {v[e], v[e + 1]},
// in either winding, or no_neighbour.
Topology build_fan_topology(const Mesh& mesh);

}  // namespace tristream
