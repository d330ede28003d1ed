// SPDX-License-Identifier: MIT
#include "core_bridge/render_core.h"

#include <cstring>
#include <string>

#include "common/activity.h"
#include "common/errors.h"
#include "core_bridge/blob_error.h"
#include "core_bridge/pack.h"
#include "frame_plan.h"

namespace tristream {

namespace {

struct Assembly {
  CoreFrame* frame;
  core::Rect view;
  int bpp;
};

void collect(void* context, const core::Tile* tile) {
  Assembly* a = static_cast<Assembly*>(context);
  CoreFrame& f = *a->frame;
  const std::size_t row = std::size_t(tile->rect.width()) * a->bpp;
  for (int y = tile->rect.y0; y < tile->rect.y1; ++y) {
    const std::uint8_t* src = tile->pixels + std::size_t(y - tile->rect.y0) * tile->stride;
    std::uint8_t* dst = f.bytes.data() +
                        (std::size_t(y - a->view.y0) * f.width + (tile->rect.x0 - a->view.x0)) * a->bpp;
    std::memcpy(dst, src, row);
  }
  ++f.tiles;
}

// The core refuses, with bad_params alone, a fill whose picture reaches beyond its coordinate
// budget (src/frame_plan.h, docs/FIXED_POINT.md): drawing positions below TS_MAX_DIMENSION pixels.
// The same arithmetic here names the limit and the option.
void check_coordinate_budget(const core::BlobInfo& blob, const core::RenderParams& p) {
  namespace d = core::detail;
  constexpr int max = core::config::max_dimension, S = core::config::subpixel_bits;
  const int w = p.output_width ? p.output_width : blob.width, h = p.output_height ? p.output_height : blob.height;
  if (p.fit != core::Fit::fill || w < 2 || h < 2 || w > max || h > max || blob.width < 2 || blob.height < 2) return;
  const d::FitLayout f = d::fit_layout(blob.width, blob.height, w, h, p.fit);
  const d::Mapping map = d::drawing_mapping(f, d::crop_shift(f.ox), d::crop_shift(f.oy));
  constexpr std::int32_t budget = (max << S) - 1;
  if (map.x((blob.width - 1) << S) <= budget && map.y((blob.height - 1) << S) <= budget) return;
  const std::uint32_t pw = (blob.width - 1) * f.nx / f.dx + 1, ph = (blob.height - 1) * f.ny / f.dy + 1;
  throw UsageError("--fit fill: the " + std::to_string(blob.width) + " x " + std::to_string(blob.height) +
                   " picture filling " + std::to_string(w) + " x " + std::to_string(h) + " would be drawn " +
                   std::to_string(pw) + " x " + std::to_string(ph) +
                   " pixels, beyond the core's coordinate budget of " + std::to_string(max) +
                   " pixels a side (TS_MAX_DIMENSION, docs/FIXED_POINT.md); use --fit inside "
                   "or stretch, or a --width and --height closer to the picture's proportions");
}

}  // namespace

CoreRenderer::CoreRenderer(std::span<const std::uint8_t> blob, const CoreOptions& o, std::string_view name) {
  core::BlobError error;
  compressed_ = core::is_compressed_blob(blob.data(), blob.size());
  const core::Status s = compressed_ ? core::open_compressed_blob(blob.data(), blob.size(), &compressed_blob_, &error)
                                     : core::open_blob(blob.data(), blob.size(), &blob_, &error);
  auto data_error = [&](core::Status st) {
    return DataError(blob_error_message(name, blob, st, error.offset));
  };
  if (s != core::Status::ok) throw data_error(s);
  if (compressed_) static_cast<core::BlobInfo&>(blob_) = compressed_blob_;  // the header fields, no layers
  auto dimension = [](int v, const char* what) {
    if (v < 0 || v > core::config::max_dimension)
      throw UsageError(std::string(what) + " must be 0 to " + std::to_string(core::config::max_dimension));
    return std::uint16_t(v);
  };
  params_.output_width = dimension(o.width, "output width");
  params_.output_height = dimension(o.height, "output height");
  params_.fit = o.fit;
  params_.viewport = o.viewport;
  params_.tile_width = dimension(o.tile_width, "tile width");
  params_.tile_height = dimension(o.tile_height, "tile height");
  params_.format = o.format;
  params_.dither = o.dither;
  for (int c = 0; c < 3; ++c) params_.background[c] = o.background.rgb[c];
  check_coordinate_budget(blob_, params_);
  std::size_t tile_bytes = 0, work_bytes = 0;
  core::Status st = core::tile_buffer_size(blob_, params_, &tile_bytes);
  if (st == core::Status::ok && !compressed_) st = core::workspace_size(blob_, params_, &work_bytes);
  if (st == core::Status::ok && compressed_) {
    std::size_t scratch_bytes = 0;
    st = core::measure_scratch_size(compressed_blob_, params_, &scratch_bytes);
    if (st != core::Status::ok) throw UsageError(std::string("render options: ") + core::status_text(st));
    std::vector<std::uint8_t> scratch(scratch_bytes);
    st = core::workspace_size(compressed_blob_, params_, scratch.data(), scratch.size(), &stream_workspace_, &error);
    work_bytes = stream_workspace_.bytes;
    if (st != core::Status::ok && st != core::Status::bad_params && st != core::Status::not_compiled)
      throw data_error(st);
  }
  if (st != core::Status::ok) throw UsageError(std::string("render options: ") + core::status_text(st));
  tile_.assign(tile_bytes, 0);
  workspace_.assign(work_bytes, 0);
}

void CoreRenderer::render(CoreFrame& frame) {
  core::Rect view = params_.viewport;
  const int w = params_.output_width ? params_.output_width : blob_.width;
  const int h = params_.output_height ? params_.output_height : blob_.height;
  if (view.empty()) view = core::Rect{0, 0, w, h};
  const int bpp = core::bytes_per_pixel(params_.format);
  frame.width = view.width();
  frame.height = view.height();
  frame.format = params_.format;
  frame.bytes.resize(std::size_t(frame.width) * frame.height * bpp);
  frame.tiles = 0;
  Assembly a{&frame, view, bpp};
  const core::Status s =
      compressed_ ? core::render(compressed_blob_, params_, tile_.data(), tile_.size(), workspace_.data(),
                                 workspace_.size(), collect, &a)
                  : core::render(blob_, params_, tile_.data(), tile_.size(), workspace_.data(), workspace_.size(),
                                 collect, &a);
  if (s != core::Status::ok) throw DataError(std::string("core render failed: ") + core::status_text(s));
}

Image frame_to_image(const CoreFrame& f) {
  using core::PixelFormat;
  if (f.format == PixelFormat::l8 || f.format == PixelFormat::coverage8) {
    Image img(f.width, f.height, 1);
    img.pixels = f.bytes;
    return img;
  }
  Image img(f.width, f.height, 3);
  const int bpp = core::bytes_per_pixel(f.format);
  for (std::size_t i = 0; i < std::size_t(f.width) * f.height; ++i) {
    const std::uint8_t* p = f.bytes.data() + i * bpp;
    std::uint8_t* q = img.pixels.data() + 3 * i;
    switch (f.format) {
      case PixelFormat::rgb888: q[0] = p[0], q[1] = p[1], q[2] = p[2]; break;
      case PixelFormat::xrgb8888: q[0] = p[2], q[1] = p[1], q[2] = p[0]; break;
      case PixelFormat::rgb565_le:
      case PixelFormat::rgb565_be: {
        const unsigned word =
            f.format == PixelFormat::rgb565_le ? unsigned(p[0] | p[1] << 8) : unsigned(p[1] | p[0] << 8);
        const unsigned r = word >> 11, g = (word >> 5) & 63, b = word & 31;
        q[0] = std::uint8_t((r * 255 + 15) / 31);
        q[1] = std::uint8_t((g * 255 + 31) / 63);
        q[2] = std::uint8_t((b * 255 + 15) / 31);
        break;
      }
      default: break;
    }
  }
  return img;
}

CoreFrame render_core_frame(const Triangulation& tri, std::string_view method, const CoreOptions& options,
                            std::string_view name) {
  const Activity activity("rendering " + std::string(name) + " with the core");
  const std::vector<std::uint8_t> blob = pack_blob(tri, parse_core_method(method), name);
  CoreRenderer r(blob, options, name);
  CoreFrame f;
  r.render(f);
  return f;
}

Image render_core(const Triangulation& tri, std::string_view method, const CoreOptions& options,
                  std::string_view name) {
  return frame_to_image(render_core_frame(tri, method, options, name));
}

core::Fit core_fit(Fit fit) {
  switch (fit) {
    case Fit::stretch: return core::Fit::stretch;
    case Fit::inside: return core::Fit::inside;
    case Fit::fill: return core::Fit::fill;
  }
  return core::Fit::stretch;
}

}  // namespace tristream
