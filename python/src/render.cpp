// SPDX-License-Identifier: MIT
// render: a triangulation (or a blob's bytes) to pixels with either engine, as trisim render draws
// it: the double-precision reference (reference/render.h) or the fixed-point core on the host
// (core_bridge/render_core.h), with trisim's options as keywords.
#include <pybind11/stl.h>

#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "bindings.h"
#include "common/name_list.h"
#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "core_bridge/render_core.h"
#include "core_bridge/unpack.h"
#include "io/limits.h"
#include "reference/fit_names.h"

namespace tristream::python {

namespace {

struct RenderArgs {
  std::optional<std::string> method, engine, format;
  int width = 0, height = 0;
  std::string fit, variant, dtype;
  Background background;
  std::optional<int> tile, tile_width, tile_height;
  std::optional<std::vector<int>> viewport;
  bool dither = false, raw = false;
};

// What is drawn: a triangulation, or a blob's bytes (v1 or compressed) with its header's facts.
struct Source {
  const Triangulation* tri = nullptr;
  std::span<const std::uint8_t> blob;
  core::Method blob_method = core::Method::bilinear;
  int width = 0, height = 0;
};

// Options that would be ignored are errors, as trisim's are.
void check_engine_keywords(const RenderArgs& a, const std::string& engine) {
  if (engine == "reference") {
    const bool core_only = a.tile || a.tile_width || a.tile_height || a.viewport || a.format || a.dither || a.raw;
    if (core_only)
      throw py::value_error(
          "tile, tile_width, tile_height, viewport, format, dither, raw: apply to engine='core' only");
    return;
  }
  if (!a.variant.empty()) throw py::value_error("variant: applies to engine='reference' only");
  if (a.dtype != "uint8")
    throw py::value_error("dtype: the core renders 8-bit pixels (dtype='float64' is the reference's)");
  const bool rgb565 = a.format && (*a.format == "rgb565le" || *a.format == "rgb565be");
  if (a.dither && !rgb565) throw py::value_error("dither: applies to format rgb565le and rgb565be only");
}

CoreOptions core_options_of(const RenderArgs& a, bool grey) {
  CoreOptions o;
  o.width = a.width;
  o.height = a.height;
  o.fit = core_fit(parse_fit(a.fit));
  if (a.viewport) {
    const std::vector<int>& v = *a.viewport;
    if (v.size() != 4 || v[0] < 0 || v[1] < 0 || v[2] <= v[0] || v[3] <= v[1])
      throw py::value_error(
          "viewport: expected (x0, y0, x1, y1) with 0 <= x0 < x1 and 0 <= y0 < y1 (output pixels "
          "[x0, x1) x [y0, y1))");
    o.viewport = core::Rect{v[0], v[1], v[2], v[3]};
  }
  o.tile_width = a.tile_width.value_or(a.tile.value_or(32));
  o.tile_height = a.tile_height.value_or(a.tile.value_or(32));
  o.format = a.format ? parse_pixel_format(*a.format) : grey ? core::PixelFormat::l8 : core::PixelFormat::rgb888;
  o.dither = a.dither;
  o.background = a.background;
  return o;
}

py::array core_render(const Source& s, const RenderArgs& a, const std::string& method, bool grey) {
  const CoreOptions o = core_options_of(a, grey);
  CoreFrame frame;
  {
    py::gil_scoped_release release;
    if (s.tri) {
      frame = render_core_frame(*s.tri, method, o, "triangulation");
    } else {
      CoreRenderer renderer(s.blob, o, "blob");
      renderer.render(frame);
    }
  }
  if (!a.raw) return array_from_image(frame_to_image(frame));
  const py::ssize_t bpp = core::bytes_per_pixel(frame.format);
  py::array_t<std::uint8_t> out({py::ssize_t(frame.height), py::ssize_t(frame.width), bpp});
  std::copy(frame.bytes.begin(), frame.bytes.end(), out.mutable_data());
  return out;
}

py::array reference_render(const Triangulation& tri, const RenderArgs& a, const std::string& method_name) {
  const MethodInfo* method = find_reference_method(method_name);
  if (!method)
    throw py::value_error("method: expected " + name_list(reference_methods(), "|", "|") + ", found '" + method_name +
                          "'");
  RenderOptions o;
  o.width = a.width;
  o.height = a.height;
  o.fit = parse_fit(a.fit);
  o.variant = a.variant;
  o.background = a.background;
  if (a.dtype == "float64") {
    Field field;
    {
      py::gil_scoped_release release;
      field = render_reference_field(tri, *method, o);
    }
    return array_from_field(field, tri.space);
  }
  Image image;
  {
    py::gil_scoped_release release;
    image = render_reference(tri, *method, o);
  }
  return array_from_image(image);
}

py::array render_source(const py::handle& source, RenderArgs& a) {
  one_of("dtype", a.dtype, {"uint8", "float64"});
  if (!find_fit(a.fit)) throw py::value_error("fit: expected stretch|inside|fill, found '" + a.fit + "'");
  if (a.width < 0 || a.height < 0) throw py::value_error("width, height: expected 0 (the triangulation's) or more");
  Source s;
  std::vector<std::uint8_t> v1;  // a blob's v1 form, for its header and its mesh
  std::optional<Triangulation> unpacked;
  if (py::isinstance<py::bytes>(source)) {
    const std::string_view view = source.cast<py::bytes>();
    s.blob = std::span(reinterpret_cast<const std::uint8_t*>(view.data()), view.size());
    v1 = v1_blob_bytes(s.blob, "blob");
    const core::Blob blob = open_blob_or_throw(v1, "blob");
    s.blob_method = blob.method, s.width = blob.width, s.height = blob.height;
  } else {
    s.tri = &source.cast<const Triangulation&>();
    s.width = s.tri->width, s.height = s.tri->height;
  }
  // A blob is drawn by the core with its own method unless engine= says otherwise (trisim's rule).
  const std::string engine = one_of("engine", a.engine.value_or(s.tri ? "reference" : "core"), {"reference", "core"});
  const std::string method = a.method.value_or(s.tri ? "bilinear" : std::string(to_string(s.blob_method)));
  if (!s.tri && engine == "core" && method != to_string(s.blob_method))
    throw py::value_error(
        "method " + method + ": the blob is packed for " + std::string(to_string(s.blob_method)) +
        ", which the core renders with that method only (engine='reference' renders its mesh with any)");
  check_engine_keywords(a, engine);
  const std::uint64_t w = a.width ? a.width : s.width, h = a.height ? a.height : s.height;
  if (w * h > limits::max_image_pixels)
    throw py::value_error("width, height: expected a render of at most " + std::to_string(limits::max_image_pixels) +
                          " pixels (the limit for a render), found " + std::to_string(w) + "x" + std::to_string(h));
  if (engine == "reference" && !s.tri) s.tri = &unpacked.emplace(unpack_blob(s.blob, "blob").tri);
  const bool grey = s.tri ? s.tri->channels() == 1 : false;
  if (engine == "core")
    return core_render(s, a, method, s.tri ? grey : open_blob_or_throw(v1, "blob").space == core::ColorSpace::grey);
  return reference_render(*s.tri, a, method);
}

}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "render",
      [](const py::handle& tri, std::optional<std::string> method, int width, int height,
         std::optional<std::string> engine, std::optional<std::string> format, const std::string& fit,
         const py::object& background, std::optional<int> tile, std::optional<int> tile_width,
         std::optional<int> tile_height, std::optional<std::vector<int>> viewport, bool dither,
         const std::string& variant, const std::string& dtype, bool raw) {
        RenderArgs a;
        a.method = method, a.engine = engine, a.format = format, a.width = width, a.height = height;
        a.fit = fit, a.variant = variant, a.dtype = dtype, a.background = background_from(background, "background");
        a.tile = tile, a.tile_width = tile_width, a.tile_height = tile_height, a.viewport = viewport;
        a.dither = dither, a.raw = raw;
        return render_source(tri, a);
      },
      py::arg("tri"), py::arg("method") = py::none(), py::kw_only(), py::arg("width") = 0, py::arg("height") = 0,
      py::arg("engine") = py::none(), py::arg("format") = py::none(), py::arg("fit") = "stretch",
      py::arg("background") = 0, py::arg("tile") = py::none(), py::arg("tile_width") = py::none(),
      py::arg("tile_height") = py::none(), py::arg("viewport") = py::none(), py::arg("dither") = false,
      py::arg("variant") = "", py::arg("dtype") = "uint8", py::arg("raw") = false,
      "Renders a Triangulation, or a blob's bytes, as trisim render does: engine 'reference' (every method; "
      "dtype='float64' gives its doubles, RGB, unclamped, NaN outside the domain) or 'core' (bilinear, "
      "zienkiewicz; format l8|rgb888|rgb565le|rgb565be|xrgb8888, the frame decoded to uint8, or with raw=True its "
      "bytes as (H, W, bytes per pixel)). A blob is drawn by the core with its own method unless engine= is given.");
}

}  // namespace tristream::python
