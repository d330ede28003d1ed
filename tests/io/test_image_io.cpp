// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>

#include "common/errors.h"
#include "io/atomic_file.h"
#include "io/image_io.h"

using namespace tristream;
namespace fs = std::filesystem;

TEST_CASE("PNG round trip, grey and RGB") {
  const fs::path dir = fs::temp_directory_path() / "tristream_test_image_io";
  fs::create_directories(dir);
  for (int channels : {1, 3}) {
    Image img(13, 7, channels);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = std::uint8_t(i * 37 + 11);
    const std::string path = (dir / (std::to_string(channels) + "channel.png")).string();
    write_png(path, img);
    const Image back = read_image(path);
    CHECK(back.width == 13);
    CHECK(back.height == 7);
    CHECK(back.channels == channels);
    CHECK(back.pixels == img.pixels);
  }
  // No temporary file is left behind.
  int files = 0;
  for (auto& e : fs::directory_iterator(dir)) files += e.path().extension() == ".png" ? 0 : 1;
  CHECK(files == 0);
  fs::remove_all(dir);
}

TEST_CASE("image errors name the file") {
  CHECK_THROWS_AS(read_image("/nonexistent/a.png"), InputError);
  const fs::path junk = fs::temp_directory_path() / "tristream_junk.png";
  write_file_atomically(junk.string(), "this is not an image");
  CHECK_THROWS_WITH(read_image(junk.string()), Catch::Contains(junk.string()) && Catch::Contains("expected"));
  fs::remove(junk);
  CHECK_THROWS_AS(write_png("/nonexistent/dir/x.png", Image(2, 2, 1)), OutputError);
}
