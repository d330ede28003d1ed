/* SPDX-License-Identifier: MIT */
#pragma once
// trisim golden DIR [--update]: renders every .tri and blob in DIR with the settings of DIR's
// manifest (golden.json) and compares each render with its golden PNG (docs/GOLDEN.md).
#include <CLI/CLI.hpp>
#include <string>

namespace tristream::trisim {

struct GoldenCommand {
  std::string dir;
  std::string diff_dir = ".";  // where <name>.diff.png goes for a picture that differs
  bool update = false;
};

CLI::App* add_golden_command(CLI::App& app, GoldenCommand& c);

// 0 when every render equals its golden (or differs within the picture's tolerance), 1 when any
// differs or has no golden; with --update, writes the goldens that differ and returns 0.
int run_golden(const GoldenCommand& c);

}  // namespace tristream::trisim
