/* SPDX-License-Identifier: MIT */
#pragma once
// What trisim renders and how: an input file (.tri or blob), the settings of its render, and the
// render with either engine. Shared by the commands (main.cpp) and trisim golden (golden.cpp).
#include <cstdint>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core_bridge/render_core.h"
#include "model/color.h"
#include "model/image.h"
#include "model/triangulation.h"
#include "reference/fit_names.h"
#include "tristream/blob.h"

namespace tristream::trisim {

struct RenderRequest {
  std::string input;
  std::string method = "bilinear";
  std::string engine = "reference";
  std::string variant;
  int width = 0;
  int height = 0;
  std::string fit = std::string(fit_name(Fit::stretch));  // a name of reference/fit_names.h
  Background background;
  // The core's tiling (RenderParams::tile_width/height): `tile` for both sides unless a side is
  // given (>= 0); 0 = the viewport's width (bands) or height (one band).
  int tile = 32;
  int tile_width = -1;
  int tile_height = -1;
  core::Rect viewport;  // output pixels to render, half-open; empty = the whole output
  std::string format;   // core: pixel format, a name of core_bridge/pixel_format_names.h ("" = pixel_format_of's)
  bool dither = false;
  // Settings given explicitly, by their option names ("--engine", "--tile", ...): an option that
  // would be ignored is an error, and a blob's engine and method are its own unless given.
  std::set<std::string, std::less<>> given;
  bool was_given(std::string_view option) const { return given.count(option) > 0; }
};

// The reference's method names, in the order of docs and tables.
std::vector<std::string> method_names();
// The methods the core renders (bilinear, zienkiewicz).
std::vector<std::string> core_method_names();

// "V" (every channel) or "R,G,B", each 0 to 255. Throws UsageError naming `what` otherwise.
Background parse_background(const std::string& text, const std::string& what);
// "X0,Y0,X1,Y1": the half-open rectangle of output pixels [X0, X1) x [Y0, Y1), as the core's Rect.
core::Rect parse_viewport(const std::string& text, const std::string& what);

// What the input file holds: a .tri, or a blob whose bytes the core renders as they are (a
// compressed blob from its streams, band by band; its v1 expansion, made by the core's
// expand_compressed_blob, serves the mesh, the checks and bench's side-by-side v1 timing).
struct Input {
  Triangulation tri;  // for a blob: its size and colour space, and with the mesh read back (unpack_blob) when needed
  std::vector<std::uint8_t> blob;  // the v1 blob's bytes when the file is a blob, else empty
  core::Method blob_method = core::Method::bilinear;
  bool compressed = false;           // the file is a compressed blob (TSTC) and `blob` its expansion
  std::size_t expand_workspace = 0;  // compressed: the ring the expansion needed (expand_workspace_size)
  std::vector<std::uint8_t> compressed_bytes;  // compressed: the file's bytes, which the core renders
  bool is_blob() const { return !blob.empty(); }
};

// Reads a .tri or a blob (by its content). A blob's mesh is read back only when `need_mesh`
// (the reference engine, compare): the core draws blobs whose mesh the reference could not.
Input read_input(const std::string& path, bool need_mesh);

// A blob goes to the core unless --engine says otherwise, with its own method unless --method
// says otherwise: another method with the core is a usage error (the blob holds what its method
// needs, gradients or not).
void resolve_blob_request(const Input& in, RenderRequest& req, bool method_given);

// Whether render or bench needs a blob's mesh: with --engine reference (a blob's default engine is
// the core, which draws the blob from its bytes).
bool needs_mesh(const RenderRequest& req);

// Refuses a render of more than limits::max_image_pixels before anything is allocated: a usage
// error when --width/--height ask for it, a data error when the file's size does.
void check_render_size(const Triangulation& tri, const RenderRequest& req);

// Options that would be ignored are usage errors: the core's options with the reference engine,
// a method variant with the core, dithering of a format that is not RGB565, a method the core
// does not have.
void check_engine_options(const RenderRequest& req);

// The core's pixel format: --format, else l8 for a grey triangulation and rgb888 for colour.
core::PixelFormat pixel_format_of(const Triangulation& tri, const RenderRequest& req);
CoreOptions core_options(const Triangulation& tri, const RenderRequest& req);

// The core's frame of the input: a blob's own bytes, a .tri packed for the method.
CoreFrame core_frame(const Input& in, const RenderRequest& req);

struct Rendered {
  Image image;
  double ms = 0;
};

// The picture a render is measured by: for a grey triangulation rendered by the core in a colour
// format, the luma of the decoded frame (what an original grey image is compared with).
Rendered render(const Input& in, const RenderRequest& req);

// The picture `trisim render` writes: with the core, the frame decoded (frame_to_image: RGB for
// every format but l8), else the reference's render.
Image render_picture(const Input& in, const RenderRequest& req);

}  // namespace tristream::trisim
