/* SPDX-License-Identifier: MIT */
#pragma once
// Where tests and benchmarks find photographs. The repository ships one, the demo's
// data/demo/kodim23.png. More come from the directory named by the environment variable
// TRISTREAM_IMAGES, laid out as grey/*.png, colour/*.png and kodak/*.png (the layout of the
// test photographs the project was developed with, which are not shipped: only the Kodak
// images may be). Code that needs one of them and finds the variable unset or the file absent
// skips and says so, naming the variable.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace tristream::test {

inline constexpr const char* images_variable = "TRISTREAM_IMAGES";

// The directory of TRISTREAM_IMAGES, or "" when the variable is unset or empty.
inline std::string shared_images_dir() {
  const char* dir = std::getenv(images_variable);
  return dir && *dir ? std::string(dir) : std::string();
}

// The shared photograph `relative` (e.g. "grey/boat.png"), or "" when it is not available.
inline std::string shared_image(const std::string& relative) {
  const std::string dir = shared_images_dir();
  if (dir.empty()) return {};
  const std::string path = dir + "/" + relative;
  return std::filesystem::exists(path) ? path : std::string();
}

// The photograph shipped with the repository.
inline std::string demo_image() { return std::string(TRISTREAM_SOURCE_DIR) + "/data/demo/kodim23.png"; }

// The message of a skip for want of `relative`.
inline std::string skip_message(const std::string& relative) {
  return "SKIPPED: needs " + relative + " under $" + images_variable +
         (shared_images_dir().empty() ? std::string(" (unset)") : " (= " + shared_images_dir() + ")");
}

}  // namespace tristream::test
