/* SPDX-License-Identifier: MIT */
#pragma once
// Limits the host tools check before they allocate, so that a small hostile input cannot ask for
// gigabytes (README "Limits"). Each is refused with a message that names it.
#include <cstdint>

namespace tristream::limits {

// Largest input file read whole (.tri, images): 1 GiB. Exit 65 when exceeded.
constexpr std::uint64_t max_input_bytes = std::uint64_t(1) << 30;

// Largest image side in a .tri file (and so of an image triencode accepts).
constexpr long max_image_side = 65535;

// Most pixels of an image read (PNG, JPEG, ...) and of a render (the .tri size, or --width x
// --height): 2^25 = 33,554,432, e.g. 8192 x 4096. A reference render holds a double per pixel
// and channel, so a colour render of this size needs about 0.8 GB.
constexpr std::uint64_t max_image_pixels = std::uint64_t(1) << 25;

// Most pixels of an image triencode encodes: 2^24 = 16,777,216, e.g. 4096 x 4096 (the encoder
// keeps several planes of doubles per pixel). Its sides are also at most max_image_side.
constexpr std::uint64_t max_encode_pixels = std::uint64_t(1) << 24;

}  // namespace tristream::limits
