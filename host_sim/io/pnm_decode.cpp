// SPDX-License-Identifier: MIT
// PNM: PGM (P2 text, P5 binary: 1 channel) and PPM (P3 text, P6 binary: 3 channels), maxval 1 to
// 65535 (two bytes a sample, big-endian, above 255). The header is the magic, width, height and
// maxval separated by white space and '#' comments, then exactly one white-space character before
// binary samples. Samples become 8 bits: maxval 255 as they are, 65535 by their high byte (as a
// 16-bit PNG's), any other by value * 255 / maxval rounded to nearest. PBM and PAM are not read.
#include <cstdint>
#include <string>

#include "common/errors.h"
#include "io/image_decoders.h"

namespace tristream {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string quoted(char c) {
  std::string q(3, '\'');
  q[1] = c;
  return q;
}

class PnmReader {
 public:
  PnmReader(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}

  // Skips white space and, when `comments`, '#' comments to the end of their line.
  void skip_space(bool comments) {
    while (at_ < bytes_.size()) {
      if (is_space(bytes_[at_])) ++at_;
      else if (comments && bytes_[at_] == '#')
        while (at_ < bytes_.size() && bytes_[at_] != '\n' && bytes_[at_] != '\r') ++at_;
      else break;
    }
  }

  // A decimal number of at most `max`, after white space (and comments in the header).
  std::uint64_t number(const std::string& what, std::uint64_t max, bool comments) {
    skip_space(comments);
    const std::uint64_t start = at_;
    std::uint64_t v = 0;
    while (at_ < bytes_.size() && is_digit(bytes_[at_])) {
      v = v * 10 + std::uint64_t(bytes_[at_++] - '0');
      if (v > max) fail(start, "expected " + what + " of at most " + std::to_string(max) + ", found a larger number");
    }
    if (at_ == start)
      fail(start, "expected " + what + ", found " +
                      (at_ < bytes_.size() ? quoted(bytes_[at_]) : std::string("the end of the file")));
    if (at_ < bytes_.size() && !is_space(bytes_[at_]) && bytes_[at_] != '#')
      fail(at_, "expected white space after " + what + ", found " + quoted(bytes_[at_]));
    return v;
  }

  // The single white-space character between the header and binary samples.
  void end_header() {
    if (at_ >= bytes_.size() || !is_space(bytes_[at_]))
      fail(at_, "expected one white-space character before the samples");
    ++at_;
  }

  std::uint64_t binary_sample(int bytes_per_sample, std::uint64_t maxval) {
    if (std::uint64_t(bytes_per_sample) > bytes_.size() - at_)
      fail(at_, "expected a sample, found the end of the file");
    std::uint64_t v = static_cast<unsigned char>(bytes_[at_]);
    if (bytes_per_sample == 2) v = v << 8 | static_cast<unsigned char>(bytes_[at_ + 1]);
    if (v > maxval)
      fail(at_, "expected a sample of at most " + std::to_string(maxval) + ", found " + std::to_string(v));
    at_ += std::uint64_t(bytes_per_sample);
    return v;
  }

  std::uint64_t position() const { return at_; }
  void seek(std::uint64_t at) { at_ = at; }

  [[noreturn]] void fail(std::uint64_t at, const std::string& message) const {
    throw DataError(path_ + ": byte " + std::to_string(at) + ": " + message);
  }

 private:
  std::string_view bytes_;
  const std::string& path_;
  std::uint64_t at_ = 0;
};

std::uint8_t to_8_bits(std::uint64_t v, std::uint64_t maxval) {
  if (maxval == 255) return std::uint8_t(v);
  if (maxval == 65535) return std::uint8_t(v >> 8);
  return std::uint8_t((v * 255 + maxval / 2) / maxval);
}

}  // namespace

Image decode_pnm(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  PnmReader in(bytes, path);
  if (bytes.size() < 3 || bytes[0] != 'P' || std::string_view("2356").find(bytes[1]) == std::string_view::npos)
    in.fail(0, "expected P2, P3, P5 or P6");
  const char kind = bytes[1];
  const bool text = kind == '2' || kind == '3';
  const int channels = kind == '2' || kind == '5' ? 1 : 3;
  in.seek(2);
  const std::uint64_t header_width_at = in.position();
  const std::uint64_t width = in.number("the width", UINT32_MAX, true);
  const std::uint64_t height = in.number("the height", UINT32_MAX, true);
  check_image_size(path, header_width_at, width, height, max_pixels);
  const std::uint64_t maxval = in.number("the maximum value", 65535, true);
  if (maxval == 0) in.fail(in.position() - 1, "expected a maximum value of 1 to 65535, found 0");
  if (!text) in.end_header();

  Image image(int(width), int(height), channels);
  const int bytes_per_sample = maxval > 255 ? 2 : 1;
  if (!text && std::uint64_t(bytes_per_sample) * image.pixels.size() > bytes.size() - in.position())
    in.fail(in.position(), "expected " + std::to_string(image.pixels.size()) + " samples of " +
                               std::to_string(bytes_per_sample) + " byte(s), found " +
                               std::to_string(bytes.size() - in.position()) + " bytes");
  for (std::uint8_t& p : image.pixels) {
    if (text) in.skip_space(false);
    const std::uint64_t at = in.position();
    const std::uint64_t v = text ? in.number("a sample", 65535, false) : in.binary_sample(bytes_per_sample, maxval);
    if (v > maxval)
      in.fail(at, "expected a sample of at most " + std::to_string(maxval) + ", found " + std::to_string(v));
    p = to_8_bits(v, maxval);
  }
  return image;
}

}  // namespace tristream
