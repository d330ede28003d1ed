// SPDX-License-Identifier: MIT
// Runs the tribaseline executable: outputs, the summary, exit codes and messages.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "io/image_io.h"
#include "io/tri_file.h"

#include "../support/tool_run.h"

namespace fs = std::filesystem;
using namespace tristream;

namespace {

using test::Run;
using test::slurp;

const fs::path& dir() {
  static const fs::path d = [] {
    fs::path p = fs::temp_directory_path() / ("tribaseline_test_" + std::to_string(::getpid()));
    fs::create_directories(p);
    Image img(40, 30, 3);
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 40; ++x) {
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

Run run(const std::string& args) { return test::run_tool(TRIBASELINE_PATH, args, dir()); }

std::string in() { return (dir() / "in.png").string(); }
std::string at(const char* name) { return (dir() / name).string(); }

}  // namespace

TEST_CASE("tribaseline gpr writes N vertices and a summary", "[tribaseline]") {
  const Run r = run("gpr " + in() + " -n 50 -o " + at("a.tri"));
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("50 vertices") != std::string::npos);
  REQUIRE(r.out.find("PSNR") != std::string::npos);
  REQUIRE(r.err.empty());
  const Triangulation t = read_tri_file(at("a.tri"));
  REQUIRE(t.layers.at(0).vertex_count() == 50);
  REQUIRE(t.space == ColorSpace::rgb);
  // --percent: 1 % of 1,200 pixels is 12 vertices.
  REQUIRE(run("gpr " + in() + " --percent 1 -o " + at("p.tri")).code == 0);
  REQUIRE(read_tri_file(at("p.tri")).layers.at(0).vertex_count() == 12);
}

TEST_CASE("tribaseline gpr --json and --values", "[tribaseline]") {
  const Run pixel = run("gpr " + in() + " -n 60 --json -o " + at("px.tri"));
  const Run lsq = run("gpr " + in() + " -n 60 --values lsq --json -o " + at("lsq.tri"));
  REQUIRE(pixel.code == 0);
  REQUIRE(lsq.code == 0);
  const auto jp = nlohmann::json::parse(pixel.out), jl = nlohmann::json::parse(lsq.out);
  REQUIRE(jp["vertices"] == 60);
  REQUIRE(jp["values"] == "pixel");
  REQUIRE(jl["values"] == "lsq");
  REQUIRE(jl["psnr_linear"].get<double>() >= jp["psnr_linear"].get<double>());
  REQUIRE(jp["seconds"].get<double>() >= 0);
}

TEST_CASE("tribaseline output is byte-identical across runs", "[tribaseline]") {
  REQUIRE(run("gpr " + in() + " -n 100 --values lsq -o " + at("r1.tri")).code == 0);
  REQUIRE(run("gpr " + in() + " -n 100 --values lsq -o " + at("r2.tri")).code == 0);
  REQUIRE(slurp(at("r1.tri")) == slurp(at("r2.tri")));
}

TEST_CASE("tribaseline bad input: clear errors and exit codes", "[tribaseline]") {
  struct Case {
    std::string args;
    int code;
    std::string message;
  };
  const Case cases[] = {
      {"gpr " + at("missing.png") + " -n 10 -o " + at("x.tri"), 66, "missing.png"},
      {"gpr " + at("not_an_image.png") + " -n 10 -o " + at("x.tri"), 65, "not_an_image.png"},
      {"gpr " + in() + " -o " + at("x.tri"), 64, "--vertices N or --percent P"},
      {"gpr " + in() + " -n 10 --percent 2 -o " + at("x.tri"), 64, "excludes"},
      {"gpr " + in() + " -n 3 -o " + at("x.tri"), 64, "at least 4"},
      {"gpr " + in() + " -n 1201 -o " + at("x.tri"), 64, "at most the pixel count 1200"},
      {"gpr " + in() + " --percent 0 -o " + at("x.tri"), 64, "above 0"},
      {"gpr " + in() + " -n 10 --values mean -o " + at("x.tri"), 64, "--values"},
      {"gpr " + in() + " -n 10", 64, "--output"},
      {in() + " -n 10 -o " + at("x.tri"), 64, "tribaseline"},
      {"gpr " + in() + " -n 10 -o " + at("no_such_dir/x.tri"), 73, "no_such_dir"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    const Run r = run(c.args);
    REQUIRE(r.code == c.code);
    REQUIRE(r.err.find(c.message) != std::string::npos);
  }
}
