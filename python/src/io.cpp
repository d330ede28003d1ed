// SPDX-License-Identifier: MIT
// Files and blobs: .tri files, images, and the core's blobs as bytes (what tripack writes to x.bin).
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "bindings.h"
#include "core_bridge/compress.h"
#include "core_bridge/pack.h"
#include "core_bridge/unpack.h"
#include "io/image_io.h"
#include "io/tri_file.h"

namespace tristream::python {

namespace {

py::bytes bytes_of(const std::vector<std::uint8_t>& v) {
  return py::bytes(reinterpret_cast<const char*>(v.data()), v.size());
}

// tripack's blob of `tri`: v1, or with `compress` the compressed blob (tripack --compress).
py::bytes pack(const Triangulation& tri, const std::string& method, bool compress) {
  const core::Method m = parse_core_method(method);
  std::vector<std::uint8_t> blob;
  {
    py::gil_scoped_release release;
    blob = pack_blob(tri, m, "triangulation");
    if (compress) blob = compress_blob(blob, "triangulation");
  }
  return bytes_of(blob);
}

Triangulation unpack(const py::bytes& data, const std::string& name) {
  const std::string_view view = data;
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(view.data()), view.size());
  return unpack_blob(bytes, name).tri;
}

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "read_tri", [](const std::filesystem::path& path) { return read_tri_file(path.string()); }, py::arg("path"),
      "Reads a .tri file (docs/FORMAT.md). InputError (an OSError) when it cannot be read, DataError (a "
      "ValueError) naming the line when it is malformed.");
  m.def(
      "write_tri",
      [](const std::filesystem::path& path, const Triangulation& tri) { write_tri_file(path.string(), tri); },
      py::arg("path"), py::arg("tri"), "Writes a .tri file (through a temporary file and a rename).");
  m.def(
      "read_image", [](const std::filesystem::path& path) { return array_from_image(read_image(path.string())); },
      py::arg("path"),
      "Reads a PNG, JPEG, BMP or PNM as uint8 (H, W) for grey or (H, W, 3) for colour (alpha dropped).");
  m.def(
      "write_png",
      [](const std::filesystem::path& path, const py::handle& image) {
        write_png(path.string(), image_from_array(image, "image"));
      },
      py::arg("path"), py::arg("image"), "Writes an 8-bit image as PNG.");
  m.def("pack", &pack, py::arg("tri"), py::arg("method") = "bilinear", py::arg("compress") = false,
        "The blob the core draws (tripack -o x.bin): for method bilinear or zienkiewicz, the compressed blob with "
        "compress=True (tripack --compress).");
  m.def("unpack", &unpack, py::arg("blob"), py::arg("name") = "blob",
        "The mesh a blob (v1 or compressed) draws, read back (trisim's reference render of a blob).");
}

}  // namespace tristream::python
