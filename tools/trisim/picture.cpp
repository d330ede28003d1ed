// SPDX-License-Identifier: MIT
#include "picture.h"

#include <algorithm>
#include <chrono>
#include <span>

#include "common/errors.h"
#include "core_bridge/blob_file.h"
#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "core_bridge/unpack.h"
#include "io/atomic_file.h"
#include "io/limits.h"
#include "io/tri_file.h"
#include "reference/render.h"
#include "tristream/compressed_blob.h"

namespace tristream::trisim {

namespace {

// Comma-separated integers in [lo, hi]; empty when the text is not that.
std::vector<long> parse_ints(const std::string& text, long lo, long hi) {
  std::vector<long> out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = text.find(',', pos);
    const std::string part = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (part.empty() || part.size() > 9 || !std::all_of(part.begin(), part.end(), [](char c) {
          return c >= '0' && c <= '9';
        }))
      return {};
    const long v = std::stol(part);
    if (v < lo || v > hi) return {};
    out.push_back(v);
    if (comma == std::string::npos) return out;
    pos = comma + 1;
  }
}

}  // namespace

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : reference_methods()) names.emplace_back(m.name);
  return names;
}

std::vector<std::string> core_method_names() {
  return {std::string(to_string(core::Method::bilinear)), std::string(to_string(core::Method::zienkiewicz))};
}

Background parse_background(const std::string& text, const std::string& what) {
  const std::vector<long> v = parse_ints(text, 0, 255);
  if (v.size() == 1) return Background(std::uint8_t(v[0]));
  if (v.size() == 3) return Background(std::uint8_t(v[0]), std::uint8_t(v[1]), std::uint8_t(v[2]));
  throw UsageError(what + ": expected one value or R,G,B, each 0 to 255, found '" + text + "'");
}

core::Rect parse_viewport(const std::string& text, const std::string& what) {
  const std::vector<long> v = parse_ints(text, 0, 65535);
  if (v.size() != 4 || v[2] <= v[0] || v[3] <= v[1])
    throw UsageError(what + ": expected X0,Y0,X1,Y1 with X0 < X1 and Y0 < Y1 (output pixels [X0, X1) x [Y0, Y1)), found '" +
                     text + "'");
  return core::Rect{std::int32_t(v[0]), std::int32_t(v[1]), std::int32_t(v[2]), std::int32_t(v[3])};
}

Input read_input(const std::string& path, bool need_mesh) {
  const std::string text = read_file(path);
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  Input in;
  if (!tristream::is_blob(bytes)) {
    in.tri = parse_tri(text, path);
    return in;
  }
  in.compressed = core::is_compressed_blob(bytes.data(), bytes.size());
  if (in.compressed) {
    in.blob = expand_compressed_or_throw(bytes, path, &in.expand_workspace);
    in.compressed_bytes.assign(bytes.begin(), bytes.end());
  } else {
    in.blob.assign(bytes.begin(), bytes.end());
  }
  // Offsets of the checks below are in the file, or for a compressed blob in its expansion.
  const std::string name = in.compressed ? path + " (expanded to v1)" : path;
  const core::Blob blob = open_blob_or_throw(in.blob, name);
  check_blob_file_length(bytes, path);  // the core opened it: its total size is the file's at most
  in.blob_method = blob.method;
  if (need_mesh) {
    in.tri = unpack_blob(blob, name).tri;
  } else {
    in.tri.width = blob.width;
    in.tri.height = blob.height;
    in.tri.space = blob.space == core::ColorSpace::grey  ? ColorSpace::grey
                   : blob.space == core::ColorSpace::rgb ? ColorSpace::rgb
                                                         : ColorSpace::ycbcr;
  }
  return in;
}

void resolve_blob_request(const Input& in, RenderRequest& req, bool method_given) {
  if (!in.is_blob()) return;
  if (!req.was_given("--engine")) req.engine = "core";
  const std::string packed(to_string(in.blob_method));
  if (!method_given) req.method = packed;
  if (req.engine == "core" && req.method != packed)
    throw UsageError("--method " + req.method + ": " + req.input + " is a blob packed for " + packed +
                     ", which the core renders with that method only (--engine reference renders its mesh with any)");
}

bool needs_mesh(const RenderRequest& req) { return req.was_given("--engine") && req.engine == "reference"; }

void check_render_size(const Triangulation& tri, const RenderRequest& req) {
  const std::uint64_t w = req.width ? req.width : tri.width, h = req.height ? req.height : tri.height;
  if (w * h <= limits::max_image_pixels) return;
  const std::string what = "a render of at most " + std::to_string(limits::max_image_pixels) +
                           " pixels (the limit for a render), found " + std::to_string(w) + "x" + std::to_string(h);
  if (req.width || req.height) throw UsageError("--width/--height: expected " + what);
  throw DataError(req.input + ": expected " + what + " (the file's size; --width and --height render smaller)");
}

void check_engine_options(const RenderRequest& req) {
  if (req.engine == "reference") {
    for (const char* core_only : {"--tile", "--tile-width", "--tile-height", "--viewport", "--format", "--dither", "--raw"})
      if (req.was_given(core_only)) throw UsageError(std::string(core_only) + ": applies to --engine core only");
    return;
  }
  if (!req.variant.empty()) throw UsageError("--variant: applies to --engine reference only");
  auto rgb565 = [](const std::string& name) {
    if (name.empty()) return false;
    const core::PixelFormat f = parse_pixel_format(name);
    return f == core::PixelFormat::rgb565_le || f == core::PixelFormat::rgb565_be;
  };
  if (req.dither && !rgb565(req.format))
    throw UsageError("--dither: applies to --format " + std::string(pixel_format_name(core::PixelFormat::rgb565_le)) +
                     " and " + std::string(pixel_format_name(core::PixelFormat::rgb565_be)) + " only");
  const std::vector<std::string> core_methods = core_method_names();
  if (std::find(core_methods.begin(), core_methods.end(), req.method) == core_methods.end())
    throw UsageError("--method " + req.method + ": the core renders bilinear and zienkiewicz only (--engine reference "
                     "renders every method)");
}

core::PixelFormat pixel_format_of(const Triangulation& tri, const RenderRequest& req) {
  if (!req.format.empty()) return parse_pixel_format(req.format);
  return tri.channels() == 1 ? core::PixelFormat::l8 : core::PixelFormat::rgb888;
}

CoreOptions core_options(const Triangulation& tri, const RenderRequest& req) {
  CoreOptions o;
  o.width = req.width;
  o.height = req.height;
  o.fit = core_fit(parse_fit(req.fit));
  o.viewport = req.viewport;
  o.tile_width = req.tile_width >= 0 ? req.tile_width : req.tile;
  o.tile_height = req.tile_height >= 0 ? req.tile_height : req.tile;
  o.format = pixel_format_of(tri, req);
  o.dither = req.dither;
  o.background = req.background;
  return o;
}

CoreFrame core_frame(const Input& in, const RenderRequest& req) {
  if (!in.is_blob()) return render_core_frame(in.tri, req.method, core_options(in.tri, req), req.input);
  CoreRenderer renderer(in.compressed ? in.compressed_bytes : in.blob, core_options(in.tri, req), req.input);
  CoreFrame frame;
  renderer.render(frame);
  return frame;
}

Rendered render(const Input& in, const RenderRequest& req) {
  const Triangulation& tri = in.tri;
  if (req.engine == "core") {
    const auto t0 = std::chrono::steady_clock::now();
    Image image = frame_to_image(core_frame(in, req));
    if (tri.channels() == 1 && image.channels == 3) image = to_grey(image);
    Rendered out{std::move(image), 0};
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  const MethodInfo* method = find_reference_method(req.method);
  if (!method) throw UsageError("unknown method '" + req.method + "'");
  RenderOptions options;
  options.width = req.width;
  options.height = req.height;
  options.fit = parse_fit(req.fit);
  options.variant = req.variant;
  options.background = req.background;
  const auto t0 = std::chrono::steady_clock::now();
  Rendered out{render_reference(tri, *method, options), 0};
  out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

Image render_picture(const Input& in, const RenderRequest& req) {
  if (req.engine == "core") return frame_to_image(core_frame(in, req));
  return render(in, req).image;
}

}  // namespace tristream::trisim
