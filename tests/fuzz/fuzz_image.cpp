// SPDX-License-Identifier: MIT
// libFuzzer target: the image decoders (PNG through libpng, JPEG through libjpeg-turbo, BMP and PNM
// of our own) must accept or refuse any bytes with a DataError, never crash, hang or read out of
// bounds; an image they accept has the size it says and decodes the same twice.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "common/errors.h"
#include "io/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;  // large inputs add time, not paths
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // A small pixel limit: a header may claim any size, and the limit is what keeps that cheap.
  constexpr std::uint64_t max_pixels = 1 << 18;
  try {
    const tristream::Image image = tristream::decode_image(bytes, "fuzz.img", max_pixels);
    if (image.width < 1 || image.height < 1 || std::uint64_t(image.width) * std::uint64_t(image.height) > max_pixels ||
        (image.channels != 1 && image.channels != 3) ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
      std::abort();
    if (tristream::decode_image(bytes, "fuzz.img", max_pixels).pixels != image.pixels) std::abort();
  } catch (const tristream::DataError&) {
  }
  return 0;
}
