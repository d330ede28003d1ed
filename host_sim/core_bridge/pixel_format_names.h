/* SPDX-License-Identifier: MIT */
#pragma once
// The names of the core's pixel formats, one table (pixel_format_names.cpp) that every option,
// manifest and printer uses: "l8", "rgb888", "rgb565le", "rgb565be", "xrgb8888".
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tristream/pixel_format.h"

namespace tristream {

struct PixelFormatName {
  std::string_view name;
  core::PixelFormat format;
};

// The formats a tool names, in the order of tristream.h (TS_L8 ... TS_XRGB8888). coverage8, a
// test format without a C value, is not one of them.
std::span<const PixelFormatName> pixel_format_names();
// The names alone, in that order (for CLI11's IsMember and a manifest's one-of check).
std::vector<std::string> pixel_format_name_list();
// The name of a format of the table; "coverage8" for the test format.
std::string_view pixel_format_name(core::PixelFormat format);
// The format of a name of the table; throws UsageError listing the names otherwise.
core::PixelFormat parse_pixel_format(std::string_view name);

}  // namespace tristream
