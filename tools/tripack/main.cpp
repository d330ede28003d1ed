// SPDX-License-Identifier: MIT
// tripack: pack a .tri triangulation into a blob for the fixed-point core (binary or C source),
// and report the RAM the core needs to render it (tile buffer, workspace and stack).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/errors.h"
#include "common/tool_main.h"
#include "core_bridge/c_source.h"
#include "core_bridge/compress.h"
#include "core_bridge/compressed_c_source.h"
#include "core_bridge/core_stack.h"
#include "core_bridge/pack.h"
#include "core_bridge/pixel_format_names.h"
#include "core_bridge/render_core.h"
#include "io/atomic_file.h"
#include "io/atomic_pair.h"
#include "io/tri_file.h"
#include "report.h"

using namespace tristream;
using namespace tristream::tripack;

namespace {

struct Request {
  std::string input;
  std::string output;
  std::string method = "bilinear";
  std::string format = std::string(pixel_format_name(core::PixelFormat::rgb565_be));
  int tile = 32;
  int tile_width = -1;   // -1: --tile
  int tile_height = -1;
  std::string symbol;
  int width = 0;
  int height = 0;
  bool json = false;
  bool compress = false;
};

void add_options(CLI::App& app, Request& req) {
  app.add_option("input", req.input, "Triangulation file (.tri)")->required();
  app.add_option("-o,--output", req.output, "Output: .bin (raw blob) or .c (C source plus header)")->required();
  app.add_option("-m,--method", req.method, "Interpolation method")
      ->check(CLI::IsMember({"bilinear", "zienkiewicz"}))
      ->capture_default_str();
  app.add_option("-f,--format", req.format,
                 "Pixel format the RAM figure and the descriptor are for; a display on SPI (ST7789, ILI9341) "
                 "wants rgb565be, RGB565 high byte first")
      ->check(CLI::IsMember(pixel_format_name_list()))
      ->capture_default_str();
  app.add_option("--tile", req.tile, "Square tile side the RAM figure is for (0 = full frame)")
      ->check(CLI::Range(0, core::config::max_dimension))
      ->capture_default_str();
  app.add_option("--tile-width", req.tile_width, "Tile width, instead of --tile's (0 = the viewport's width: bands)")
      ->check(CLI::Range(0, core::config::max_dimension));
  app.add_option("--tile-height", req.tile_height, "Tile height, instead of --tile's (0 = the viewport's height)")
      ->check(CLI::Range(0, core::config::max_dimension));
  app.add_option("--symbol", req.symbol,
                 "C name of the descriptor for -o x.c (default: from the file name, e.g. blob_int for int.c)");
  app.add_option("--width", req.width, "Output width the RAM figure is for (default: the triangulation's)")
      ->check(CLI::Range(2, core::config::max_dimension));
  app.add_option("--height", req.height, "Output height (default: the triangulation's)")
      ->check(CLI::Range(2, core::config::max_dimension));
  app.add_flag("--compress", req.compress,
               "Write the compressed blob (\"TSTC\", docs/COMPRESSED_BLOB.md) instead of v1: x.bin, or x.c and x.h\n"
               "as for v1 (a ts_blob_descriptor for ts_open_compressed and ts_render_compressed, guards, the\n"
               "bounds of the render from the streams) and SYMBOL_EXPANDED_BYTES, SYMBOL_DECODER_RING_BYTES for\n"
               "C++'s expand_compressed_blob; the report adds its bytes against v1 and its bits per vertex");
  app.add_flag("--json", req.json, "Print the figures as JSON");
}

CoreOptions core_options(const Request& req) {
  CoreOptions o;
  o.width = req.width;
  o.height = req.height;
  o.tile_width = req.tile_width >= 0 ? req.tile_width : req.tile;
  o.tile_height = req.tile_height >= 0 ? req.tile_height : req.tile;
  o.format = parse_pixel_format(req.format);
  return o;
}

// The compressed blob of --compress, opened by the core (which must accept what the compressor wrote).
struct Compressed {
  std::vector<std::uint8_t> bytes;
  core::CompressedBlob opened;  // points into bytes
  CompressStats stats;
};

void compress(const std::vector<std::uint8_t>& v1, const std::string& name, Compressed& c) {
  c.bytes = compress_blob(v1, name, &c.stats);
  core::BlobError error;
  const core::Status s = core::open_compressed_blob(c.bytes.data(), c.bytes.size(), &c.opened, &error);
  if (s != core::Status::ok)
    throw std::logic_error("compressed blob refused at byte " + std::to_string(error.offset) + ": " +
                           core::status_text(s));
}

void write_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

// Writes -o: the blob (.bin), or the C source and its header (.c), whose descriptor has the figures
// of a render of the whole output in the tiles asked for; the two as one unit (both or neither),
// the source refusing to compile beside another header. `compressed` and `stream` (its render
// from the streams) with --compress only.
void write_outputs(const Request& req, const CoreOptions& o, const std::vector<std::uint8_t>& blob,
                   const CoreRenderer& sizes, const Compressed* compressed, const CoreRenderer* stream) {
  const bool c_source = std::filesystem::path(req.output).extension() == ".c";
  if (!c_source) return write_bytes(req.output, compressed ? compressed->bytes : blob);
  CBlobSpec spec;
  spec.symbol = req.symbol.empty() ? blob_symbol_of(req.output) : req.symbol;
  spec.source_name = std::filesystem::path(req.input).filename().string();
  spec.format = o.format;
  spec.output_width = req.width ? req.width : sizes.blob().width;
  spec.output_height = req.height ? req.height : sizes.blob().height;
  spec.tile_width = o.tile_width;
  spec.tile_height = o.tile_height;
  const std::string header = std::filesystem::path(req.output).replace_extension(".h").string();
  CPair pair;
  if (compressed) {
    spec.tile_buffer_bytes = stream->tile_buffer_bytes();
    spec.workspace_bytes = stream->workspace_bytes();
    pair.header = compressed_c_header(compressed->opened, sizes.blob(), stream->stream_workspace().decoders, spec);
    pair.source = compressed_c_source(compressed->bytes, sizes.blob(), spec);
  } else {
    spec.tile_buffer_bytes = sizes.tile_buffer_bytes();
    spec.workspace_bytes = sizes.workspace_bytes();
    pair.header = blob_c_header(sizes.blob(), spec);
    pair.source = blob_c_source(blob, sizes.blob(), spec);
  }
  tie_c_pair(pair, spec.symbol, std::filesystem::path(header).filename().string());
  write_pair_atomically(header, pair.header, req.output, pair.source);
}

PackReport report_of(const Request& req, const CoreOptions& o, const std::vector<std::uint8_t>& blob,
                     const CoreRenderer& sizes, const Compressed* compressed, const CoreRenderer* stream) {
  PackReport r;
  r.output = req.output;
  r.method = req.method;
  r.format = req.format;
  r.tile = req.tile;
  r.tile_width = o.tile_width;
  r.tile_height = o.tile_height;
  r.v1_bytes = blob.size();
  r.tile_buffer_bytes = sizes.tile_buffer_bytes();
  r.workspace_bytes = sizes.workspace_bytes();
  r.stack_bytes = core_stack_bytes(sizes.blob().method);
  r.output_width = req.width ? req.width : sizes.blob().width;
  r.output_height = req.height ? req.height : sizes.blob().height;
  r.bound = buffer_upper_bounds(sizes.blob(), o.format, r.output_width, r.output_height, o.tile_width, o.tile_height);
  if (!compressed) return r;
  CompressedReport& c = r.compressed.emplace();
  c.bytes = compressed->bytes.size();
  c.stats = compressed->stats;
  c.expanded_bytes = core::expanded_blob_size(compressed->opened);
  c.decoder_ring_bytes = core::expand_workspace_size(compressed->opened);
  c.decoder_state_bytes = sizeof(core::LayerDecoder);
  c.layer_count = int(compressed->opened.layer_count);
  c.tile_buffer_bytes = stream->tile_buffer_bytes();
  c.workspace = stream->stream_workspace();
  c.stack_bytes = core_compressed_stack_bytes(sizes.blob().method);
  return r;
}

int pack(const Request& req) {
  const std::string ext = std::filesystem::path(req.output).extension().string();
  if (ext != ".bin" && ext != ".c") throw UsageError("output " + req.output + ": expected a name ending in .bin or .c");
  const Triangulation tri = read_tri_file(req.input);
  const std::vector<std::uint8_t> blob = pack_blob(tri, parse_core_method(req.method), req.input);
  if (!req.symbol.empty() && !is_blob_symbol(req.symbol))
    throw UsageError("--symbol " + req.symbol +
                     ": expected a C identifier that is no C or C++ keyword, not reserved, not main and not "
                     "starting with ts_ or tristream");
  const CoreOptions o = core_options(req);
  const CoreRenderer sizes(blob, o, req.input);
  std::optional<Compressed> compressed;
  std::optional<CoreRenderer> stream;  // the compressed blob rendered from its streams, at the same options
  if (req.compress) {
    compress(blob, req.input, compressed.emplace());
    stream.emplace(compressed->bytes, o, req.input);
  }
  const Compressed* c = compressed ? &*compressed : nullptr;
  const CoreRenderer* s = stream ? &*stream : nullptr;
  write_outputs(req, o, blob, sizes, c, s);
  const PackReport report = report_of(req, o, blob, sizes, c, s);
  if (req.json) print_json(report);
  else print_text(report);
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Pack a triangulation (.tri) into a blob for the fixed-point core and report the RAM it needs.\n"
               "-o x.bin writes the blob; -o x.c writes x.c (the bytes and a ts_blob_descriptor) and x.h, which\n"
               "refuses to compile against a core without the blob's method or the format, and defines\n"
               "<SYMBOL>_BYTES (the blob's size), <SYMBOL>_TILE_BUFFER_MAX_BYTES and <SYMBOL>_WORKSPACE_MAX_BYTES:\n"
               "enough for any output up to --width x --height, any viewport of it and any tile up to the tile size.\n"
               "The two are written as one unit (both, or neither changed) and x.c refuses to compile beside an x.h\n"
               "that was not written with it (<SYMBOL>_PAIR_HASH)."};
  Request req;
  add_options(app, req);
  return run_tool("tripack", app, argc, argv, [&] { return pack(req); });
}
