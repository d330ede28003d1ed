// SPDX-License-Identifier: MIT
// Runs the triencode executable: exit codes, messages, byte-identical outputs.
#include <sys/wait.h>

#include <algorithm>
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
    // 120x80: smooth shading, a disc and stripes, so that more vertices keep paying.
    Image photo(120, 80, 3);
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 120; ++x) {
        const bool disc = (x - 70) * (x - 70) + (y - 35) * (y - 35) < 400;
        photo.at(x, y, 0) = std::uint8_t(disc ? 230 : 40 + x);
        photo.at(x, y, 1) = std::uint8_t(100 + 80 * std::sin(x * 0.11) * std::cos(y * 0.07));
        photo.at(x, y, 2) = std::uint8_t(x % 16 < 8 && y > 55 ? 220 : 2 * y);
      }
    write_png((p / "photo.png").string(), photo);
    std::ofstream(p / "not_an_image.png") << "this is text, not a PNG\n";
    return p;
  }();
  return d;
}

Run run_tool(const char* tool, const std::string& args) { return test::run_tool(tool, args, dir()); }

Run run(const std::string& args) { return run_tool(TRIENCODE_PATH, args); }

std::string in() { return (dir() / "in.png").string(); }
std::string photo() { return (dir() / "photo.png").string(); }
std::string at(const char* name) { return (dir() / name).string(); }

// The smallest and largest vertex coordinates of every layer.
struct Box {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
};
Box vertex_box(const Triangulation& t) {
  Box b;
  for (const Mesh& m : t.layers)
    for (const Point& p : m.points) {
      b.x0 = std::min(b.x0, p.x);
      b.y0 = std::min(b.y0, p.y);
      b.x1 = std::max(b.x1, p.x);
      b.y1 = std::max(b.y1, p.y);
    }
  return b;
}

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
  for (const std::string mode : {"--color co", "--color separate --space ycbcr", "--grey --values lsq",
                                 "--cotri thesis", "-m zienkiewicz", "-m clough-tocher --color separate"}) {
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

TEST_CASE("triencode -m zienkiewicz: gradients in the .tri on the step, the compressed blob codes the step",
          "[triencode]") {
  const std::string z = (dir() / "z.tri").string(), zb = (dir() / "z.bin").string();
  const Run r = run(in() + " -n 300 -m zienkiewicz --json -o " + z);
  REQUIRE(r.code == 0);
  REQUIRE(r.out.find("\"method\":\"zienkiewicz\"") != std::string::npos);
  REQUIRE(r.out.find("\"gradient_step_bits\":9") != std::string::npos);
  REQUIRE(r.out.find("psnr_linear") == std::string::npos);  // the PSNR is zienkiewicz's
  const Triangulation tri = read_tri_file(z);
  const Mesh& m = tri.layers.at(0);
  REQUIRE(m.has_gradients());
  for (double g : m.gradients) REQUIRE(g * 8 == std::round(g * 8));
  const Run pack = run_tool(TRIPACK_PATH, z + " -m zienkiewicz --compress --json -o " + zb);
  REQUIRE(pack.code == 0);
  REQUIRE(nlohmann::json::parse(pack.out)["gradient_step_bits"] == nlohmann::json::array({9}));
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
  REQUIRE(r.out.find("--values") != std::string::npos);
  REQUIRE(r.out.find("--relocate") != std::string::npos);
  for (const char* panel : {"--width", "--height", "--fit", "stretch|inside|fill", "--max-bytes", "--method"})
    REQUIRE(r.out.find(panel) != std::string::npos);
}

TEST_CASE("triencode --width/--height: a .tri of the panel's size for each fit", "[triencode][panel]") {
  // photo.png is 120x80; the panel 48x40. inside: n / d = 47 / 119, e_y = floor(79 * 47 / 119) = 31,
  // o_y = floor((39 - 31) / 2) = 4.
  for (const std::string fit : {"stretch", "inside", "fill"}) {
    INFO("--fit " << fit);
    const Run r = run(photo() + " -n 60 --width 48 --height 40 --fit " + fit + " --resampled " + at("panel.png") +
                      " -o " + at("panel.tri"));
    INFO(r.err);
    REQUIRE(r.code == 0);
    const Triangulation t = read_tri_file(at("panel.tri"));
    REQUIRE(t.width == 48);
    REQUIRE(t.height == 40);
    REQUIRE(t.layers.at(0).vertex_count() == 60);
    const Image resampled = read_image(at("panel.png"));
    REQUIRE(resampled.width == 48);
    REQUIRE(resampled.height == 40);
    const Box b = vertex_box(t);
    REQUIRE(b.x0 == 0);
    REQUIRE(b.x1 == 47);
    if (fit == "inside") {
      // The triangulation covers the picture's rows 4..35 only; the border is black in the image.
      REQUIRE(b.y0 == 4);
      REQUIRE(b.y1 == 35);
      for (int x = 0; x < 48; ++x)
        for (int c = 0; c < 3; ++c) {
          REQUIRE(resampled.at(x, 3, c) == 0);
          REQUIRE(resampled.at(x, 36, c) == 0);
        }
      // The core draws the border in its background and the picture from row 4 to row 35.
      REQUIRE(run_tool(TRISIM_PATH, "render " + at("panel.tri") + " --engine core --format rgb888 --background 77 -o " +
                                        at("panel_render.png"))
                  .code == 0);
      const Image render = read_image(at("panel_render.png"));
      REQUIRE(render.width == 48);
      REQUIRE(render.height == 40);
      int border = 0, picture_rows_at_77 = 0;
      for (int y = 0; y < 40; ++y) {
        bool all77 = true;
        for (int x = 0; x < 48; ++x)
          for (int c = 0; c < 3; ++c) all77 = all77 && render.at(x, y, c) == 77;
        if (y < 4 || y > 35) border += all77;
        else picture_rows_at_77 += all77;
      }
      REQUIRE(border == 8);
      REQUIRE(picture_rows_at_77 == 0);
    } else {
      REQUIRE(b.y0 == 0);
      REQUIRE(b.y1 == 39);
    }
  }
}

TEST_CASE("triencode --fit fill crops the centre, stretch squeezes the whole", "[triencode][panel]") {
  // A 120x40 horizontal ramp (red = 2 x + 10) on a 40x40 panel. fill: n / d = 39 / 39, e_x = 119,
  // o_x = floor((39 - 119) / 2) = -40: panel column i is image column i + 40, copied (scale 1).
  // stretch: column i * 119 / 39.
  Image ramp(120, 40, 3);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 120; ++x) {
      ramp.at(x, y, 0) = std::uint8_t(10 + 2 * x);
      ramp.at(x, y, 1) = 50;
      ramp.at(x, y, 2) = 50;
    }
  write_png(at("ramp.png"), ramp);
  REQUIRE(run(at("ramp.png") + " -n 8 --width 40 --height 40 --fit fill --resampled " + at("fill.png") + " -o " +
              at("fill.tri"))
              .code == 0);
  const Image fill = read_image(at("fill.png"));
  for (int x = 0; x < 40; ++x) REQUIRE(fill.at(x, 20, 0) == 10 + 2 * (x + 40));
  REQUIRE(
      run(at("ramp.png") + " -n 8 --width 40 --height 40 --resampled " + at("stretch.png") + " -o " + at("stretch.tri"))
          .code == 0);
  const Image stretch = read_image(at("stretch.png"));
  for (int x = 2; x < 38; ++x) REQUIRE(std::fabs(stretch.at(x, 20, 0) - (10 + 2 * (x * 119.0 / 39))) <= 1.5);
}

TEST_CASE("triencode --max-bytes: a blob within 0.85 to 1 times the budget, as tripack writes it",
          "[triencode][budget]") {
  struct Case {
    long budget;
    std::string method, blob, fit;
  };
  for (const Case& k : {Case{1500, "bilinear", "compressed", "fill"}, Case{4000, "bilinear", "compressed", "stretch"},
                        Case{6000, "zienkiewicz", "compressed", "fill"}, Case{30000, "bilinear", "v1", "stretch"}}) {
    INFO("budget " << k.budget << " " << k.method << " " << k.blob << " --fit " << k.fit);
    const std::string args = photo() + " --width 64 --height 48 --fit " + k.fit + " --max-bytes " +
                             std::to_string(k.budget) + " -m " + k.method + " --blob " + k.blob + " --resampled " +
                             at("budget.png") + " -o " + at("budget.tri");
    const Run r = run(args + " --json");
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    const long bytes = j.at("blob_bytes").get<long>();
    REQUIRE(bytes <= k.budget);
    REQUIRE(double(bytes) >= 0.85 * double(k.budget));
    REQUIRE(j.at("trials").size() <= 12);
    // tripack writes exactly that many bytes.
    const std::string compress = k.blob == "compressed" ? " --compress" : "";
    REQUIRE(run_tool(TRIPACK_PATH, at("budget.tri") + compress + " -m " + k.method + " -o " + at("budget.bin")).code ==
            0);
    REQUIRE(long(fs::file_size(at("budget.bin"))) == bytes);
    // The PSNR is the one trisim measures for that render against the resampled image.
    const Run c = run_tool(
        TRISIM_PATH, "compare " + at("budget.tri") + " -m " + k.method + " --original " + at("budget.png") + " --json");
    REQUIRE(c.code == 0);
    const double psnr = j.at("psnr").get<double>();
    REQUIRE(psnr == Approx(nlohmann::json::parse(c.out).at("psnr").get<double>()).epsilon(1e-12));
    // The text says the same.
    const Run t = run(args);
    REQUIRE(t.code == 0);
    char expected[200];
    std::snprintf(expected, sizeof expected, "%s blob %ld bytes of %ld", k.blob.c_str(), bytes, k.budget);
    REQUIRE(t.out.find(expected) != std::string::npos);
    std::snprintf(expected, sizeof expected, "PSNR %.2f dB (%s render", psnr, k.method.c_str());
    REQUIRE(t.out.find(expected) != std::string::npos);
  }
}

TEST_CASE("triencode --max-bytes stops at an exact encoding", "[triencode][budget]") {
  // A flat picture is exact with its 4 corners: a larger budget buys nothing.
  write_png(at("flat.png"), Image(40, 30, 3, 90));
  const Run r = run(at("flat.png") + " --max-bytes 5000 --json -o " + at("flat.tri"));
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j.at("vertices").get<int>() == 4);
  REQUIRE(j.at("trials").size() == 1);
  REQUIRE(j.at("psnr").is_null());
  const Run t = run(at("flat.png") + " --max-bytes 5000 -o " + at("flat.tri"));
  REQUIRE(t.out.find("the picture needs no more") != std::string::npos);
}

TEST_CASE("triencode --max-bytes is deterministic", "[triencode][budget]") {
  const std::string args = photo() + " --max-bytes 2500 --width 64 --height 48 --fit inside -o ";
  REQUIRE(run(args + at("m1.tri")).code == 0);
  REQUIRE(run(args + at("m2.tri")).code == 0);
  REQUIRE(slurp(at("m1.tri")) == slurp(at("m2.tri")));
}

TEST_CASE("triencode --max-bytes below the smallest blob: 64", "[triencode][budget]") {
  const Run r = run(photo() + " --max-bytes 40 -o " + at("tiny.tri"));
  REQUIRE(r.code == 64);
  REQUIRE(r.err.find("--max-bytes 40") != std::string::npos);
  REQUIRE(r.err.find("the smallest compressed blob") != std::string::npos);
  REQUIRE(!fs::exists(at("tiny.tri")));
  const Run v1 = run(photo() + " --max-bytes 100 --blob v1 --width 40 --height 40 --resampled " + at("tiny.png") +
                     " -o " + at("tiny.tri"));
  REQUIRE(v1.code == 64);
  REQUIRE(v1.err.find("the smallest v1 blob") != std::string::npos);
  REQUIRE(!fs::exists(at("tiny.tri")));
  REQUIRE(!fs::exists(at("tiny.png")));
}

TEST_CASE("triencode panel and budget usage errors: 64", "[triencode][panel]") {
  const std::string out = " -o " + at("usage.tri");
  auto refused = [&](const std::string& args, const char* says) {
    const Run r = run(photo() + " " + args + out);
    INFO(args << ": " << r.err);
    REQUIRE(r.code == 64);
    REQUIRE(r.err.find(says) != std::string::npos);
  };
  refused("-n 10 --fit inside", "--fit: applies with --width and --height");
  refused("-n 10 --resampled " + at("r.png"), "--resampled: applies with --width and --height");
  refused("-n 10 --width 40", "--width: give the panel's --width and --height together");
  refused("-n 10 --height 40", "--height: give the panel's --width and --height together");
  refused("-n 10 --width 40 --height 40 --fit squash", "expected stretch, inside or fill");
  refused("-n 10 --width 40 --height 40 --fit pixel", "--values pixel");
  refused("-n 10 --width 1 --height 40", "--width");
  refused("-n 10 --max-bytes 5000", "--max-bytes");
  refused("-e 5 --max-bytes 5000", "--max-bytes");
  refused("-n 10 --gradient-step 3", "--gradient-step: applies to --method zienkiewicz or clough-tocher only");
  refused("-n 10 -m zienkiewicz --gradient-step 13", "--gradient-step");
  refused("-n 10 -m zienkiewicz --values pixel", "--values lsq only");
  refused("--max-bytes 5000 -m clough-tocher", "--method clough-tocher: the core does not draw it");
  refused("--max-bytes 0", "--max-bytes");
  refused("--max-bytes 5000 -m bezier", "--method");
  refused("", "--max-bytes");
  refused("-n 10 --width 2 --height 300 --fit inside", "expected at least 2 a side");
  REQUIRE(!fs::exists(at("usage.tri")));
}
