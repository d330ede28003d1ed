// SPDX-License-Identifier: MIT
#include "core_bridge/pixel_format_names.h"

#include <array>

#include "common/errors.h"
#include "common/name_list.h"

namespace tristream {
namespace {

constexpr std::array formats{
    PixelFormatName{"l8", core::PixelFormat::l8},
    PixelFormatName{"rgb888", core::PixelFormat::rgb888},
    PixelFormatName{"rgb565le", core::PixelFormat::rgb565_le},
    PixelFormatName{"rgb565be", core::PixelFormat::rgb565_be},
    PixelFormatName{"xrgb8888", core::PixelFormat::xrgb8888},
};

}  // namespace

std::span<const PixelFormatName> pixel_format_names() { return formats; }

std::vector<std::string> pixel_format_name_list() {
  std::vector<std::string> names;
  for (const PixelFormatName& f : formats) names.emplace_back(f.name);
  return names;
}

std::string_view pixel_format_name(core::PixelFormat format) {
  for (const PixelFormatName& f : formats)
    if (f.format == format) return f.name;
  return format == core::PixelFormat::coverage8 ? "coverage8" : "?";
}

core::PixelFormat parse_pixel_format(std::string_view name) {
  for (const PixelFormatName& f : formats)
    if (f.name == name) return f.format;
  throw UsageError("pixel format must be " + name_list(formats) + ", not \"" + std::string(name) + "\"");
}

}  // namespace tristream
