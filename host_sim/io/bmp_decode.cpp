// SPDX-License-Identifier: MIT
// BMP, uncompressed: the Windows headers of 40, 56, 108 and 124 bytes and OS/2's of 12; 1, 4 and 8
// bits through a palette, 16 and 32 bits through channel masks (BI_RGB's defaults or BI_BITFIELDS),
// 24 bits as B, G, R; rows bottom-up, or top-down for a negative height. RLE and embedded
// JPEG/PNG are refused. Every BMP is colour (3 channels), as stb_image read it before; alpha is
// dropped. A channel of n bits becomes 8 by repeating its bits (5 bits abcde: abcdeabc), as stb did.
// Every read is checked against the file's end.
#include <bit>
#include <cstdint>
#include <string>

#include "common/errors.h"
#include "io/image_decoders.h"

namespace tristream {
namespace {

class BmpBytes {
 public:
  BmpBytes(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  std::uint32_t u32(std::uint64_t at, const char* what) const { return std::uint32_t(le(at, 4, what)); }
  std::uint16_t u16(std::uint64_t at, const char* what) const { return std::uint16_t(le(at, 2, what)); }
  std::uint8_t u8(std::uint64_t at) const { return std::uint8_t(bytes_[at]); }  // in range: see need()

  // Throws unless bytes [at, at + count) are in the file.
  void need(std::uint64_t at, std::uint64_t count, const std::string& what) const {
    if (at > bytes_.size() || count > bytes_.size() - at)
      fail(std::min<std::uint64_t>(at, bytes_.size()), "expected " + what + ", found the end of the file");
  }

  [[noreturn]] void fail(std::uint64_t at, const std::string& message) const {
    throw DataError(path_ + ": byte " + std::to_string(at) + ": " + message);
  }

 private:
  std::uint64_t le(std::uint64_t at, int count, const char* what) const {
    need(at, std::uint64_t(count), what);
    std::uint64_t v = 0;
    for (int i = count - 1; i >= 0; --i) v = v << 8 | u8(at + std::uint64_t(i));
    return v;
  }

  std::string_view bytes_;
  const std::string& path_;
};

struct BmpHeader {
  std::uint64_t data_offset = 0, header_size = 0;
  std::int64_t width = 0, height = 0;  // height < 0: rows top-down
  unsigned bits = 0, compression = 0;
  std::uint32_t masks[3] = {0, 0, 0};  // R, G, B for 16 and 32 bits
  std::uint64_t palette_offset = 0, palette_entries = 0, palette_entry_bytes = 4;
};

constexpr unsigned bi_rgb = 0, bi_bitfields = 3;

void read_masks(const BmpBytes& in, BmpHeader& h) {
  if (h.compression == bi_bitfields) {
    // Version 4 and 5 headers hold the masks; a 40- or 56-byte header is followed by them.
    const std::uint64_t at = h.header_size >= 52 ? 14 + 40 : 14 + h.header_size;
    for (int c = 0; c < 3; ++c) h.masks[c] = in.u32(at + 4 * std::uint64_t(c), "a channel mask");
  } else if (h.bits == 16) {
    h.masks[0] = 0x7c00, h.masks[1] = 0x03e0, h.masks[2] = 0x001f;
  } else {
    h.masks[0] = 0xff0000, h.masks[1] = 0x00ff00, h.masks[2] = 0x0000ff;
  }
  for (std::uint32_t m : h.masks)
    if (m == 0 || std::popcount(m) != int(std::bit_width(m >> std::countr_zero(m))))
      in.fail(14 + 40, "expected contiguous, non-empty channel masks, found " + std::to_string(m));
}

BmpHeader read_header(const BmpBytes& in) {
  BmpHeader h;
  h.data_offset = in.u32(10, "the offset of the pixels");
  h.header_size = in.u32(14, "the size of the header");
  const std::uint64_t s = h.header_size;
  if (s != 12 && s != 40 && s != 56 && s != 108 && s != 124)
    in.fail(14, "expected a header of 12, 40, 56, 108 or 124 bytes, found " + std::to_string(s));
  in.need(14, s, "the whole header");
  h.width = s == 12 ? in.u16(18, "width") : std::int32_t(in.u32(18, "width"));
  h.height = s == 12 ? in.u16(20, "height") : std::int32_t(in.u32(22, "height"));
  const std::uint64_t planes_at = s == 12 ? 22 : 26;
  if (in.u16(planes_at, "planes") != 1) in.fail(planes_at, "expected 1 plane");
  h.bits = in.u16(planes_at + 2, "bits per pixel");
  h.compression = s == 12 ? bi_rgb : in.u32(30, "compression");
  if (h.bits != 1 && h.bits != 4 && h.bits != 8 && h.bits != 16 && h.bits != 24 && h.bits != 32)
    in.fail(planes_at + 2, "expected 1, 4, 8, 16, 24 or 32 bits per pixel, found " + std::to_string(h.bits));
  const bool masked = h.bits == 16 || h.bits == 32;
  if (!(h.compression == bi_rgb || (h.compression == bi_bitfields && masked)))
    in.fail(30, "expected uncompressed pixels (BI_RGB, or BI_BITFIELDS at 16 or 32 bits), found compression " +
                    std::to_string(h.compression) + " (RLE, JPEG and PNG in a BMP are not read)");
  h.palette_offset = 14 + s;
  if (masked) read_masks(in, h);
  if (h.bits <= 8) {
    const std::uint64_t used = s == 12 ? 0 : in.u32(46, "the palette size");
    h.palette_entries = used == 0 ? std::uint64_t(1) << h.bits : used;
    if (h.palette_entries > (std::uint64_t(1) << h.bits))
      in.fail(46,
              "expected at most " + std::to_string(1u << h.bits) + " palette entries, found " + std::to_string(used));
    h.palette_entry_bytes = s == 12 ? 3 : 4;
    in.need(h.palette_offset, h.palette_entries * h.palette_entry_bytes, "the palette");
  }
  return h;
}

// n bits to 8: below 8 by repeating them from the top, above 8 by keeping the top 8.
std::uint8_t widen(std::uint32_t value, int bits) {
  if (bits >= 8) return std::uint8_t(value >> (bits - 8));
  std::uint32_t out = 0;
  int filled = 0;
  for (; filled < 8; filled += bits) out = out << bits | value;
  return std::uint8_t(out >> (filled - 8));
}

std::uint8_t channel(std::uint32_t pixel, std::uint32_t mask) {
  const int shift = std::countr_zero(mask);
  return widen((pixel & mask) >> shift, std::popcount(mask));
}

void read_row(const BmpBytes& in, const BmpHeader& h, std::uint64_t at, std::uint8_t* out) {
  for (std::int64_t x = 0; x < h.width; ++x, out += 3) {
    if (h.bits <= 8) {
      const std::uint64_t bit = std::uint64_t(x) * h.bits;
      const unsigned index = (in.u8(at + bit / 8) >> (8 - h.bits - bit % 8)) & ((1u << h.bits) - 1);
      if (index >= h.palette_entries)
        in.fail(at + bit / 8, "expected a palette index below " + std::to_string(h.palette_entries) + ", found " +
                                  std::to_string(index));
      const std::uint64_t entry = h.palette_offset + index * h.palette_entry_bytes;  // B, G, R
      out[0] = in.u8(entry + 2), out[1] = in.u8(entry + 1), out[2] = in.u8(entry);
    } else if (h.bits == 24) {
      const std::uint64_t p = at + 3 * std::uint64_t(x);
      out[0] = in.u8(p + 2), out[1] = in.u8(p + 1), out[2] = in.u8(p);
    } else {
      const std::uint64_t p = at + std::uint64_t(x) * (h.bits / 8);
      std::uint32_t pixel = 0;
      for (unsigned i = h.bits / 8; i-- > 0;) pixel = pixel << 8 | in.u8(p + i);
      for (int c = 0; c < 3; ++c) out[c] = channel(pixel, h.masks[c]);
    }
  }
}

}  // namespace

Image decode_bmp(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  const BmpBytes in(bytes, path);
  const BmpHeader h = read_header(in);
  const std::uint64_t rows = std::uint64_t(h.height < 0 ? -h.height : h.height);
  check_image_size(path, 18, std::uint64_t(h.width < 0 ? 0 : h.width), rows, max_pixels);
  // Rows are padded to 4 bytes; the last row's padding may be missing.
  const std::uint64_t used = (std::uint64_t(h.width) * h.bits + 7) / 8, stride = (used + 3) / 4 * 4;
  in.need(h.data_offset, stride * (rows - 1) + used,
          "the pixels: " + std::to_string(rows) + " rows of " + std::to_string(stride) + " bytes from byte " +
              std::to_string(h.data_offset));
  Image image(int(h.width), int(rows), 3);
  for (std::uint64_t r = 0; r < rows; ++r) {
    const std::uint64_t y = h.height < 0 ? r : rows - 1 - r;
    read_row(in, h, h.data_offset + r * stride, image.pixels.data() + y * std::uint64_t(h.width) * 3);
  }
  return image;
}

}  // namespace tristream
