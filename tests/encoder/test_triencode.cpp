// SPDX-License-Identifier: MIT
// Runs the triencode executable: exit codes, messages, byte-identical outputs.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/image_io.h"
#include "io/tri_file.h"

namespace fs = std::filesystem;
using namespace tristream;

namespace {

struct Run {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const fs::path& dir() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("triencode_test_" + std::to_string(::getpid()));
    fs::create_directories(p);
    Image img(48, 32, 3);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 48; ++x) {
        img.at(x, y, 0) = std::uint8_t(x * 5);
        img.at(x, y, 1) = std::uint8_t((x * y) % 256);
        img.at(x, y, 2) = std::uint8_t(x > y ? 200 : 30);
      }
    write_png((p / "in.png").string(), img);
    std::ofstream(p / "not_an_image.png") << "this is text, not a PNG\n";
    return p;
  }();
  return d;
}

Run run(const std::string& args) {
  const fs::path out = dir() / "stdout.txt", err = dir() / "stderr.txt";
  const std::string cmd = std::string(TRIENCODE_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

std::string in() { return (dir() / "in.png").string(); }

}  // namespace

TEST_CASE("triencode writes a readable triangulation and a summary", "[triencode]") {
  const std::string out = (dir() / "a.tri").string();
  const Run r = run(in() + " --vertices 100 -o " + out);
  INFO(r.err);
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("100 vertices") != std::string::npos);
  REQUIRE(r.out.find("PSNR") != std::string::npos);
  REQUIRE(r.err.empty());  // stderr is not a terminal: no progress bar
  const Triangulation t = read_tri_file(out);
  REQUIRE(t.layers.at(0).vertex_count() == 100);
  REQUIRE(t.space == ColorSpace::rgb);
}

TEST_CASE("triencode output is byte-identical across runs", "[triencode]") {
  for (const std::string mode :
       {"--color co", "--color separate --space ycbcr", "--grey --fit lsq", "--cotri thesis"}) {
    const std::string a = (dir() / "d1.tri").string(), b = (dir() / "d2.tri").string();
    REQUIRE(run(in() + " -n 300 " + mode + " -o " + a).code == 0);
    REQUIRE(run(in() + " -n 300 " + mode + " -o " + b).code == 0);
    REQUIRE(slurp(a) == slurp(b));
    REQUIRE(!slurp(a).empty());
  }
}

TEST_CASE("triencode --json", "[triencode]") {
  const Run r = run(in() + " --error 10 --json -o " + (dir() / "j.tri").string());
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("\"psnr_linear\"") != std::string::npos);
  REQUIRE(r.out.find("\"vertices\"") != std::string::npos);
}

TEST_CASE("triencode --relocate: 0 keeps the inserted positions, the default lowers the error", "[triencode]") {
  const std::string a = (dir() / "r0.tri").string(), b = (dir() / "r4.tri").string();
  const Run none = run(in() + " -n 200 --grey --relocate 0 --json -o " + a);
  const Run dflt = run(in() + " -n 200 --grey --json -o " + b);
  REQUIRE(none.code == 0);
  REQUIRE(dflt.code == 0);
  auto psnr = [](const std::string& json) {
    const auto at = json.find("\"psnr_linear\":");
    REQUIRE(at != std::string::npos);
    return std::stod(json.substr(at + 14));
  };
  REQUIRE(psnr(dflt.out) > psnr(none.out));
  const Triangulation t0 = read_tri_file(a), t4 = read_tri_file(b);
  REQUIRE(t0.layers.at(0).vertex_count() == 200);
  REQUIRE(t4.layers.at(0).vertex_count() == 200);
  std::size_t moved = 0;
  for (std::size_t v = 0; v < 200; ++v)
    moved +=
        t0.layers[0].points[v].x != t4.layers[0].points[v].x || t0.layers[0].points[v].y != t4.layers[0].points[v].y;
  REQUIRE(moved > 0);
  REQUIRE(run(in() + " -n 200 --relocate -1 -o " + a).code == 64);
}

TEST_CASE("triencode bad input: clear errors and exit codes", "[triencode]") {
  const std::string out = " -o " + (dir() / "bad.tri").string();
  SECTION("unreadable image: 66") {
    const Run r = run((dir() / "missing.png").string() + " -n 10" + out);
    REQUIRE(r.code == 66);
    REQUIRE(r.err.find("missing.png") != std::string::npos);
  }
  SECTION("not an image: 65") {
    const Run r = run((dir() / "not_an_image.png").string() + " -n 10" + out);
    REQUIRE(r.code == 65);
    REQUIRE(r.err.find("not_an_image.png") != std::string::npos);
  }
  SECTION("fewer than 4 vertices: 64") {
    const Run r = run(in() + " -n 3" + out);
    REQUIRE(r.code == 64);
    REQUIRE(r.err.find("at least 4") != std::string::npos);
  }
  SECTION("more vertices than pixels: 64") {
    const Run r = run(in() + " -n 1537" + out);
    REQUIRE(r.code == 64);
    REQUIRE(r.err.find("1536") != std::string::npos);
  }
  SECTION("no stop criterion, unknown option, no output: 64") {
    REQUIRE(run(in() + out).code == 64);
    REQUIRE(run(in() + " -n 10 --colour co" + out).code == 64);
    REQUIRE(run(in() + " -n 10").code == 64);
    REQUIRE(run(in() + " -n 10 --space lab" + out).code == 64);
  }
  SECTION("unwritable output: 73") {
    const Run r = run(in() + " -n 10 -o " + (dir() / "no_such_dir" / "x.tri").string());
    REQUIRE(r.code == 73);
    REQUIRE(r.err.find("no_such_dir") != std::string::npos);
  }
  REQUIRE(!fs::exists(dir() / "bad.tri"));
}

TEST_CASE("triencode --help", "[triencode]") {
  const Run r = run("--help");
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("--vertices") != std::string::npos);
  REQUIRE(r.out.find("--fit") != std::string::npos);
  REQUIRE(r.out.find("--relocate") != std::string::npos);
}
