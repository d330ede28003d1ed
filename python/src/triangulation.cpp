// SPDX-License-Identifier: MIT
// Triangulation and Mesh: the host model with its vertices, values and triangles as numpy arrays.
// A Triangulation made from arrays is checked by the .tri reader itself: its text (format_tri) is
// parsed back (parse_tri), so it holds what a file could, with the same messages (their line
// numbers are those of tri.to_text()), and a missing triangle list becomes the Delaunay one.
#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "io/tri_file.h"
#include "model/triangulation.h"

namespace tristream::python {

namespace {

ColorSpace space_of(const std::string& name) {
  for (ColorSpace s : {ColorSpace::grey, ColorSpace::rgb, ColorSpace::ycbcr})
    if (to_string(s) == name) return s;
  throw py::value_error("space: expected grey|rgb|ycbcr, found '" + name + "'");
}

// The layer names a .tri file gives a layered triangulation's channels (docs/FORMAT.md).
const char* layer_name(ColorSpace space, int c) {
  static const char* const rgb[] = {"r", "g", "b"};
  static const char* const ycbcr[] = {"y", "cb", "cr"};
  return space == ColorSpace::ycbcr ? ycbcr[c] : rgb[c];
}

// A mesh of arrays: vertices (N, 2), values (N, C) or (N,), triangles (M, 3) or None.
Mesh mesh_from_arrays(const py::handle& vertices, const py::handle& values, const py::handle& triangles,
                      int value_count, const std::string& what) {
  Mesh mesh;
  mesh.value_count = value_count;
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  if (!v || v.ndim() != 2 || v.shape(1) != 2)
    throw py::value_error(what + ": expected vertices as an array of shape (N, 2) (x, y in pixels)");
  const auto n = std::size_t(v.shape(0));
  for (std::size_t i = 0; i < n; ++i) mesh.points.push_back(Point{v.at(i, 0), v.at(i, 1)});
  const auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  const bool flat = c && c.ndim() == 1 && value_count == 1;
  if (!c || !(flat || (c.ndim() == 2 && c.shape(1) == value_count)) || std::size_t(c.shape(0)) != n)
    throw py::value_error(what + ": expected values as an array of shape (" + std::to_string(n) + ", " +
                          std::to_string(value_count) + ") (one row per vertex)");
  mesh.values.assign(c.data(), c.data() + n * std::size_t(value_count));
  if (triangles.is_none()) return mesh;
  const auto t = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(triangles);
  if (!t || t.ndim() != 2 || t.shape(1) != 3)
    throw py::value_error(what +
                          ": expected triangles as an array of shape (M, 3) of vertex indices, or None "
                          "(the Delaunay triangulation)");
  for (py::ssize_t i = 0; i < t.shape(0); ++i) {
    Triangle tr;
    for (int k = 0; k < 3; ++k) {
      const std::int64_t index = t.at(i, k);
      if (index < 0 || std::size_t(index) >= n)
        throw py::value_error(what + ": triangle " + std::to_string(i) + " names vertex " + std::to_string(index) +
                              "; expected 0 to " + std::to_string(n) + " - 1");
      tr.v[std::size_t(k)] = std::uint32_t(index);
    }
    mesh.triangles.push_back(tr);
  }
  return mesh;
}

// The triangulation as the reader checks it: parse_tri of its own text.
Triangulation checked(const Triangulation& tri) { return parse_tri(format_tri(tri), "Triangulation"); }

Triangulation make_single(int width, int height, const std::string& space, const py::handle& vertices,
                          const py::handle& values, const py::handle& triangles, const py::handle& gradients) {
  Triangulation tri;
  tri.width = width;
  tri.height = height;
  tri.space = space_of(space);
  Mesh mesh = mesh_from_arrays(vertices, values, triangles, tri.channels(), "Triangulation");
  if (!gradients.is_none()) {
    const auto g = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(gradients);
    const std::size_t n = mesh.vertex_count(), per_vertex = 2 * std::size_t(tri.channels());
    if (!g || g.ndim() != 2 || std::size_t(g.shape(0)) != n || std::size_t(g.shape(1)) != per_vertex)
      throw py::value_error("Triangulation: expected gradients as an array of shape (" + std::to_string(n) + ", " +
                            std::to_string(per_vertex) + ") (gx, gy per value), or None (estimated)");
    mesh.gradients.assign(g.data(), g.data() + n * per_vertex);
  }
  tri.layers.push_back(std::move(mesh));
  return checked(tri);
}

Triangulation make_layered(int width, int height, const std::string& space, const py::sequence& layers) {
  Triangulation tri;
  tri.width = width;
  tri.height = height;
  tri.space = space_of(space);
  if (tri.channels() != 3 || layers.size() != 3)
    throw py::value_error("layers: expected three layers (one per channel) of an rgb or ycbcr triangulation");
  for (int c = 0; c < 3; ++c) {
    const py::sequence layer = layers[std::size_t(c)].cast<py::sequence>();
    if (layer.size() != 2 && layer.size() != 3)
      throw py::value_error("layers[" + std::to_string(c) +
                            "]: expected (vertices, values) or (vertices, values, triangles)");
    Mesh m = mesh_from_arrays(layer[0], layer[1], layer.size() == 3 ? py::handle(layer[2]) : py::handle(py::none()), 1,
                              "layers[" + std::to_string(c) + "]");
    m.name = layer_name(tri.space, c);
    tri.layers.push_back(std::move(m));
  }
  return checked(tri);
}

py::array_t<double> vertices_of(const Mesh& m) {
  py::array_t<double> out({py::ssize_t(m.points.size()), py::ssize_t(2)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < m.points.size(); ++i)
    o(py::ssize_t(i), 0) = m.points[i].x, o(py::ssize_t(i), 1) = m.points[i].y;
  return out;
}

py::array_t<double> values_of(const Mesh& m) {
  py::array_t<double> out({py::ssize_t(m.points.size()), py::ssize_t(m.value_count)});
  std::copy(m.values.begin(), m.values.end(), out.mutable_data());
  return out;
}

py::array_t<std::uint32_t> triangles_of(const Mesh& m) {
  py::array_t<std::uint32_t> out({py::ssize_t(m.triangles.size()), py::ssize_t(3)});
  std::uint32_t* o = out.mutable_data();
  for (const Triangle& t : m.triangles) o = std::copy(t.v.begin(), t.v.end(), o);
  return out;
}

// None when the mesh stores no gradients (zienkiewicz and clough-tocher then estimate them).
py::object gradients_of(const Mesh& m) {
  if (!m.has_gradients()) return py::none();
  py::array_t<double> out({py::ssize_t(m.points.size()), py::ssize_t(2 * m.value_count)});
  std::copy(m.gradients.begin(), m.gradients.end(), out.mutable_data());
  return out;
}

// The one mesh of a triangulation that is not layered.
const Mesh& single_mesh(const Triangulation& tri) {
  if (tri.layered())
    throw py::value_error(
        "a layered triangulation has one mesh per channel: use tri.layers[c].vertices, .values, "
        ".triangles");
  return tri.layers.at(0);
}

void bind_mesh(py::module_& m) {
  py::class_<Mesh>(m, "Mesh", "One triangulated point set with its vertex values (a layer of a layered triangulation).")
      .def_readonly("name", &Mesh::name, "The layer's name (r g b, y cb cr), empty for a single mesh")
      .def_property_readonly("vertices", &vertices_of, "float64 (N, 2): x, y in pixels (y down)")
      .def_property_readonly("values", &values_of, "float64 (N, C): each vertex's values, 0 to 255")
      .def_property_readonly("triangles", &triangles_of, "uint32 (M, 3): vertex indices, clockwise on screen")
      .def_property_readonly("gradients", &gradients_of,
                             "float64 (N, 2C): each vertex's gradient per value (gx, gy in values per pixel), as "
                             "encode(method='zienkiewicz'|'clough-tocher') fits them; None when the mesh has none")
      .def("__repr__", [](const Mesh& mesh) {
        return "<tristream.Mesh '" + mesh.name + "': " + std::to_string(mesh.vertex_count()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles>";
      });
}

}  // namespace

void bind_triangulation(py::module_& m) {
  bind_mesh(m);
  py::class_<Triangulation>(m, "Triangulation",
                            "A triangulation-represented image (docs/FORMAT.md): size, colour space and one mesh, or "
                            "one mesh per channel (layered).")
      .def(py::init(&make_single), py::arg("width"), py::arg("height"), py::arg("space"), py::arg("vertices"),
           py::arg("values"), py::arg("triangles") = py::none(), py::kw_only(), py::arg("gradients") = py::none(),
           "From arrays: vertices (N, 2), values (N, C) for C channels of `space` (grey, rgb, ycbcr), triangles "
           "(M, 3) or None for the Delaunay triangulation, gradients (N, 2C: gx, gy per value, for zienkiewicz and "
           "clough-tocher) or None to estimate them. Checked as the .tri reader checks a file.")
      .def_static("from_layers", &make_layered, py::arg("width"), py::arg("height"), py::arg("space"),
                  py::arg("layers"),
                  "A layered triangulation: three (vertices, values[, triangles]) of one value per vertex.")
      .def_static("from_text", &parse_tri, py::arg("text"), py::arg("name") = "text", "Parses .tri text.")
      .def("to_text", &format_tri, "The .tri text (write_tri writes it).")
      .def_readonly("width", &Triangulation::width)
      .def_readonly("height", &Triangulation::height)
      .def_property_readonly("space", [](const Triangulation& t) { return std::string(to_string(t.space)); })
      .def_property_readonly("channels", &Triangulation::channels)
      .def_property_readonly("layered", &Triangulation::layered)
      .def_readonly("layers", &Triangulation::layers, "The meshes: one, or one per channel when layered")
      .def_property_readonly(
          "vertices", [](const Triangulation& t) { return vertices_of(single_mesh(t)); },
          "float64 (N, 2) of the single mesh")
      .def_property_readonly(
          "values", [](const Triangulation& t) { return values_of(single_mesh(t)); },
          "float64 (N, C) of the single mesh")
      .def_property_readonly(
          "triangles", [](const Triangulation& t) { return triangles_of(single_mesh(t)); },
          "uint32 (M, 3) of the single mesh")
      .def("__eq__", [](const Triangulation& a, const Triangulation& b) { return format_tri(a) == format_tri(b); })
      .def("__repr__", [](const Triangulation& t) {
        std::size_t vertices = 0, triangles = 0;
        for (const Mesh& mesh : t.layers) vertices += mesh.vertex_count(), triangles += mesh.triangles.size();
        return "<tristream.Triangulation " + std::to_string(t.width) + "x" + std::to_string(t.height) + " " +
               std::string(to_string(t.space)) + (t.layered() ? " layered" : "") + ": " + std::to_string(vertices) +
               " vertices, " + std::to_string(triangles) + " triangles>";
      });
}

}  // namespace tristream::python
