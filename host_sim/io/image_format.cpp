// SPDX-License-Identifier: MIT
#include "io/image_format.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "common/errors.h"

namespace tristream {
namespace {

bool starts_with(std::string_view bytes, std::string_view prefix) { return bytes.substr(0, prefix.size()) == prefix; }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

// Formats other programs read that these tools refuse (stb_image, which read images before, took
// several of them; the README promises none of them).
std::string recognised_other_format(std::string_view bytes) {
  if (starts_with(bytes, "GIF87a") || starts_with(bytes, "GIF89a")) return "a GIF image";
  if (starts_with(bytes, "8BPS")) return "a PSD (Photoshop) image";
  if (starts_with(bytes, "#?RADIANCE") || starts_with(bytes, "#?RGBE")) return "an HDR (Radiance) image";
  if (starts_with(bytes, std::string_view("\x53\x80\xf6\x34", 4))) return "a PIC (Softimage) image";
  if (starts_with(bytes, "RIFF") && bytes.size() >= 12 && bytes.substr(8, 4) == "WEBP") return "a WebP image";
  if (starts_with(bytes, std::string_view("II*\0", 4)) || starts_with(bytes, std::string_view("MM\0*", 4)))
    return "a TIFF image";
  if (bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == '1' || bytes[1] == '4') && is_space(bytes[2]))
    return "a PBM (bitmap) image";
  if (starts_with(bytes, "P7\n")) return "a PAM image";
  // TGA has no signature: its footer, when present, names it.
  if (bytes.size() >= 18 && bytes.substr(bytes.size() - 18) == std::string_view("TRUEVISION-XFILE.\0", 18))
    return "a TGA image";
  return "";
}

std::string first_bytes_in_hex(std::string_view bytes) {
  if (bytes.empty()) return "an empty file";
  std::string hex = "an unknown format (first bytes";
  for (std::size_t i = 0; i < std::min<std::size_t>(bytes.size(), 8); ++i) {
    char byte[4];
    std::snprintf(byte, sizeof byte, " %02x", unsigned(static_cast<unsigned char>(bytes[i])));
    hex += byte;
  }
  return hex + ")";
}

}  // namespace

ImageFormat detect_image_format(std::string_view bytes) {
  if (starts_with(bytes, "\x89PNG\r\n\x1a\n")) return ImageFormat::png;
  if (starts_with(bytes, "\xff\xd8\xff")) return ImageFormat::jpeg;
  if (starts_with(bytes, "BM")) return ImageFormat::bmp;
  if (bytes.size() >= 3 && bytes[0] == 'P' && std::string_view("2356").find(bytes[1]) != std::string_view::npos &&
      is_space(bytes[2]))
    return ImageFormat::pnm;
  return ImageFormat::unknown;
}

void refuse_image_format(std::string_view bytes, const std::string& path) {
  std::string found = recognised_other_format(bytes);
  if (found.empty()) found = first_bytes_in_hex(bytes);
  else found += ", which is not read";
  throw DataError(path + ": byte 0: expected " + readable_image_formats + ", found " + found);
}

}  // namespace tristream
