// SPDX-License-Identifier: MIT
// mse, psnr, ssim: metrics/metrics.h on two arrays of one shape (trisim metrics' figures).
#include <pybind11/stl.h>

#include <string>

#include "bindings.h"
#include "metrics/metrics.h"

namespace tristream::python {

namespace {

struct Pair {
  Image a, b;
};

// Both images, of one shape (the metrics' DataError names the sizes otherwise).
Pair images(const py::handle& a, const py::handle& b) { return {image_from_array(a, "a"), image_from_array(b, "b")}; }

SsimOptions ssim_options(const std::string& window) {
  SsimOptions o;
  o.window = one_of("window", window, {"gaussian", "8x8"}) == "8x8" ? SsimWindow::uniform8 : SsimWindow::gaussian11;
  return o;
}

}  // namespace

void bind_metrics(py::module_& m) {
  m.def(
      "mse",
      [](const py::handle& a, const py::handle& b) {
        const Pair p = images(a, b);
        return mse(p.a, p.b);
      },
      py::arg("a"), py::arg("b"), "Mean squared difference over every pixel and channel (8-bit images).");
  m.def(
      "psnr",
      [](const py::handle& a, const py::handle& b) {
        const Pair p = images(a, b);
        return psnr(p.a, p.b);
      },
      py::arg("a"), py::arg("b"), "10 log10(255^2 / mse) in dB; inf for identical images.");
  m.def(
      "ssim",
      [](const py::handle& a, const py::handle& b, const std::string& window) {
        const Pair p = images(a, b);
        const SsimOptions o = ssim_options(window);
        py::gil_scoped_release release;
        return ssim(p.a, p.b, o);
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("window") = "gaussian",
      "Mean SSIM (Wang et al. 2004; window 'gaussian' 11x11 sigma 1.5, or the thesis's '8x8'); colour: the mean "
      "of the channels.");
  m.def(
      "metrics",
      [](const py::handle& a, const py::handle& b, const std::string& window) {
        const Pair p = images(a, b);
        const SsimOptions o = ssim_options(window);
        Metrics r;
        {
          py::gil_scoped_release release;
          r = compare_images(p.a, p.b, o);
        }
        py::dict d;
        d["mse"] = r.mse, d["psnr"] = r.psnr, d["ssim"] = r.ssim;
        return d;
      },
      py::arg("a"), py::arg("b"), py::kw_only(), py::arg("window") = "gaussian",
      "The three at once, as trisim metrics prints them: {'mse', 'psnr', 'ssim'}.");
}

}  // namespace tristream::python
