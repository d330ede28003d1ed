// SPDX-License-Identifier: MIT
#include "core_bridge/c_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "common/errors.h"
#include "core_bridge/pixel_format_names.h"
#include "crc32.h"
#include "tristream/config.h"
#include "tristream/tristream.h"

namespace tristream {

namespace {

// Keywords of C89 through C23 and of C++98 through C++20, and names the descriptor must not take.
constexpr std::string_view taken[] = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum", "extern",
    "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict", "return", "short", "signed",
    "sizeof", "static", "struct", "switch", "typedef", "union", "unsigned", "void", "volatile", "while",
    "alignas", "alignof", "bool", "constexpr", "false", "nullptr", "static_assert", "thread_local", "true",
    "typeof", "typeof_unqual", "and", "and_eq", "asm", "bitand", "bitor", "catch", "char8_t", "char16_t",
    "char32_t", "class", "compl", "concept", "consteval", "constinit", "const_cast", "co_await", "co_return",
    "co_yield", "decltype", "delete", "dynamic_cast", "explicit", "export", "friend", "mutable", "namespace",
    "new", "noexcept", "not", "not_eq", "operator", "or", "or_eq", "private", "protected", "public",
    "reinterpret_cast", "requires", "static_cast", "template", "this", "throw", "try", "typeid", "typename",
    "using", "virtual", "wchar_t", "xor", "xor_eq", "main",
    // Names the generated files' includes (stddef.h, stdint.h) or C++ define, beyond the `_t` types.
    "NULL", "offsetof", "std", "errno", "assert"};

// The limit macros of stdint.h and stddef.h: INT8_MAX, UINT64_C, SIZE_MAX, PTRDIFF_MIN, ...
bool is_limit_macro(std::string_view name) {
  for (std::string_view head : {"INT", "UINT", "SIZE_", "PTRDIFF_", "SIG_ATOMIC_", "WCHAR_", "WINT_"})
    if (name.substr(0, head.size()) == head)
      for (std::string_view tail : {"_MAX", "_MIN", "_C"})
        if (name.size() > tail.size() && name.substr(name.size() - tail.size()) == tail) return true;
  return false;
}

}  // namespace

std::string c_upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Text for a C comment: no "*/" and only printable ASCII.
std::string c_comment_safe(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E) c = '?';
  for (std::size_t at; (at = s.find("*/")) != std::string::npos;) s[at + 1] = '?';
  return s;
}

namespace {

std::size_t round_up(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

}  // namespace

bool is_blob_symbol(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  if (name[0] == '_' && name.size() > 1 && (name[1] == '_' || std::isupper(static_cast<unsigned char>(name[1]))))
    return false;
  if (name.find("__") != std::string_view::npos) return false;  // reserved in C++
  // `_t` names are the standard headers' types (uint8_t, size_t) and reserved by POSIX.
  if (name.size() >= 2 && name.substr(name.size() - 2) == "_t") return false;
  if (is_limit_macro(name)) return false;
  const std::string lower = [&] {
    std::string s(name);
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }();
  if (lower.rfind("ts_", 0) == 0 || lower.rfind("tristream", 0) == 0) return false;
  return std::find(std::begin(taken), std::end(taken), name) == std::end(taken);
}

std::string blob_symbol_of(std::string_view path) {
  std::string id;
  for (char c : std::filesystem::path(std::string(path)).stem().string()) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    if (c != '_' || id.empty() || id.back() != '_') id += c;  // "__" is reserved in C++
  }
  // A name that cannot be the symbol gets a prefix, or a suffix where the prefix is not enough
  // (uint8_t: a `_t` name; blob_uint8_t still ends so).
  if (!is_blob_symbol(id)) id = is_blob_symbol("blob_" + id) ? "blob_" + id : id + "_blob";
  if (!is_blob_symbol(id)) id = "blob";
  return id;
}

namespace {

constexpr std::size_t workspace_alignment = 8;  // firmware_core/src/workspace_layout.h

// The tile's largest size and the channel scratch of a layered blob in such a tile (6 bytes a pixel).
struct TileBound {
  std::size_t width, height, scratch;
};
TileBound tile_bound(const core::Blob& blob, core::PixelFormat format, int width, int height, int tile_width,
                     int tile_height) {
  const std::size_t tw = std::size_t(tile_width > 0 ? std::min(tile_width, width) : width);
  const std::size_t th = std::size_t(tile_height > 0 ? std::min(tile_height, height) : height);
  std::size_t scratch = 0;
  if (blob.layer_count > 1 && format != core::PixelFormat::coverage8)
    scratch = round_up(tw * th * 3 * sizeof(std::int16_t), workspace_alignment);
  return {tw, th, scratch};
}

// render.h's need(V, C, F) of a band store holding V vertices and C triangles of which F have flags.
std::size_t band_store_need(std::size_t v, std::size_t c, std::size_t f, int values_per_vertex, bool gradients) {
  const std::size_t n = std::size_t(values_per_vertex);
  const std::size_t records = c == 0 ? 0 : (v <= 1024 ? 4 * (c + f) + 4 : round_up(6 * (c + f) + 2, 4));
  return 4 * v + round_up(2 * n * v, 4) + (gradients ? 8 * n * v : 0) + records +
         std::max(round_up(6 * ((v + 31) / 32), 4), 4 * ((c + f + 31) / 32));
}

}  // namespace

BufferBounds buffer_upper_bounds(const core::Blob& blob, core::PixelFormat format, int width, int height,
                                 int tile_width, int tile_height) {
  const TileBound t = tile_bound(blob, format, width, height, tile_width, tile_height);
  std::uint32_t triangles = 0;
  for (int l = 0; l < blob.layer_count; ++l) triangles = std::max(triangles, blob.layers[l].triangle_count);
  const std::size_t bitmap = round_up(triangles, 32) / 8;
  return {t.width * t.height * std::size_t(core::bytes_per_pixel(format)),
          workspace_alignment + t.scratch + std::size_t(blob.layer_count) * bitmap};
}

BufferBounds compressed_buffer_upper_bounds(const core::Blob& blob, std::size_t decoder_bytes,
                                            core::PixelFormat format, int width, int height, int tile_width,
                                            int tile_height) {
  const TileBound t = tile_bound(blob, format, width, height, tile_width, tile_height);
  std::size_t store = 0;
  for (int l = 0; l < blob.layer_count; ++l) {
    const core::BlobLayer& layer = blob.layers[l];
    std::size_t flagged = 0;
    for (std::uint32_t k = 0; k < layer.triangle_count; ++k) {
      const std::uint8_t* record = layer.triangles + std::size_t(k) * core::blob_triangle_size;
      flagged += (record[6] | record[7]) != 0;  // the u16 flags after the three u16 corners
    }
    store = std::max(store, band_store_need(layer.vertex_count, layer.triangle_count, flagged,
                                            blob.values_per_vertex, blob.method == core::Method::zienkiewicz));
  }
  return {t.width * t.height * std::size_t(core::bytes_per_pixel(format)),
          workspace_alignment + t.scratch + decoder_bytes + std::size_t(blob.layer_count) * store};
}

int c_format(core::PixelFormat format) {
  switch (format) {
    case core::PixelFormat::l8: return TS_L8;
    case core::PixelFormat::rgb888: return TS_RGB888;
    case core::PixelFormat::rgb565_le: return TS_RGB565_LE;
    case core::PixelFormat::rgb565_be: return TS_RGB565_BE;
    case core::PixelFormat::xrgb8888: return TS_XRGB8888;
    case core::PixelFormat::coverage8: break;
  }
  throw UsageError("coverage8 is a test format without a C value");
}

std::string blob_c_guard(core::Method method_of, core::ColorSpace space_of, int layer_count, const CBlobSpec& spec) {
  const int method_bit = method_of == core::Method::zienkiewicz ? 2 : 1;
  const std::string method = method_of == core::Method::zienkiewicz ? "zienkiewicz" : "bilinear";
  const std::string space = space_of == core::ColorSpace::grey  ? "grey"
                            : space_of == core::ColorSpace::rgb ? "RGB"
                                                                : "YCbCr";
  const std::string layers =
      layer_count > 1 ? "#if !TS_LAYERED\n#error \"" + spec.symbol +
                            ": the blob has a mesh per channel, which this core leaves out (TS_LAYERED)\"\n#endif\n"
                      : std::string();
  const std::string format(pixel_format_name(spec.format));
  char format_bit[16];
  std::snprintf(format_bit, sizeof format_bit, "0x%02X", 1u << unsigned(spec.format));
  return "#if TS_SUBPIXEL_BITS != " + std::to_string(core::config::subpixel_bits) +
         " || TS_GRADIENT_FRAC_BITS != " + std::to_string(core::config::gradient_frac_bits) +
         "\n#error \"" + spec.symbol +
         ": blob packed for another tristream core configuration (TS_SUBPIXEL_BITS, TS_GRADIENT_FRAC_BITS)\"\n"
         "#endif\n#if !(TS_METHODS & " + std::to_string(method_bit) + ")\n#error \"" + spec.symbol +
         ": the blob is " + method + ", which this core leaves out (TS_METHODS)\"\n#endif\n"
         "#if !(TS_PIXEL_FORMATS & " + format_bit + ")\n#error \"" + spec.symbol + ": the descriptor is for " +
         format + ", which this core leaves out (TS_PIXEL_FORMATS)\"\n#endif\n"
         "#if !(TS_COLOR_SPACES & " + std::to_string(1 << int(space_of)) + ")\n#error \"" + spec.symbol +
         ": the blob is " + space + ", which this core leaves out (TS_COLOR_SPACES)\"\n#endif\n" + layers;
}

std::string blob_c_bytes(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  std::string s = "/* Placement of the bytes: define TS_BLOB_SECTION (a string, such as \".rodata.blobs\" or an\n"
                  "   external flash section of the linker script) and TS_BLOB_ALIGN (bytes, a power of two; the\n"
                  "   core needs 4) before this point, on the command line or before including this file. GCC and\n"
                  "   Clang syntax; with another compiler define TS_BLOB_ATTRIBUTES itself. */\n"
                  "#ifndef TS_BLOB_ATTRIBUTES\n#ifndef TS_BLOB_ALIGN\n#define TS_BLOB_ALIGN 4\n#endif\n"
                  "#if defined(__GNUC__) && defined(TS_BLOB_SECTION)\n"
                  "#define TS_BLOB_ATTRIBUTES __attribute__((section(TS_BLOB_SECTION), aligned(TS_BLOB_ALIGN)))\n"
                  "#elif defined(__GNUC__)\n#define TS_BLOB_ATTRIBUTES __attribute__((aligned(TS_BLOB_ALIGN)))\n"
                  "#else\n#define TS_BLOB_ATTRIBUTES\n#endif\n#endif\n\n"
                  "static const uint8_t " + name + "[" + std::to_string(bytes.size()) + "] TS_BLOB_ATTRIBUTES = {";
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i % 16 == 0) s += "\n ";
    char hex[8];
    std::snprintf(hex, sizeof hex, " 0x%02x,", bytes[i]);
    s += hex;
  }
  return s + "\n};\n";
}

std::string blob_c_descriptor(const core::Blob& blob, const CBlobSpec& spec) {
  const std::string& id = spec.symbol;
  return "\nextern const ts_blob_descriptor " + id + ";\nconst ts_blob_descriptor " + id + " = {\n  " + id +
         "_bytes, sizeof " + id + "_bytes,\n  " + std::to_string(blob.width) + ", " + std::to_string(blob.height) +
         ", " + std::to_string(spec.output_width) + ", " + std::to_string(spec.output_height) + ",\n  " +
         std::to_string(spec.tile_width) + ", " + std::to_string(spec.tile_height) + ", " +
         std::to_string(c_format(spec.format)) + ",\n  " + std::to_string(spec.tile_buffer_bytes) + ", " +
         std::to_string(spec.workspace_bytes) + "\n};\n";
}

std::string blob_c_tiles(const CBlobSpec& spec) {
  return (spec.tile_width ? std::to_string(spec.tile_width) : std::string("viewport-wide")) + " x " +
         (spec.tile_height ? std::to_string(spec.tile_height) : std::string("viewport-high"));
}

std::string blob_c_source(const std::vector<std::uint8_t>& bytes, const core::Blob& blob, const CBlobSpec& spec) {
  // The file repeats the header's guard: tie_c_pair adds the include of its own header (where its
  // name can be spelled in an #include) with the check that it is the one written with it.
  return "/* Generated by tripack from " + c_comment_safe(spec.source_name) +
         ". Do not edit. */\n#include \"tristream/tristream.h\"\n\n" +
         blob_c_guard(blob.method, blob.space, blob.layer_count, spec) + "\n" + blob_c_bytes(bytes, spec.symbol + "_bytes") +
         blob_c_descriptor(blob, spec);
}

std::string blob_c_header_opening(const std::string& prefix, const std::string& symbol) {
  const std::string guard = prefix + symbol + "_H", macro = c_upper(symbol);
  return "#ifndef " + guard + "\n#define " + guard + "\n\n#include \"tristream/tristream.h\"\n\n#ifdef " + macro +
         "_BYTES\n#error \"" + macro + "_BYTES is defined already: the header of another blob whose symbol differs from " +
         symbol + " only in case? Give one of them tripack --symbol.\"\n#endif\n";
}

std::string blob_c_header(const core::Blob& blob, const CBlobSpec& spec) {
  const std::string& id = spec.symbol;
  const std::string macro = c_upper(id);
  const BufferBounds bounds = buffer_upper_bounds(blob, spec.format, spec.output_width, spec.output_height,
                                                  spec.tile_width, spec.tile_height);
  return "/* Generated by tripack from " + c_comment_safe(spec.source_name) + ". Do not edit. */\n" +
         blob_c_header_opening("TRISTREAM_BLOB_", id) + blob_c_guard(blob.method, blob.space, blob.layer_count, spec) +
         "\n/* The blob's bytes (" + id + ".size): to size a copy of it, e.g. into RAM. */\n#define " + macro +
         "_BYTES " + std::to_string(blob.size) +
         "u\n\n/* Buffer sizes that suffice for every render of this blob in " +
         std::string(pixel_format_name(spec.format)) +
         "\n   with an output of at most " + std::to_string(spec.output_width) + " x " +
         std::to_string(spec.output_height) + ", any fit and viewport of it and tiles of at most " + blob_c_tiles(spec) +
         " pixels:\n   static buffers of these sizes are always big enough. The descriptor holds the exact figures\n"
         "   for the whole output in these tiles. */\n#define " + macro + "_TILE_BUFFER_MAX_BYTES " +
         std::to_string(bounds.tile_buffer_bytes) + "u\n#define " + macro + "_WORKSPACE_MAX_BYTES " +
         std::to_string(bounds.workspace_bytes) +
         "u\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\nextern const ts_blob_descriptor " + id +
         ";\n\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
}

bool is_includable_name(std::string_view name) {
  for (std::string_view bad : {"//", "/*", "??"})  // "??": a trigraph in C89
    if (name.find(bad) != std::string_view::npos) return false;
  if (name.empty()) return false;
  for (char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E || c == '"' || c == '\\' ||
        c == '\'')
      return false;
  return true;
}

void tie_c_pair(CPair& pair, const std::string& symbol, const std::string& header_name) {
  constexpr std::string_view core_include = "#include \"tristream/tristream.h\"\n";
  constexpr std::string_view header_end = "#endif\n";
  const std::size_t at = pair.source.find(core_include);
  if (at == std::string::npos || pair.header.size() < header_end.size() ||
      pair.header.compare(pair.header.size() - header_end.size(), header_end.size(), header_end) != 0)
    throw std::logic_error("tie_c_pair: not a pair tripack generated");
  auto crc = [](std::uint32_t c, const std::string& s) {
    return core::detail::crc32(c, reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
  };
  char hash[16];
  std::snprintf(hash, sizeof hash, "0x%08Xu", unsigned(crc(crc(0, pair.header), pair.source)));
  const std::string macro = c_upper(symbol) + "_PAIR_HASH";
  pair.header.insert(pair.header.size() - header_end.size(),
                     "/* Ties this header to the source tripack wrote with it, which refuses to compile beside\n"
                     "   another header. */\n#define " +
                         macro + " " + hash + "\n\n");
  std::string check;
  if (is_includable_name(header_name))
    check = "#include \"" + header_name + "\"\n#if !defined(" + macro + ") || " + macro + " != " + hash +
            "\n#error \"" + header_name +
            " is not the header tripack wrote with this source (another blob or other "
            "options): run tripack again, it writes both\"\n#endif\n";
  else
    check =
        "/* The header's name cannot be spelled in an #include: this source does not check that the header\n"
        "   beside it is its own (" +
        macro + "). */\n";
  pair.source.insert(at + core_include.size(), check);
}

}  // namespace tristream
