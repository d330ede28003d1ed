// SPDX-License-Identifier: MIT
// PNG through libpng (fuzzed upstream by OSS-Fuzz, maintained in Debian). libpng reports errors by
// longjmp: the functions that call it (the phases below) hold only plain data, so no destructor is
// skipped, and the C++ objects live in decode_png, which libpng never jumps out of.
//
// Pixels: palette to RGB, grey below 8 bits scaled to 8 (bits repeated), 16 bits to their high
// byte, alpha and tRNS dropped, gamma and colour profiles ignored. Chunk CRCs and zlib's Adler-32
// are checked (libpng's defaults): a damaged chunk is refused.
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "common/errors.h"
#include "io/image_decoders.h"

namespace tristream {
namespace {

// What libpng's callbacks share with the decoder.
struct PngSource {
  const unsigned char* data;
  std::size_t size;
  std::size_t position;  // bytes libpng has read
  bool out_of_memory;
  char message[160];
};

PngSource& source_of(png_structp png) { return *static_cast<PngSource*>(png_get_error_ptr(png)); }

void on_error(png_structp png, png_const_charp message) {
  std::snprintf(source_of(png).message, sizeof source_of(png).message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}  // ancillary chunks libpng skips: nothing the pixels need

void on_read(png_structp png, png_bytep out, std::size_t count) {
  PngSource& source = source_of(png);
  if (count > source.size - source.position) png_error(png, "the file ends early");
  std::memcpy(out, source.data + source.position, count);
  source.position += count;
}

png_voidp on_malloc(png_structp png, png_alloc_size_t bytes) {
  void* p = std::malloc(bytes);
  if (p == nullptr) static_cast<PngSource*>(png_get_mem_ptr(png))->out_of_memory = true;
  return p;
}

void on_free(png_structp, png_voidp p) { std::free(p); }

struct PngShape {
  png_uint_32 width = 0, height = 0;
  int channels = 0;  // after the transformations: 1 to 4 samples of 8 bits
};

// Reads the chunks up to the first IDAT. False when libpng failed (its message in the source).
bool read_header(png_structp png, png_infop info, PngShape* shape) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  shape->width = png_get_image_width(png, info);
  shape->height = png_get_image_height(png, info);
  return true;
}

bool set_transformations(png_structp png, png_infop info, PngShape* shape) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_expand(png);  // palette to RGB, grey of 1, 2 or 4 bits to 8, tRNS to an alpha channel
  png_set_strip_16(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  shape->channels = png_get_channels(png, info);
  return png_get_bit_depth(png, info) == 8 && png_get_rowbytes(png, info) == png_size_t(shape->channels) * shape->width;
}

bool read_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  return true;
}

// Owns libpng's structures; destroys them on every path out of decode_png.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

[[noreturn]] void fail(const PngSource& source, const std::string& path) {
  if (source.out_of_memory) throw std::bad_alloc();
  throw DataError(path + ": byte " + std::to_string(source.position) + ": not a valid PNG: " +
                  (source.message[0] ? source.message : "a pixel layout libpng does not convert to 8 bits"));
}

// The size in IHDR, checked before libpng reads further: a header that claims too many pixels is
// refused even when the file ends right after it. libpng checks the same chunk again.
void check_header_size(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  if (bytes.size() < 24 || bytes.substr(12, 4) != "IHDR") return;
  auto be32 = [&](std::size_t at) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  check_image_size(path, 16, be32(16), be32(20), max_pixels);
}

}  // namespace

Image decode_png(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  check_header_size(bytes, path, max_pixels);
  PngSource source{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0, false, {}};
  PngReader reader;
  reader.png =
      png_create_read_struct_2(PNG_LIBPNG_VER_STRING, &source, on_error, on_warning, &source, on_malloc, on_free);
  if (reader.png == nullptr) throw std::bad_alloc();
  reader.info = png_create_info_struct(reader.png);
  if (reader.info == nullptr) throw std::bad_alloc();
  png_set_read_fn(reader.png, &source, on_read);

  PngShape shape;
  if (!read_header(reader.png, reader.info, &shape)) fail(source, path);
  check_image_size(path, 16, shape.width, shape.height, max_pixels);
  if (!set_transformations(reader.png, reader.info, &shape)) fail(source, path);

  const int out_channels = shape.channels <= 2 ? 1 : 3;
  Image image(int(shape.width), int(shape.height), out_channels);
  const std::size_t row_bytes = std::size_t(shape.width) * shape.channels;
  // Rows go straight into the image when no alpha has to be dropped.
  std::vector<png_byte> decoded(shape.channels == out_channels ? 0 : row_bytes * shape.height);
  png_byte* base = decoded.empty() ? image.pixels.data() : decoded.data();
  std::vector<png_bytep> rows(shape.height);
  for (png_uint_32 y = 0; y < shape.height; ++y) rows[y] = base + y * row_bytes;
  if (!read_rows(reader.png, rows.data())) fail(source, path);

  if (!decoded.empty()) {
    std::size_t out = 0;
    for (std::size_t in = 0; in < decoded.size(); in += std::size_t(shape.channels))
      for (int c = 0; c < out_channels; ++c) image.pixels[out++] = decoded[in + std::size_t(c)];
  }
  return image;
}

}  // namespace tristream
