/* SPDX-License-Identifier: MIT */
#pragma once
// The golden renders: blobs packed from the .tri files here, rendered by the core with these
// parameters, kept as PNG. Shared by the host test, the ARM (qemu) run and update_golden.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tristream/render.h"

namespace tristream::golden {

struct Case {
  const char* name;    // <name>.png
  const char* tri;     // <tri>.tri, packed to <tri>-<method>.bin
  const char* method;  // bilinear | zienkiewicz
  core::PixelFormat format;
  int tile_width, tile_height;
  bool dither;
  int out_width, out_height;
  core::Rect viewport;
};

inline const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"grey-bilinear-l8-tiles32", "grey", "bilinear", core::PixelFormat::l8, 32, 32, false, 0, 0, {}},
      {"rgb-zienkiewicz-rgb888-tiles13x7", "rgb", "zienkiewicz", core::PixelFormat::rgb888, 13, 7, false, 0, 0, {}},
      {"rgb-bilinear-rgb565be-dither-240x160",
       "rgb",
       "bilinear",
       core::PixelFormat::rgb565_be,
       16,
       16,
       true,
       240,
       160,
       {}},
      {"ycbcr-zienkiewicz-xrgb8888-bands-viewport",
       "ycbcr-layers",
       "zienkiewicz",
       core::PixelFormat::xrgb8888,
       0,
       8,
       false,
       0,
       0,
       {20, 10, 170, 110}},
      {"ycbcr-bilinear-rgb565le-full", "ycbcr-layers", "bilinear", core::PixelFormat::rgb565_le, 0, 0, false, 0, 0, {}},
      // Direct RGB spans of bilinear (the SSE2 and the scalar pixel loops must agree).
      {"rgb-bilinear-rgb888-tiles32", "rgb", "bilinear", core::PixelFormat::rgb888, 32, 32, false, 0, 0, {}},
      {"rgb-bilinear-rgb565le-tiles24x16", "rgb", "bilinear", core::PixelFormat::rgb565_le, 24, 16, false, 0, 0, {}},
      {"rgb-bilinear-xrgb8888-full-300x200", "rgb", "bilinear", core::PixelFormat::xrgb8888, 0, 0, false, 300, 200, {}},
      // Direct RGB rows of zienkiewicz (forward differenced and per pixel) in the packed formats.
      {"rgb-zienkiewicz-rgb565be-tiles32", "rgb", "zienkiewicz", core::PixelFormat::rgb565_be, 32, 32, false, 0, 0, {}},
      {"rgb-zienkiewicz-xrgb8888-full-384x256",
       "rgb",
       "zienkiewicz",
       core::PixelFormat::xrgb8888,
       0,
       0,
       false,
       384,
       256,
       {}},
  };
  return all;
}

inline std::string blob_name(const Case& c) { return std::string(c.tri) + "-" + c.method + ".bin"; }

// An 8-bit image decoded from a rendered frame: grey for L8, RGB otherwise.
struct Pixels {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> data;
};

namespace detail {

struct Frame {
  core::Rect view;
  int bpp;
  std::vector<std::uint8_t> bytes;
  int width;
};

inline void collect(void* context, const core::Tile* tile) {
  Frame* f = static_cast<Frame*>(context);
  for (int y = tile->rect.y0; y < tile->rect.y1; ++y)
    std::memcpy(f->bytes.data() + (std::size_t(y - f->view.y0) * f->width + (tile->rect.x0 - f->view.x0)) * f->bpp,
                tile->pixels + std::size_t(y - tile->rect.y0) * tile->stride, std::size_t(tile->rect.width()) * f->bpp);
}

}  // namespace detail

// Renders a case from its blob bytes; returns the status of the first failing core call.
inline core::Status render(const Case& c, const std::vector<std::uint8_t>& blob_bytes, Pixels* out) {
  core::Blob blob;
  core::Status s = core::open_blob(blob_bytes.data(), blob_bytes.size(), &blob);
  if (s != core::Status::ok) return s;
  core::RenderParams p;
  p.output_width = std::uint16_t(c.out_width);
  p.output_height = std::uint16_t(c.out_height);
  p.viewport = c.viewport;
  p.tile_width = std::uint16_t(c.tile_width);
  p.tile_height = std::uint16_t(c.tile_height);
  p.format = c.format;
  p.dither = c.dither;
  p.background[0] = 255, p.background[1] = 0, p.background[2] = 255;
  std::size_t tile = 0, work = 0;
  if ((s = core::tile_buffer_size(blob, p, &tile)) != core::Status::ok) return s;
  if ((s = core::workspace_size(blob, p, &work)) != core::Status::ok) return s;
  std::vector<std::uint8_t> tile_buffer(tile), workspace(work);
  detail::Frame f;
  f.view = c.viewport.empty() ? core::Rect{0, 0, c.out_width ? c.out_width : blob.width,
                                           c.out_height ? c.out_height : blob.height}
                              : c.viewport;
  f.bpp = core::bytes_per_pixel(c.format);
  f.width = f.view.width();
  f.bytes.assign(std::size_t(f.view.width()) * f.view.height() * f.bpp, 0);
  s = core::render(blob, p, tile_buffer.data(), tile, workspace.data(), work, detail::collect, &f);
  if (s != core::Status::ok) return s;
  out->width = f.view.width();
  out->height = f.view.height();
  out->channels = c.format == core::PixelFormat::l8 ? 1 : 3;
  out->data.assign(std::size_t(out->width) * out->height * out->channels, 0);
  for (std::size_t i = 0; i < std::size_t(out->width) * out->height; ++i) {
    const std::uint8_t* p8 = f.bytes.data() + i * f.bpp;
    std::uint8_t* q = out->data.data() + i * out->channels;
    switch (c.format) {
      case core::PixelFormat::l8: q[0] = p8[0]; break;
      case core::PixelFormat::rgb888: q[0] = p8[0], q[1] = p8[1], q[2] = p8[2]; break;
      case core::PixelFormat::xrgb8888: q[0] = p8[2], q[1] = p8[1], q[2] = p8[0]; break;
      default: {
        const unsigned w = c.format == core::PixelFormat::rgb565_le ? unsigned(p8[0] | p8[1] << 8)
                                                                     : unsigned(p8[1] | p8[0] << 8);
        q[0] = std::uint8_t((w >> 11) * 255 / 31);
        q[1] = std::uint8_t(((w >> 5) & 63) * 255 / 63);
        q[2] = std::uint8_t((w & 31) * 255 / 31);
      }
    }
  }
  return core::Status::ok;
}

}  // namespace tristream::golden
