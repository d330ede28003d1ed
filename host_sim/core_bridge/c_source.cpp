// SPDX-License-Identifier: MIT
#include "core_bridge/c_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "common/errors.h"
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
    "using", "virtual", "wchar_t", "xor", "xor_eq", "main"};

std::string upper(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Text for a C comment: no "*/" and only printable ASCII.
std::string comment_safe(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E) c = '?';
  for (std::size_t at; (at = s.find("*/")) != std::string::npos;) s[at + 1] = '?';
  return s;
}

std::size_t round_up(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

// The compile-time refusals: a core of another precision, without the blob's method, colour space
// or layering, or without the descriptor's format.
std::string guard(const core::Blob& blob, const CBlobSpec& spec) {
  const int method_bit = blob.method == core::Method::zienkiewicz ? 2 : 1;
  const std::string method = blob.method == core::Method::zienkiewicz ? "zienkiewicz" : "bilinear";
  const std::string space = blob.space == core::ColorSpace::grey  ? "grey"
                            : blob.space == core::ColorSpace::rgb ? "RGB"
                                                                  : "YCbCr";
  const std::string layers =
      blob.layer_count > 1 ? "#if !TS_LAYERED\n#error \"" + spec.symbol +
                                 ": the blob has a mesh per channel, which this core leaves out (TS_LAYERED)\"\n#endif\n"
                           : std::string();
  const std::string format(format_name(spec.format));
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
         "#if !(TS_COLOR_SPACES & " + std::to_string(1 << int(blob.space)) + ")\n#error \"" + spec.symbol +
         ": the blob is " + space + ", which this core leaves out (TS_COLOR_SPACES)\"\n#endif\n" + layers;
}

}  // namespace

bool is_blob_symbol(std::string_view name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  if (name[0] == '_' && name.size() > 1 && (name[1] == '_' || std::isupper(static_cast<unsigned char>(name[1]))))
    return false;
  if (name.find("__") != std::string_view::npos) return false;  // reserved in C++
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
  if (!is_blob_symbol(id)) id = "blob_" + id;
  if (!is_blob_symbol(id)) id = "blob";
  return id;
}

BufferBounds buffer_upper_bounds(const core::Blob& blob, core::PixelFormat format, int width, int height,
                                 int tile_width, int tile_height) {
  const std::size_t tw = std::size_t(tile_width > 0 ? std::min(tile_width, width) : width);
  const std::size_t th = std::size_t(tile_height > 0 ? std::min(tile_height, height) : height);
  constexpr std::size_t alignment = 8;  // firmware_core/src/workspace_layout.h workspace_alignment
  std::size_t scratch = 0;
  if (blob.layer_count > 1 && format != core::PixelFormat::coverage8)
    scratch = round_up(tw * th * 3 * sizeof(std::int16_t), alignment);
  std::uint32_t triangles = 0;
  for (int l = 0; l < blob.layer_count; ++l) triangles = std::max(triangles, blob.layers[l].triangle_count);
  const std::size_t bitmap = round_up(triangles, 32) / 8;
  return {tw * th * std::size_t(core::bytes_per_pixel(format)),
          alignment + scratch + std::size_t(blob.layer_count) * bitmap};
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

std::string_view format_name(core::PixelFormat format) {
  switch (format) {
    case core::PixelFormat::l8: return "l8";
    case core::PixelFormat::rgb888: return "rgb888";
    case core::PixelFormat::rgb565_le: return "rgb565le";
    case core::PixelFormat::rgb565_be: return "rgb565be";
    case core::PixelFormat::xrgb8888: return "xrgb8888";
    case core::PixelFormat::coverage8: return "coverage8";
  }
  return "?";
}

std::string blob_c_source(const std::vector<std::uint8_t>& bytes, const core::Blob& blob, const CBlobSpec& spec) {
  const std::string& id = spec.symbol;
  // The file includes only the core's header (not its own, whose name may not be spellable in an
  // #include), and repeats the header's guard.
  std::string s = "/* Generated by tripack from " + comment_safe(spec.source_name) +
                  ". Do not edit. */\n#include \"tristream/tristream.h\"\n\n" + guard(blob, spec) +
                  "\n/* Placement of the bytes: define TS_BLOB_SECTION (a string, such as \".rodata.blobs\" or an\n"
                  "   external flash section of the linker script) and TS_BLOB_ALIGN (bytes, a power of two; the\n"
                  "   core needs 4) before this point, on the command line or before including this file. GCC and\n"
                  "   Clang syntax; with another compiler define TS_BLOB_ATTRIBUTES itself. */\n"
                  "#ifndef TS_BLOB_ATTRIBUTES\n#ifndef TS_BLOB_ALIGN\n#define TS_BLOB_ALIGN 4\n#endif\n"
                  "#if defined(__GNUC__) && defined(TS_BLOB_SECTION)\n"
                  "#define TS_BLOB_ATTRIBUTES __attribute__((section(TS_BLOB_SECTION), aligned(TS_BLOB_ALIGN)))\n"
                  "#elif defined(__GNUC__)\n#define TS_BLOB_ATTRIBUTES __attribute__((aligned(TS_BLOB_ALIGN)))\n"
                  "#else\n#define TS_BLOB_ATTRIBUTES\n#endif\n#endif\n\n"
                  "static const uint8_t " + id + "_bytes[" + std::to_string(bytes.size()) + "] TS_BLOB_ATTRIBUTES = {";
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i % 16 == 0) s += "\n ";
    char hex[8];
    std::snprintf(hex, sizeof hex, " 0x%02x,", bytes[i]);
    s += hex;
  }
  s += "\n};\n\nextern const ts_blob_descriptor " + id + ";\nconst ts_blob_descriptor " + id + " = {\n  " + id +
       "_bytes, sizeof " + id + "_bytes,\n  " + std::to_string(blob.width) + ", " + std::to_string(blob.height) +
       ", " + std::to_string(spec.output_width) + ", " + std::to_string(spec.output_height) + ",\n  " +
       std::to_string(spec.tile_width) + ", " + std::to_string(spec.tile_height) + ", " +
       std::to_string(c_format(spec.format)) + ",\n  " + std::to_string(spec.tile_buffer_bytes) + ", " +
       std::to_string(spec.workspace_bytes) + "\n};\n";
  return s;
}

std::string blob_c_header(const core::Blob& blob, const CBlobSpec& spec) {
  const std::string& id = spec.symbol;
  const std::string macro = upper(id);
  const std::string guard_macro = "TRISTREAM_BLOB_" + macro + "_H";
  const BufferBounds bounds = buffer_upper_bounds(blob, spec.format, spec.output_width, spec.output_height,
                                                  spec.tile_width, spec.tile_height);
  const std::string tiles = (spec.tile_width ? std::to_string(spec.tile_width) : std::string("viewport-wide")) +
                            " x " +
                            (spec.tile_height ? std::to_string(spec.tile_height) : std::string("viewport-high"));
  return "/* Generated by tripack from " + comment_safe(spec.source_name) + ". Do not edit. */\n#ifndef " +
         guard_macro + "\n#define " + guard_macro + "\n\n#include \"tristream/tristream.h\"\n\n" + guard(blob, spec) +
         "\n/* Buffer sizes that suffice for every render of this blob in " + std::string(format_name(spec.format)) +
         "\n   with an output of at most " + std::to_string(spec.output_width) + " x " +
         std::to_string(spec.output_height) + ", any fit and viewport of it and tiles of at most " + tiles +
         " pixels:\n   static buffers of these sizes are always big enough. The descriptor holds the exact figures\n"
         "   for the whole output in these tiles. */\n#define " + macro + "_TILE_BUFFER_MAX_BYTES " +
         std::to_string(bounds.tile_buffer_bytes) + "u\n#define " + macro + "_WORKSPACE_MAX_BYTES " +
         std::to_string(bounds.workspace_bytes) +
         "u\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\nextern const ts_blob_descriptor " + id +
         ";\n\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
}

}  // namespace tristream
