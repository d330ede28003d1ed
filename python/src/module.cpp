// SPDX-License-Identifier: MIT
// The Python module `tristream`: the host library's encoder, renderers, files, blobs and metrics,
// with the host's errors (common/errors.h) as Python exceptions of the same message.
#include "bindings.h"
#include "common/errors.h"
#include "tristream/version.h"

PYBIND11_MODULE(tristream, m) {
  namespace py = pybind11;
  using namespace tristream;
  m.doc() = "tristream: images as triangulations. encode, render, read_tri, write_tri, pack, unpack, mse, psnr, ssim.";
  m.attr("__version__") = TRISTREAM_VERSION;
  // Bad options and bad data are ValueErrors, files that cannot be read or written OSErrors.
  py::register_exception<UsageError>(m, "UsageError", PyExc_ValueError);
  py::register_exception<DataError>(m, "DataError", PyExc_ValueError);
  py::register_exception<InputError>(m, "InputError", PyExc_OSError);
  py::register_exception<OutputError>(m, "OutputError", PyExc_OSError);
  python::bind_triangulation(m);
  python::bind_io(m);
  python::bind_encode(m);
  python::bind_render(m);
  python::bind_metrics(m);
}
