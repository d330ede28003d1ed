// SPDX-License-Identifier: MIT
// Aspect-preserving fits (RenderParams::fit, docs/CONVENTIONS.md "Fitting"): the layout in integers,
// every picture pixel written exactly once and the border exactly the background, the same pixels
// for every tiling, the core within the usual tolerance of the reference (bilinear 1, zienkiewicz 2),
// and the refusals. Coverage counts need a core with PixelFormat::coverage8 (CMakeLists.txt).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "core_support.h"
#include "reference/fit.h"
#include "reference/render.h"
#include "tristream/tristream.h"

using namespace tristream;
using namespace tristream::testing;

namespace {

Fit host_fit(core::Fit f) { return f == core::Fit::inside ? Fit::inside : f == core::Fit::fill ? Fit::fill : Fit::stretch; }

const char* name_of(core::Fit f) { return f == core::Fit::inside ? "inside" : f == core::Fit::fill ? "fill" : "stretch"; }

struct Size {
  int w, h;
};

// Whether output pixel (i, j) is in the picture's box of `f`.
bool in_box(const FitLayout& f, int i, int j) {
  return i >= f.x0 && i < f.x0 + f.width && j >= f.y0 && j < f.y0 + f.height;
}

// Whether the far edge of the picture, mapped and rounded to nearest 1/16 pixel as the stretch
// does, would land on the next pixel centre although the exact edge is short of it: the case the
// fits' rounding down is for.
bool far_edge_rounds_up(int domain, const FitLayout& f) {
  const std::int64_t raw = (std::int64_t(16) * (domain - 1) * f.n + f.d / 2) / f.d;
  const std::int64_t e = std::int64_t(domain - 1) * f.n / f.d;
  return raw >= 16 * (e + 1);
}

int tolerance_of(std::string_view method) { return method == "bilinear" ? 1 : 2; }

}  // namespace

TEST_CASE("the fit layout in integers: scale, centring and odd borders") {
  // 768 x 512 into a 240 x 320 portrait panel: width limits, scale 239/767, 160 rows from row 80.
  FitLayout f = fit_layout(768, 512, 240, 320, Fit::inside);
  CHECK(f.n == 239);
  CHECK(f.d == 767);
  CHECK((f.x0 == 0 && f.width == 240));
  CHECK((f.y0 == 80 && f.height == 160));
  // Scale 1: a 64 x 48 picture in 64 x 65 rows 8 .. 55, the odd border's extra row at the bottom.
  f = fit_layout(64, 48, 64, 65, Fit::inside);
  CHECK((f.n == f.d && f.x0 == 0 && f.y0 == 8 && f.height == 48));
  CHECK(65 - (f.y0 + f.height) == 9);
  // Fill: 64 x 48 into 49 x 48 at scale 1 crops 8 columns on the left and 7 on the right.
  f = fit_layout(64, 48, 49, 48, Fit::fill);
  CHECK((f.n == f.d && f.x0 == -8 && f.width == 64 && f.y0 == 0));
  // The same aspect: inside and fill are the stretch.
  for (Fit fit : {Fit::inside, Fit::fill}) {
    f = fit_layout(65, 49, 129, 97, fit);
    CHECK((f.n == 128 && f.d == 64 && f.x0 == 0 && f.y0 == 0 && f.width == 129 && f.height == 97));
  }
  // Ties between the two ratios take x; a 2 x 2 domain works.
  f = fit_layout(2, 2, 5, 9, Fit::inside);
  CHECK((f.n == 4 && f.d == 1 && f.x0 == 0 && f.y0 == 2 && f.width == 5 && f.height == 5));
}

TEST_CASE("fits: each picture pixel written once, the rest background, for every tiling") {
  // A domain that is the whole rectangle, so the covered pixels are exactly the picture's box; its
  // vertices on the pixel lattice, so that no triangle collapses at these scales (a strong
  // downscale can collapse one, as for the stretch: docs/FIXED_POINT.md).
  const int w = 64, h = 48;
  const Mesh mesh = random_lattice_mesh(w, h, 120, 5, 10);
  const auto blob = pack_blob(single_mesh(mesh, w, h), core::Method::bilinear);
  std::vector<Size> outputs = {{64, 65}, {49, 48}, {97, 40}, {40, 97}, {128, 96}, {31, 77}, {77, 31}, {33, 33}};
  // Sizes whose picture ends just short of a pixel centre that the rounded mapping reaches.
  int rounding_cases = 0;
  for (int ow = 20; ow <= 120 && rounding_cases < 3; ++ow)
    for (int oh : {ow + 37, ow / 2 + 2}) {
      const FitLayout f = fit_layout(w, h, ow, oh, Fit::inside);
      const bool x_short = f.width < ow && far_edge_rounds_up(w, f), y_short = f.height < oh && far_edge_rounds_up(h, f);
      if (x_short || y_short) outputs.push_back({ow, oh}), ++rounding_cases;
    }
  REQUIRE(rounding_cases == 3);
  for (core::Fit fit : {core::Fit::inside, core::Fit::fill, core::Fit::stretch}) {
    for (const Size& s : outputs) {
      const FitLayout f = fit_layout(w, h, s.w, s.h, host_fit(fit));
      CoreOptions o;
      o.width = s.w;
      o.height = s.h;
      o.fit = fit;
      o.format = core::PixelFormat::coverage8;
      const CoreFrame whole = core_frame(blob, o, {0, 0});
      std::size_t wrong = 0;
      for (int j = 0; j < s.h; ++j)
        for (int i = 0; i < s.w; ++i) wrong += whole.bytes[std::size_t(j) * s.w + i] != (in_box(f, i, j) ? 1 : 0);
      INFO(name_of(fit) << " " << s.w << "x" << s.h);
      CHECK(wrong == 0);
      for (const Tiling& t : all_tilings()) {
        INFO("tiles " << t.w << "x" << t.h);
        CHECK(bytes_differing(core_frame(blob, o, t).bytes, whole.bytes) == 0);
      }
    }
  }
}

TEST_CASE("fits: the border is exactly the background, also dithered, and tiling never changes a pixel") {
  const int w = 71, h = 45;
  const Triangulation tri = single_mesh(random_subpixel_mesh(w, h, 150, 42, true, 3), w, h, ColorSpace::ycbcr);
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    const auto blob = pack_blob(tri, m);
    for (core::Fit fit : {core::Fit::inside, core::Fit::fill}) {
      for (Size s : {Size{60, 80}, Size{97, 40}, Size{120, 61}}) {
        for (core::PixelFormat fmt : {core::PixelFormat::rgb888, core::PixelFormat::rgb565_be}) {
          for (bool dither : {false, true}) {
            CoreOptions o;
            o.width = s.w;
            o.height = s.h;
            o.fit = fit;
            o.format = fmt;
            o.dither = dither && fmt == core::PixelFormat::rgb565_be;
            o.background = 77;
            const CoreFrame whole = core_frame(blob, o, {0, 0});
            INFO("method " << int(m) << " " << name_of(fit) << " " << s.w << "x" << s.h << " format " << int(fmt)
                           << " dither " << o.dither);
            // The background as the core writes it outside the domain (dithered in place): a
            // stretched render of a domain that is one tiny triangle at the far corner, which
            // covers output pixel (W'-1, H'-1) only.
            Mesh corner;
            corner.value_count = 3;
            corner.points = {{w - 1.0, h - 1.0}, {w - 1.5, h - 1.0}, {w - 1.0, h - 1.5}};
            corner.values.assign(9, 10.0);
            corner.triangles = {{{0, 1, 2}}};
            corner.normalize_winding();
            CoreOptions stretched = o;
            stretched.fit = core::Fit::stretch;
            const CoreFrame bg = core_frame(pack_blob(single_mesh(corner, w, h, ColorSpace::ycbcr), m), stretched, {0, 0});
            const FitLayout f = fit_layout(w, h, s.w, s.h, host_fit(fit));
            const int bpp = core::bytes_per_pixel(fmt);
            std::size_t border = 0, wrong = 0, not_77 = 0;
            for (int j = 0; j < s.h; ++j)
              for (int i = 0; i < s.w; ++i) {
                if (in_box(f, i, j)) continue;
                ++border;
                if (i == s.w - 1 && j == s.h - 1) continue;
                const std::size_t k = (std::size_t(j) * s.w + i) * bpp;
                wrong += !std::equal(&whole.bytes[k], &whole.bytes[k] + bpp, &bg.bytes[k]);
                for (int b = 0; b < bpp; ++b) not_77 += whole.bytes[k + b] != 77;
              }
            CHECK(border == (fit == core::Fit::inside ? std::size_t(s.w) * s.h - f.width * f.height : 0));
            CHECK(wrong == 0);
            if (fmt == core::PixelFormat::rgb888) CHECK(not_77 == 0);
            for (const Tiling& t : all_tilings()) {
              INFO("tiles " << t.w << "x" << t.h);
              CHECK(bytes_differing(core_frame(blob, o, t).bytes, whole.bytes) == 0);
            }
            CoreOptions view = o;
            view.viewport = core::Rect{3, 5, s.w - 7, s.h - 2};
            CoreOptions band = view;
            const CoreFrame part = core_frame(blob, view, {32, 32});
            CHECK(bytes_differing(core_frame(blob, band, {0, 16}).bytes, part.bytes) == 0);
            std::size_t differ = 0;
            for (int j = 5; j < s.h - 2; ++j)
              for (int i = 3; i < s.w - 7; ++i)
                for (int b = 0; b < bpp; ++b)
                  differ += part.bytes[(std::size_t(j - 5) * (s.w - 10) + (i - 3)) * bpp + b] !=
                            whole.bytes[(std::size_t(j) * s.w + i) * bpp + b];
            CHECK(differ == 0);
          }
        }
      }
    }
  }
}

TEST_CASE("fits: the core within the tolerance of the reference, which uses the same layout") {
  // Scales at which the mapping is exact (1 and 2, every case of border or crop), as the stretch's
  // tolerance is guaranteed at the native size and at 2x: elsewhere rounding positions to 1/16
  // pixel moves steep edges (docs/FIXED_POINT.md).
  const std::vector<std::pair<core::Fit, Size>> exact = {
      {core::Fit::inside, {64, 65}}, {core::Fit::inside, {70, 48}}, {core::Fit::inside, {127, 200}},
      {core::Fit::inside, {200, 95}}, {core::Fit::fill, {49, 48}},   {core::Fit::fill, {64, 31}},
      {core::Fit::fill, {100, 95}},   {core::Fit::fill, {127, 60}}};
  for (const auto& [fit, s] : exact) {
    const FitLayout f = fit_layout(64, 48, s.w, s.h, host_fit(fit));
    INFO(name_of(fit) << " " << s.w << "x" << s.h);
    CHECK((f.n == f.d || f.n == 2 * f.d));
    CHECK((f.x0 != 0 || f.y0 != 0));
  }
  const int w = 64, h = 48;
  std::vector<std::pair<std::string, Triangulation>> cases;
  cases.emplace_back("grey", single_mesh(random_lattice_mesh(w, h, 150, 3, 100), w, h));
  cases.emplace_back("rgb sub-pixel", single_mesh(random_subpixel_mesh(w, h, 90, 4, true, 3), w, h, ColorSpace::rgb));
  cases.emplace_back("ycbcr", single_mesh(random_lattice_mesh(w, h, 150, 5, 0, 3), w, h, ColorSpace::ycbcr));
  cases.emplace_back("hull domain", single_mesh(random_subpixel_mesh(w, h, 60, 6, false), w, h));
  Triangulation layered;
  layered.width = w;
  layered.height = h;
  layered.space = ColorSpace::rgb;
  for (int c = 0; c < 3; ++c) {
    layered.layers.push_back(random_lattice_mesh(w, h, 60 + 40 * c, 70 + c, 20));
    layered.layers.back().name = "channel" + std::to_string(c);
  }
  cases.emplace_back("layered", layered);
  for (const auto& [what, tri] : cases)
    for (std::string_view method : {"bilinear", "zienkiewicz"})
      for (const auto& [fit, s] : exact) {
          RenderOptions ro;
          ro.width = s.w;
          ro.height = s.h;
          ro.fit = host_fit(fit);
          ro.background = 9;
          const Image ref = render_reference(tri, *find_reference_method(method), ro);
          CoreOptions co;
          co.width = s.w;
          co.height = s.h;
          co.fit = fit;
          co.background = 9;
          co.format = tri.space == ColorSpace::grey ? core::PixelFormat::l8 : core::PixelFormat::rgb888;
          const Image got = render_core(tri, method, co);
          REQUIRE(got.pixels.size() == ref.pixels.size());
          int worst = 0;
          for (std::size_t i = 0; i < got.pixels.size(); ++i)
            worst = std::max(worst, std::abs(int(got.pixels[i]) - int(ref.pixels[i])));
          INFO(what << " " << method << " " << name_of(fit) << " " << s.w << "x" << s.h << ": max diff " << worst);
          CHECK(worst <= tolerance_of(method));
      }
}

TEST_CASE("fits at scale 1 are the native pixels, shifted or cropped") {
  const int w = 64, h = 48;
  const Triangulation tri = single_mesh(random_subpixel_mesh(w, h, 120, 9, true, 3), w, h, ColorSpace::rgb);
  for (core::Method m : {core::Method::bilinear, core::Method::zienkiewicz}) {
    const auto blob = pack_blob(tri, m);
    CoreOptions o;
    const CoreFrame native = core_frame(blob, o, {32, 32});
    for (auto [fit, s, dx, dy] : {std::tuple{core::Fit::inside, Size{64, 65}, 0, 8},
                                  std::tuple{core::Fit::inside, Size{70, 48}, 3, 0},
                                  std::tuple{core::Fit::fill, Size{49, 48}, -8, 0},
                                  std::tuple{core::Fit::fill, Size{64, 31}, 0, -9}}) {
      o.width = s.w;
      o.height = s.h;
      o.fit = fit;
      const CoreFrame got = core_frame(blob, o, {0, 16});
      std::size_t differ = 0, compared = 0;
      for (int j = 0; j < s.h; ++j)
        for (int i = 0; i < s.w; ++i) {
          const int x = i - dx, y = j - dy;
          if (x < 0 || y < 0 || x >= w || y >= h) continue;
          ++compared;
          for (int b = 0; b < 3; ++b)
            differ += got.bytes[(std::size_t(j) * s.w + i) * 3 + b] != native.bytes[(std::size_t(y) * w + x) * 3 + b];
        }
      INFO("method " << int(m) << " " << name_of(fit) << " " << s.w << "x" << s.h);
      CHECK(compared == std::size_t(std::min(w, s.w)) * std::min(h, s.h));
      CHECK(differ == 0);
    }
  }
}

TEST_CASE("fits far off the output: large negative and positive positions of a fill") {
  // 2048 x 64 filling 64 x 64: scale 1, the picture from column -992 to 1055, drawn 992 pixels to the
  // right (a multiple of 4); 104 x 64 and, scaled by 39/63, 64 x 40 likewise. (100 x 64 would be
  // drawn from 976 pixels to the right, 2 more than its crop, and refused: the far corner at 2049.)
  const int w = 2048, h = 64;
  Mesh mesh;
  mesh.points = {{0, 0}, {w - 1.0, 0}, {0, h - 1.0}, {w - 1.0, h - 1.0}, {1000.25, 20.5}, {1030.0, 40.0}, {1010.0, 63.0}};
  mesh.values = {0, 255, 30, 200, 90, 140, 250};
  mesh.triangles = delaunay_triangulation(mesh.points);
  const Triangulation tri = single_mesh(mesh, w, h);
  for (std::string_view method : {"bilinear", "zienkiewicz"}) {
    for (Size s : {Size{64, 64}, Size{104, 64}, Size{64, 40}}) {
      RenderOptions ro;
      ro.width = s.w;
      ro.height = s.h;
      ro.fit = Fit::fill;
      const Image ref = render_reference(tri, *find_reference_method(method), ro);
      CoreOptions co;
      co.width = s.w;
      co.height = s.h;
      co.fit = core::Fit::fill;
      co.format = core::PixelFormat::l8;
      for (const Tiling& t : {Tiling{0, 0}, Tiling{32, 32}, Tiling{0, 16}, Tiling{13, 7}}) {
        co.tile_width = t.w;
        co.tile_height = t.h;
        const Image got = render_core(tri, method, co);
        int worst = 0;
        for (std::size_t i = 0; i < got.pixels.size(); ++i)
          worst = std::max(worst, std::abs(int(got.pixels[i]) - int(ref.pixels[i])));
        INFO(method << " " << s.w << "x" << s.h << " tiles " << t.w << "x" << t.h << ": max diff " << worst);
        CHECK(worst <= tolerance_of(method));
      }
    }
  }
  const auto blob = pack_blob(tri, core::Method::bilinear);
  CoreOptions o;
  o.format = core::PixelFormat::coverage8;
  o.fit = core::Fit::fill;
  o.width = o.height = 64;
  const CoreFrame f = core_frame(blob, o, {32, 32});
  CHECK(std::count(f.bytes.begin(), f.bytes.end(), std::uint8_t(1)) == 64 * 64);
}

TEST_CASE("fits: parameters refused") {
  const int w = 2048, h = 32;
  const auto blob = pack_blob(single_mesh(random_lattice_mesh(w, h, 20, 1), w, h), core::Method::bilinear);
  core::Blob b;
  core::BlobError error;
  REQUIRE(core::open_blob(blob.data(), blob.size(), &b, &error) == core::Status::ok);
  core::RenderParams p;
  p.format = core::PixelFormat::l8;
  p.output_width = 64;
  p.output_height = 64;
  std::size_t bytes = 0;
  // Inside is always possible; a fill of this aspect would span 2047 * 63 / 31 columns.
  p.fit = core::Fit::inside;
  CHECK(core::workspace_size(b, p, &bytes) == core::Status::ok);
  p.fit = core::Fit::fill;
  CHECK(core::workspace_size(b, p, &bytes) == core::Status::bad_params);
  CHECK(core::tile_buffer_size(b, p, &bytes) == core::Status::bad_params);
  // 2048 x 32 into 2047 x 32: scale 1, a crop of 1 pixel drawn 4 pixels before the output, so the
  // far corner would be drawn at 2047 + 3 pixels.
  p.output_width = 2047;
  p.output_height = 32;
  CHECK(core::workspace_size(b, p, &bytes) == core::Status::bad_params);
  p.output_width = 1024;
  p.output_height = 17;  // scale 16/31: the picture is 1057 columns long
  CHECK(core::workspace_size(b, p, &bytes) == core::Status::ok);
  p.fit = core::Fit(3);
  CHECK(core::workspace_size(b, p, &bytes) == core::Status::bad_params);

  ts_blob cb;
  REQUIRE(ts_open(blob.data(), blob.size(), &cb, nullptr) == TS_OK);
  ts_params cp = {};
  cp.format = TS_L8;
  cp.output_width = 64;
  cp.output_height = 64;
  cp.fit = TS_FIT_INSIDE;
  CHECK(ts_tile_buffer_size(&cb, &cp, &bytes) == TS_OK);
  CHECK(bytes == 64 * 64);
  cp.fit = TS_FIT_FILL;
  CHECK(ts_tile_buffer_size(&cb, &cp, &bytes) == TS_BAD_PARAMS);
  for (int bad : {-1, 3, 100}) {
    cp.fit = bad;
    CHECK(ts_tile_buffer_size(&cb, &cp, &bytes) == TS_BAD_PARAMS);
  }
}
