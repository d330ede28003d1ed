/* SPDX-License-Identifier: MIT */
#pragma once
// The host tools' progress bar: one line on stderr, redrawn when the whole percentage changes.
#include <cstdio>

namespace tristream {

class ProgressBar {
 public:
  void operator()(double fraction) {
    const int percent = int(fraction * 100);
    if (percent == last_) return;
    last_ = percent;
    constexpr int width = 40;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
                 percent);
    std::fflush(stderr);
  }
  // Ends the line, when a bar was drawn.
  void finish() {
    if (last_ >= 0) std::fprintf(stderr, "\n");
  }

 private:
  int last_ = -1;
};

}  // namespace tristream
