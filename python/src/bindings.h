/* SPDX-License-Identifier: MIT */
#pragma once
// The Python module's parts, one per concept (module.cpp calls each bind_* once), and the
// conversions between numpy arrays and the host model that they share (arrays.cpp).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "model/color.h"
#include "model/image.h"
#include "reference/render.h"

namespace tristream::python {

namespace py = pybind11;

void bind_triangulation(py::module_& m);  // triangulation.cpp: Triangulation, Mesh
void bind_io(py::module_& m);             // io.cpp: read_tri, write_tri, read_image, write_png, pack, unpack
void bind_encode(py::module_& m);         // encode.cpp: encode
void bind_render(py::module_& m);         // render.cpp: render
void bind_metrics(py::module_& m);        // metrics.cpp: mse, psnr, ssim, metrics

// An 8-bit image of an array of shape (H, W) or (H, W, 1) (grey) or (H, W, 3) (RGB). uint8 arrays
// are taken as they are; integer and float arrays when every value is an integer in 0..255 (the
// encoder and the metrics work on 8-bit images). Throws ValueError naming `what` otherwise.
Image image_from_array(const py::handle& array, const std::string& what);
// (H, W) uint8 for one channel, (H, W, C) otherwise.
py::array_t<std::uint8_t> array_from_image(const Image& image);
// The reference's doubles (H, W) or (H, W, 3): YCbCr converted to RGB, unclamped, unrounded, NaN
// outside the domain.
py::array_t<double> array_from_field(const Field& field, ColorSpace space);

// One value for every channel, or (R, G, B), each 0..255. Throws ValueError naming `what` otherwise.
Background background_from(const py::handle& value, const std::string& what);

// A keyword's text value that must be one of `names`; throws ValueError "<keyword>: expected a|b, found 'x'".
std::string one_of(const std::string& keyword, const std::string& value, std::initializer_list<const char*> names);

}  // namespace tristream::python
