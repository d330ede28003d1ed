/* SPDX-License-Identifier: MIT */
#pragma once
// The host-side model of a triangulation-represented image (see docs/FORMAT.md).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tristream {

enum class ColorSpace : std::uint8_t { grey, rgb, ycbcr };

// 1 for grey, 3 for rgb and ycbcr.
int channel_count(ColorSpace space);
std::string_view to_string(ColorSpace space);

struct Point {
  double x = 0;
  double y = 0;
};

// Vertex indices of a triangle. After Mesh::normalize_winding() (the reader calls it),
// orient(p[v0], p[v1], p[v2]) > 0 with orient as in geometry: (b-a) x (c-a) in the
// y-down image frame, i.e. clockwise on screen.
struct Triangle {
  std::array<std::uint32_t, 3> v{};
};

// One triangulated point set with `value_count` values per vertex.
struct Mesh {
  std::string name;  // layer name; empty when the file has a single mesh
  int value_count = 1;
  std::vector<Point> points;
  std::vector<double> values;  // points.size() * value_count, each in [0, 255]
  // Vertex gradients for the methods that take them (zienkiewicz, clough-tocher): empty, and
  // they are estimated from the surface (reference/gradients.h), or points.size() * value_count
  // pairs (gx, gy) in value units per pixel, vertex by vertex and value by value (a .tri file's
  // `gradients` section; the encoder's fit for those methods, encoder/hermite_fit.h).
  std::vector<double> gradients;
  std::vector<Triangle> triangles;
  // Where the mesh was read from, for messages: each vertex's line in its .tri file (empty for a
  // mesh made otherwise, e.g. by the encoder), and whether the reader computed the triangles (a
  // file without them), so that triangle numbers are in no file.
  std::vector<std::uint32_t> vertex_lines;
  bool triangulated_by_reader = false;

  std::size_t vertex_count() const { return points.size(); }
  double value(std::size_t vertex, int c) const { return values[vertex * value_count + c]; }
  bool has_gradients() const { return !gradients.empty(); }
  // The stored gradient of value c at `vertex` (has_gradients() must hold): gx, then gy.
  double gradient(std::size_t vertex, int c, int axis) const {
    return gradients[(vertex * value_count + c) * 2 + axis];
  }
  // Signed doubled area (b-a) x (c-a) of triangle t.
  double doubled_area(std::size_t t) const;
  // Reorders vertex indices so that every triangle has positive doubled_area().
  void normalize_winding();
  // The vertices some triangle uses, in index order (a vertex no triangle uses is never drawn).
  std::vector<std::uint32_t> used_vertices() const;
};

// A whole image: size, colour space and either one mesh carrying every channel or, in a
// layered file, one single-valued mesh per channel (the thesis's separate triangulations).
struct Triangulation {
  int width = 0;
  int height = 0;
  ColorSpace space = ColorSpace::grey;
  std::vector<Mesh> layers;

  int channels() const { return channel_count(space); }
  bool layered() const { return layers.size() > 1; }
  // The mesh holding channel c and the value index of c inside it.
  const Mesh& mesh_of_channel(int c) const { return layered() ? layers[c] : layers[0]; }
  int value_index_of_channel(int c) const { return layered() ? 0 : c; }
};

}  // namespace tristream
