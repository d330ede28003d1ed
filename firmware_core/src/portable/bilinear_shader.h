/* SPDX-License-Identifier: MIT */
#pragma once
// BilinearShader's lanes (bilinear_shader.h) where there are none: every span goes through the
// writer's scalar paths.
#include <stdint.h>

#include "../interpolate.h"
#include "../tuning.h"

namespace tristream::core::detail::portable {
namespace {

// BilinearLanes<Channels, Writer>, the part of BilinearShader (its member `lanes`) that draws RGB spans with
// the three channels in vector lanes where the platform has them:
//   static constexpr bool active       whether it draws this shader's spans (else the scalar paths);
//   void set(const BilinearChannel* ch)  after the channels' set-up (begin), when active;
//   void span(const Writer& w, int32_t y, int32_t x0, int32_t x1, int32_t xr, int32_t yr) const
//                                       pixels x0..x1 of row y (xr, yr: the reference pixel), when active.
template <int Channels, typename Writer>
struct BilinearLanes {
  static constexpr bool active = false;
  void set(const BilinearChannel*) {}
  void span(const Writer&, int32_t, int32_t, int32_t, int32_t, int32_t) const {}
};

}  // namespace
}  // namespace tristream::core::detail::portable
