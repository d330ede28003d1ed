// SPDX-License-Identifier: MIT
// tripack: pack a .tri triangulation into a blob for the fixed-point core (binary or C source),
// and report the RAM the core needs to render it (tile buffer, workspace and stack).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "common/errors.h"
#include "common/json_name.h"
#include "common/tool_main.h"
#include "core_bridge/c_source.h"
#include "core_bridge/compress.h"
#include "core_bridge/compressed_c_source.h"
#include "core_bridge/core_stack.h"
#include "core_bridge/pack.h"
#include "core_bridge/render_core.h"
#include "io/atomic_file.h"
#include "io/tri_file.h"

using namespace tristream;

namespace {

struct Request {
  std::string input;
  std::string output;
  std::string method = "bilinear";
  std::string format = "rgb565be";
  int tile = 32;
  int tile_width = -1;   // -1: --tile
  int tile_height = -1;
  std::string symbol;
  int width = 0;
  int height = 0;
  bool json = false;
  bool compress = false;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Pack a triangulation (.tri) into a blob for the fixed-point core and report the RAM it needs.\n"
               "-o x.bin writes the blob; -o x.c writes x.c (the bytes and a ts_blob_descriptor) and x.h, which\n"
               "refuses to compile against a core without the blob's method or the format, and defines\n"
               "<SYMBOL>_BYTES (the blob's size), <SYMBOL>_TILE_BUFFER_MAX_BYTES and <SYMBOL>_WORKSPACE_MAX_BYTES:\n"
               "enough for any output up to --width x --height, any viewport of it and any tile up to the tile size."};
  Request req;
  app.add_option("input", req.input, "Triangulation file (.tri)")->required();
  app.add_option("-o,--output", req.output, "Output: .bin (raw blob) or .c (C source plus header)")->required();
  app.add_option("-m,--method", req.method, "Interpolation method")
      ->check(CLI::IsMember({"bilinear", "zienkiewicz"}))
      ->capture_default_str();
  app.add_option("-f,--format", req.format,
                 "Pixel format the RAM figure and the descriptor are for; a display on SPI (ST7789, ILI9341) "
                 "wants rgb565be, RGB565 high byte first")
      ->check(CLI::IsMember({"l8", "rgb888", "rgb565le", "rgb565be", "xrgb8888"}))
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
  return run_tool("tripack", app, argc, argv, [&]() -> int {
    const std::string ext = std::filesystem::path(req.output).extension().string();
    if (ext != ".bin" && ext != ".c")
      throw UsageError("output " + req.output + ": expected a name ending in .bin or .c");
    const Triangulation tri = read_tri_file(req.input);
    const std::vector<std::uint8_t> blob = pack_blob(tri, parse_core_method(req.method), req.input);
    if (!req.symbol.empty() && !is_blob_symbol(req.symbol))
      throw UsageError("--symbol " + req.symbol +
                       ": expected a C identifier that is no C or C++ keyword, not reserved, not main and not "
                       "starting with ts_ or tristream");
    CoreOptions o;
    o.width = req.width;
    o.height = req.height;
    o.tile_width = req.tile_width >= 0 ? req.tile_width : req.tile;
    o.tile_height = req.tile_height >= 0 ? req.tile_height : req.tile;
    o.format = parse_pixel_format(req.format);
    CoreRenderer sizes(blob, o, req.input);
    CompressStats stats;
    std::vector<std::uint8_t> compressed;
    core::CompressedBlob cblob;
    if (req.compress) {
      compressed = compress_blob(blob, req.input, &stats);
      core::BlobError error;
      const core::Status s = core::open_compressed_blob(compressed.data(), compressed.size(), &cblob, &error);
      if (s != core::Status::ok)
        throw std::logic_error("compressed blob refused at byte " + std::to_string(error.offset) + ": " +
                               core::status_text(s));
    }
    // The compressed blob rendered from its streams, at the same options.
    std::optional<CoreRenderer> stream;
    if (req.compress) stream.emplace(compressed, o, req.input);
    const std::string symbol = req.symbol.empty() ? blob_symbol_of(req.output) : req.symbol;
    // The descriptor of -o x.c: the figures of a render of the whole output in these tiles.
    CBlobSpec spec;
    spec.symbol = symbol;
    spec.source_name = std::filesystem::path(req.input).filename().string();
    spec.format = o.format;
    spec.output_width = req.width ? req.width : sizes.blob().width;
    spec.output_height = req.height ? req.height : sizes.blob().height;
    spec.tile_width = o.tile_width;
    spec.tile_height = o.tile_height;
    const std::filesystem::path header = std::filesystem::path(req.output).replace_extension(".h");
    if (req.compress && ext == ".bin") {
      write_file_atomically(req.output,
                            std::string_view(reinterpret_cast<const char*>(compressed.data()), compressed.size()));
    } else if (req.compress) {
      spec.tile_buffer_bytes = stream->tile_buffer_bytes();
      spec.workspace_bytes = stream->workspace_bytes();
      write_file_atomically(header.string(),
                            compressed_c_header(cblob, sizes.blob(), stream->stream_workspace().decoders, spec));
      write_file_atomically(req.output, compressed_c_source(compressed, sizes.blob(), spec));
    } else if (ext == ".bin") {
      write_file_atomically(req.output, std::string_view(reinterpret_cast<const char*>(blob.data()), blob.size()));
    } else {
      spec.tile_buffer_bytes = sizes.tile_buffer_bytes();
      spec.workspace_bytes = sizes.workspace_bytes();
      write_file_atomically(header.string(), blob_c_header(sizes.blob(), spec));
      write_file_atomically(req.output, blob_c_source(blob, sizes.blob(), spec));
    }
    // The stack is the Cortex-M4 figure make bench-mcu measured (core_bridge/core_stack.h).
    const std::size_t stack = core_stack_bytes(sizes.blob().method);
    const std::size_t ram = sizes.tile_buffer_bytes() + sizes.workspace_bytes() + stack;
    const std::size_t stream_stack = core_compressed_stack_bytes(sizes.blob().method);
    const int out_w = req.width ? req.width : sizes.blob().width, out_h = req.height ? req.height : sizes.blob().height;
    const BufferBounds bound = buffer_upper_bounds(sizes.blob(), o.format, out_w, out_h, o.tile_width, o.tile_height);
    if (req.json) {
      nlohmann::json j;
      j["output"] = json_file_name(req.output);
      j["method"] = req.method;
      j["format"] = req.format;
      j["tile"] = req.tile;
      j["tile_width"] = o.tile_width;
      j["tile_height"] = o.tile_height;
      j["blob_bytes"] = blob.size();
      j["tile_buffer_bytes"] = sizes.tile_buffer_bytes();
      j["workspace_bytes"] = sizes.workspace_bytes();
      j["stack_bytes"] = stack;
      j["ram_bytes"] = ram;
      j["tile_buffer_max_bytes"] = bound.tile_buffer_bytes;
      j["workspace_max_bytes"] = bound.workspace_bytes;
      if (req.compress) {
        const double n = double(stats.vertices);
        j["blob_bytes"] = compressed.size();
        j["v1_bytes"] = blob.size();
        j["expanded_bytes"] = core::expanded_blob_size(cblob);
        j["decoder_ring_bytes"] = core::expand_workspace_size(cblob);
        j["decoder_state_bytes"] = sizeof(core::LayerDecoder);
        const core::CompressedWorkspace& f = stream->stream_workspace();
        j["stream_render"] = {{"tile_buffer_bytes", stream->tile_buffer_bytes()},
                              {"workspace_bytes", f.bytes},
                              {"decoders_bytes", f.decoders},
                              {"band_store_bytes", f.band_store},
                              {"live_triangles", f.live_triangles},
                              {"live_vertices", f.live_vertices},
                              {"channel_scratch_bytes", f.channel_scratch},
                              {"stack_bytes", stream_stack},
                              {"ram_bytes", stream->tile_buffer_bytes() + f.bytes + stream_stack}};
        j["vertices"] = stats.vertices;
        j["triangles"] = stats.triangles;
        j["bits_per_vertex"] = {{"positions", stats.position_bits / n},
                                {"values", stats.value_bits / n},
                                {"gradients", stats.gradient_bits / n},
                                {"connectivity", stats.connectivity_bits / n},
                                {"flags", stats.flag_bits / n},
                                {"total", 8.0 * double(compressed.size()) / n}};
      }
      std::printf("%s\n", j.dump(2).c_str());
    } else {
      const std::string w = o.tile_width ? std::to_string(o.tile_width) : std::string("full-width");
      const std::string h = o.tile_height ? std::to_string(o.tile_height) : std::string("full-height");
      const std::string tiles = o.tile_width == 0 && o.tile_height == 0 ? std::string("full frame")
                                : o.tile_width == 0 ? "bands of " + h + " rows"
                                                    : "tiles " + w + "x" + h;
      if (req.compress) {
        const double n = double(stats.vertices);
        std::printf("%s: compressed blob %zu bytes (%s), v1 %zu bytes (%.2fx)\n", req.output.c_str(),
                    compressed.size(), req.method.c_str(), blob.size(), double(blob.size()) / double(compressed.size()));
        std::printf("bits per vertex (%llu vertices, %llu triangles): positions %.2f + values %.2f + gradients %.2f + "
                    "connectivity %.2f + flags %.2f = %.2f\n",
                    static_cast<unsigned long long>(stats.vertices), static_cast<unsigned long long>(stats.triangles),
                    stats.position_bits / n, stats.value_bits / n, stats.gradient_bits / n,
                    stats.connectivity_bits / n, stats.flag_bits / n, 8.0 * double(compressed.size()) / n);
        std::printf("decoder RAM: ring %zu + state %zu bytes; expanded v1 blob %zu bytes\n",
                    core::expand_workspace_size(cblob), sizeof(core::LayerDecoder), core::expanded_blob_size(cblob));
        const core::CompressedWorkspace& f = stream->stream_workspace();
        std::printf("RAM rendered from the stream for %s, %s: tile buffer %zu + workspace %zu (8 + channel scratch %zu "
                    "+ decoders and rings %zu + %d x band store %zu for at most %u live triangles and %u live "
                    "vertices in a band) + stack %zu (Cortex-M4) = %zu bytes\n",
                    req.format.c_str(), tiles.c_str(), stream->tile_buffer_bytes(), f.bytes, f.channel_scratch,
                    f.decoders, int(cblob.layer_count), f.band_store, unsigned(f.live_triangles), unsigned(f.live_vertices),
                    stream_stack,
                    stream->tile_buffer_bytes() + f.bytes + stream_stack);
        std::printf("RAM of its v1 blob (read in place from flash, %zu bytes):\n", blob.size());
      } else {
        std::printf("%s: blob %zu bytes (%s)\n", req.output.c_str(), blob.size(), req.method.c_str());
      }
      std::printf("RAM for %s, %s: tile buffer %zu + workspace %zu + stack %zu (Cortex-M4) = %zu bytes\n",
                  req.format.c_str(), tiles.c_str(), sizes.tile_buffer_bytes(), sizes.workspace_bytes(), stack, ram);
      std::printf("upper bound for outputs up to %dx%d, any viewport, %s at most: tile buffer %zu + workspace %zu + "
                  "stack %zu = %zu bytes\n",
                  out_w, out_h, tiles.c_str(), bound.tile_buffer_bytes, bound.workspace_bytes, stack,
                  bound.tile_buffer_bytes + bound.workspace_bytes + stack);
    }
    return exit_ok;
  });
}
