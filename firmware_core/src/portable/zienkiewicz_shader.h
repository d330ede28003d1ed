/* SPDX-License-Identifier: MIT */
#pragma once
// ZienkiewiczShader's lanes (zienkiewicz_shader.h) where there are none: forward-differenced rows
// channel by channel.
#include <stdint.h>

#include "../interpolate.h"
#include "../tuning.h"

namespace tristream::core::detail::portable {
namespace {

// ZienkiewiczLanes<Channels, Writer>: a forward-differenced row with the channels in vector lanes
// where the platform has them:
//   static constexpr bool active   whether it draws this shader's forward-differenced rows;
//   static void row(const Writer& w, const ZienkiewiczChannel* ch, uint32_t a, uint32_t b,
//                   uint32_t da, uint32_t db, int32_t xs, int32_t x0, int32_t x1, int32_t y,
//                   uint8_t* p, int step)
//       pixels x0..x1 of row y (p: x0's, step bytes apart) from the weights a, b at xs, stepped
//       by da, db per column, when active.
template <int Channels, typename Writer>
struct ZienkiewiczLanes {
  static constexpr bool active = false;
  static void row(const Writer&, const ZienkiewiczChannel*, uint32_t, uint32_t, uint32_t, uint32_t, int32_t, int32_t,
                  int32_t, int32_t, uint8_t*, int) {}
};

}  // namespace
}  // namespace tristream::core::detail::portable
