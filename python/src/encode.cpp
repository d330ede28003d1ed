// SPDX-License-Identifier: MIT
// encode: an image array to a triangulation, as triencode makes it (encoder/encoder.h, and for a
// byte budget encoder/blob_budget.h), with triencode's options as keywords.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.h"
#include "core_bridge/pack.h"
#include "encoder/blob_budget.h"
#include "encoder/encoder.h"
#include "encoder/panel.h"
#include "reference/fit_names.h"

namespace tristream::python {

namespace {

// triencode's options, as keywords (None: not given).
struct EncodeArgs {
  std::optional<long long> vertices, max_bytes;
  std::optional<double> error, sigma;
  std::string method, blob, color, space, cotri, values, rank, fit, name;
  bool grey = false;
  std::optional<int> relocate, flips, gradient_step;
  std::optional<int> width, height;
};

// The keywords' rules (triencode's usage errors, named by keyword).
void check_keywords(const EncodeArgs& a, bool grey) {
  if (a.max_bytes) {
    if (a.vertices || a.error)
      throw py::value_error("max_bytes: chooses the vertex count itself; give it without vertices and error");
    if (*a.max_bytes < 1)
      throw py::value_error("max_bytes: expected at least 1, found " + std::to_string(*a.max_bytes));
  } else if (!a.vertices && !a.error) {
    throw py::value_error("give vertices=N, error=E or max_bytes=B");
  }
  if (a.vertices && *a.vertices < 4)
    throw py::value_error("vertices: expected at least 4 (the corners), found " + std::to_string(*a.vertices));
  if (a.error && !(*a.error > 0 && *a.error <= 255))
    throw py::value_error("error: expected a number above 0, at most 255");
  if (a.sigma && !(*a.sigma >= 0 && *a.sigma <= 10)) throw py::value_error("sigma: expected a number in 0..10");
  if (a.relocate && (*a.relocate < 0 || *a.relocate > 100)) throw py::value_error("relocate: expected 0 to 100");
  if (a.flips && (*a.flips < 0 || *a.flips > 100)) throw py::value_error("flips: expected 0 to 100");
  if (bool(a.width) != bool(a.height))
    throw py::value_error("width, height: give the panel's width and height together");
  if (a.width && (*a.width < 2 || *a.height < 2 || *a.width > 65535 || *a.height > 65535))
    throw py::value_error("width, height: expected 2 to 65535 pixels a side");
  if (grey && (a.color != "co" || a.space != "rgb" || a.cotri != "greedy"))
    throw py::value_error("color, space, cotri: apply to colour encodings only (not a grey image or grey=True)");
  if (a.color == "separate" && a.cotri != "greedy") throw py::value_error("cotri: applies to color='co' only");
  if (a.values == "pixel" && a.relocate) throw py::value_error("relocate: applies to values='lsq' only");
  if (a.values == "pixel" && a.flips) throw py::value_error("flips: applies to values='lsq' only");
  if (a.values == "pixel" && a.method != "bilinear")
    throw py::value_error("method: " + a.method + " fits its values and gradients by least squares (values='lsq')");
  if (a.gradient_step && a.method == "bilinear")
    throw py::value_error("gradient_step: applies to method='zienkiewicz' or 'clough-tocher' only");
  if (a.gradient_step && (*a.gradient_step < 0 || *a.gradient_step > 12))
    throw py::value_error("gradient_step: expected 0 to 12");
  if (a.max_bytes && a.method == "clough-tocher")
    throw py::value_error("method: the core does not draw clough-tocher, so there is no blob for max_bytes");
}

EncodeOptions options_of(const EncodeArgs& a) {
  EncodeOptions o;
  o.vertices = a.vertices ? std::size_t(*a.vertices) : 0;
  o.max_rms = a.error.value_or(0);
  o.color = one_of("color", a.color, {"co", "separate"}) == "co" ? ColorMode::co : ColorMode::separate;
  o.space = one_of("space", a.space, {"rgb", "ycbcr"}) == "rgb" ? ColorSpace::rgb : ColorSpace::ycbcr;
  o.grey = a.grey;
  o.cotri = one_of("cotri", a.cotri, {"greedy", "thesis"}) == "greedy" ? CotriMethod::greedy : CotriMethod::thesis;
  o.fit = one_of("values", a.values, {"pixel", "lsq"}) == "pixel" ? VertexFit::pixel : VertexFit::lsq;
  o.rank_by_total_error = one_of("rank", a.rank, {"total", "worst"}) == "total";
  o.smoothing_sigma = a.sigma.value_or(-1);
  if (a.relocate) o.relocate_passes = *a.relocate;
  if (a.flips) o.flip_rounds = *a.flips;
  o.method = parse_fit_method(a.method);
  if (a.gradient_step) o.gradient_step_bits = *a.gradient_step;
  return o;
}

Triangulation encode_array(const py::handle& array, const EncodeArgs& a) {
  const Image image = image_from_array(array, a.name);
  one_of("method", a.method, {"bilinear", "zienkiewicz", "clough-tocher"});
  EncodeOptions o = options_of(a);
  one_of("blob", a.blob, {"compressed", "v1"});
  const std::optional<Fit> fit = find_fit(a.fit);
  if (!fit) throw py::value_error("fit: expected stretch|inside|fill, found '" + a.fit + "'");
  check_keywords(a, a.grey || image.channels == 1);
  py::gil_scoped_release release;
  check_encodable(image, a.name);
  const PanelPicture panel = picture_for_panel(image, a.width.value_or(0), a.height.value_or(0), *fit, a.name);
  if (!a.max_bytes) return on_panel(encode(panel.picture, o, a.name).triangulation, panel);
  BlobBudget budget;
  budget.max_bytes = std::size_t(*a.max_bytes);
  budget.method = parse_core_method(a.method);
  budget.compressed = a.blob == "compressed";
  budget.option = "max_bytes";
  return encode_to_budget(panel, o, budget, a.name).tri;
}

}  // namespace

void bind_encode(py::module_& m) {
  m.def(
      "encode",
      [](const py::handle& image, std::optional<long long> vertices, std::optional<long long> max_bytes,
         std::optional<double> error, const std::string& method, const std::string& blob, bool grey,
         const std::string& color, const std::string& space, const std::string& cotri, const std::string& values,
         const std::string& rank, std::optional<double> sigma, std::optional<int> relocate, std::optional<int> flips,
         std::optional<int> gradient_step, std::optional<int> width, std::optional<int> height, const std::string& fit,
         const std::string& name) {
        const EncodeArgs a{vertices, max_bytes, error, sigma, method,   blob,  color,         space, cotri, values,
                           rank,     fit,       name,  grey,  relocate, flips, gradient_step, width, height};
        return encode_array(image, a);
      },
      py::arg("image"), py::arg("vertices") = py::none(), py::kw_only(), py::arg("max_bytes") = py::none(),
      py::arg("error") = py::none(), py::arg("method") = "bilinear", py::arg("blob") = "compressed",
      py::arg("grey") = false, py::arg("color") = "co", py::arg("space") = "rgb", py::arg("cotri") = "greedy",
      py::arg("values") = "lsq", py::arg("rank") = "total", py::arg("sigma") = py::none(),
      py::arg("relocate") = py::none(), py::arg("flips") = py::none(), py::arg("gradient_step") = py::none(),
      py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("fit") = "stretch",
      py::arg("name") = "image",
      "Encodes an image (uint8 (H, W) or (H, W, 3)) as triencode does with the same options: vertices=N (-n), "
      "error=E (-e) or max_bytes=B (--max-bytes, with blob=), and method (-m: the values, and gradients for "
      "zienkiewicz and clough-tocher, fitted for it), gradient_step, grey, color, space, cotri, values, "
      "rank, sigma, relocate, flips, width, height, fit. `name` starts the messages of errors in the data.");
}

}  // namespace tristream::python
