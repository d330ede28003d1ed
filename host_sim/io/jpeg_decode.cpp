// SPDX-License-Identifier: MIT
// JPEG through libjpeg-turbo's libjpeg API (fuzzed upstream by OSS-Fuzz, maintained in Debian).
// The libjpeg API rather than TurboJPEG: its error manager turns every corrupt-data warning into a
// refusal (TurboJPEG 2.1 decodes past them), tells running out of memory from bad data, and hands
// CMYK and YCCK over as CMYK for the conversion below.
//
// libjpeg reports errors by longjmp: the functions that call it (the phases below) hold only plain
// data, so no destructor is skipped; the C++ objects live in decode_jpeg.
//
// Pixels: grey as 1 channel, YCbCr and RGB as 3 (libjpeg's defaults: the accurate integer IDCT and
// fancy upsampling), CMYK and YCCK (Adobe's inverted form) multiplied out to RGB.
#include <csetjmp>
#include <cstddef>
#include <cstdio>  // jpeglib.h needs size_t and FILE declared first
#include <new>
#include <vector>

#include <jerror.h>
#include <jpeglib.h>

#include "common/errors.h"
#include "io/image_decoders.h"

namespace tristream {
namespace {

// More scans than any encoder writes (a progressive JPEG has about ten); each scan of a hostile
// file can make the decoder pass over the whole image again.
constexpr int max_scans = 500;

struct JpegErrors {
  jpeg_error_mgr manager;  // first: libjpeg hands its callbacks a pointer to it
  jpeg_progress_mgr progress;
  std::jmp_buf jump;
  bool out_of_memory;
  char message[JMSG_LENGTH_MAX];
};

JpegErrors& errors_of(j_common_ptr cinfo) { return *reinterpret_cast<JpegErrors*>(cinfo->err); }

void on_error_exit(j_common_ptr cinfo) {
  JpegErrors& errors = errors_of(cinfo);
  errors.out_of_memory = cinfo->err->msg_code == JERR_OUT_OF_MEMORY;
  (*cinfo->err->format_message)(cinfo, errors.message);
  std::longjmp(errors.jump, 1);
}

// A warning (level -1) is corrupt data that libjpeg would decode past, filling in what is missing:
// refused, except for metadata the pixels do not depend on. Trace messages (level >= 0) are ignored.
void on_emit_message(j_common_ptr cinfo, int level) {
  const int code = cinfo->err->msg_code;
  if (level < 0 && code != JWRN_JFIF_MAJOR && code != JWRN_BOGUS_ICC && code != JWRN_ADOBE_XFORM) on_error_exit(cinfo);
}

void on_progress(j_common_ptr cinfo) {
  if (cinfo->is_decompressor && reinterpret_cast<j_decompress_ptr>(cinfo)->input_scan_number > max_scans) {
    std::snprintf(errors_of(cinfo).message, JMSG_LENGTH_MAX, "more than %d scans", max_scans);
    std::longjmp(errors_of(cinfo).jump, 1);
  }
}

// Creates the decompressor and reads the markers up to the first scan. False when libjpeg failed.
bool read_header(jpeg_decompress_struct* cinfo, JpegErrors* errors, const unsigned char* data, unsigned long size) {
  if (setjmp(errors->jump)) return false;
  jpeg_create_decompress(cinfo);
  cinfo->progress = &errors->progress;
  jpeg_mem_src(cinfo, data, size);
  jpeg_read_header(cinfo, TRUE);
  return true;
}

// The pixels, `channels` (1, 3 or 4 for CMYK) samples each, into `out`.
bool read_pixels(jpeg_decompress_struct* cinfo, JpegErrors* errors, J_COLOR_SPACE space, unsigned char* out) {
  if (setjmp(errors->jump)) return false;
  cinfo->out_color_space = space;
  jpeg_start_decompress(cinfo);
  const std::size_t row_bytes = std::size_t(cinfo->output_width) * std::size_t(cinfo->output_components);
  while (cinfo->output_scanline < cinfo->output_height) {
    JSAMPROW row = out + std::size_t(cinfo->output_scanline) * row_bytes;
    jpeg_read_scanlines(cinfo, &row, 1);
  }
  jpeg_finish_decompress(cinfo);
  return true;
}

// Owns the decompressor (zeroed first, so that destroying one never created is safe).
struct JpegReader {
  jpeg_decompress_struct cinfo{};
  ~JpegReader() { jpeg_destroy_decompress(&cinfo); }
};

// Adobe's CMYK is stored inverted (255 = no ink): each of C, M, Y times K, scaled by 255, is R, G, B.
std::uint8_t times_k(unsigned value, unsigned k) {
  const unsigned t = value * k + 128;
  return std::uint8_t((t + (t >> 8)) >> 8);
}

}  // namespace

Image decode_jpeg(std::string_view bytes, const std::string& path, std::uint64_t max_pixels) {
  JpegErrors errors{};
  JpegReader reader;
  reader.cinfo.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = on_error_exit;
  errors.manager.emit_message = on_emit_message;
  errors.progress.progress_monitor = on_progress;
  const auto fail = [&] {
    if (errors.out_of_memory) throw std::bad_alloc();
    // Where libjpeg's source stood (the start of the marker segment or of the block row it was
    // reading), or the end for a file that ends early; past the end it reads an end marker of its own.
    const auto* next =
        reader.cinfo.src ? reinterpret_cast<const char*>(reader.cinfo.src->next_input_byte) : bytes.data();
    const bool inside =
        errors.manager.msg_code != JWRN_JPEG_EOF && next >= bytes.data() && next <= bytes.data() + bytes.size();
    throw DataError(path + ": byte " + std::to_string(inside ? std::size_t(next - bytes.data()) : bytes.size()) +
                    ": not a valid JPEG: " + errors.message);
  };

  if (!read_header(&reader.cinfo, &errors, reinterpret_cast<const unsigned char*>(bytes.data()),
                   static_cast<unsigned long>(bytes.size())))
    fail();
  check_image_size(path, 0, reader.cinfo.image_width, reader.cinfo.image_height, max_pixels);

  const J_COLOR_SPACE stored = reader.cinfo.jpeg_color_space;
  const bool cmyk = stored == JCS_CMYK || stored == JCS_YCCK;
  const J_COLOR_SPACE space = cmyk ? JCS_CMYK : reader.cinfo.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
  const int channels = space == JCS_GRAYSCALE ? 1 : 3;
  Image image(int(reader.cinfo.image_width), int(reader.cinfo.image_height), channels);
  std::vector<unsigned char> ink(cmyk ? image.pixels.size() / 3 * 4 : 0);
  if (!read_pixels(&reader.cinfo, &errors, space, cmyk ? ink.data() : image.pixels.data())) fail();

  for (std::size_t p = 0, n = ink.size() / 4; p < n; ++p)
    for (std::size_t c = 0; c < 3; ++c) image.pixels[3 * p + c] = times_k(ink[4 * p + c], ink[4 * p + 3]);
  return image;
}

}  // namespace tristream
