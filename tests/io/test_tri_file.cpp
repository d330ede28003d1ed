// SPDX-License-Identifier: MIT
#include <catch2/catch.hpp>
#include <random>
#include <string>

#include "../support/random_mesh.h"
#include "common/errors.h"
#include "geometry/predicates.h"
#include "io/tri_file.h"

using namespace tristream;

namespace {

const char* square = R"(tri 1
# a comment line
size 10 10
channels grey

vertices 4
0 0 0      # corner
9 0 255
9 9 128.5
0 9 3
triangles 2
0 1 2
0 3 2     # clockwise on purpose
)";

bool same(const Triangulation& a, const Triangulation& b) {
  if (a.width != b.width || a.height != b.height || a.space != b.space || a.layers.size() != b.layers.size())
    return false;
  for (std::size_t l = 0; l < a.layers.size(); ++l) {
    const Mesh &p = a.layers[l], &q = b.layers[l];
    if (p.value_count != q.value_count || p.values != q.values || p.points.size() != q.points.size()) return false;
    for (std::size_t i = 0; i < p.points.size(); ++i)
      if (p.points[i].x != q.points[i].x || p.points[i].y != q.points[i].y) return false;
    if (p.triangles.size() != q.triangles.size()) return false;
    for (std::size_t t = 0; t < p.triangles.size(); ++t)
      if (p.triangles[t].v != q.triangles[t].v) return false;
  }
  return true;
}

// The parse error for `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_tri(text, "in.tri");
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

std::string header(int n, const char* channels = "grey") {
  return std::string("tri 1\nsize 10 10\nchannels ") + channels + "\nvertices " + std::to_string(n) + "\n";
}

}  // namespace

TEST_CASE("a small file parses, with winding normalized") {
  const Triangulation t = parse_tri(square, "square.tri");
  CHECK(t.width == 10);
  CHECK(t.space == ColorSpace::grey);
  REQUIRE(t.layers.size() == 1);
  const Mesh& m = t.layers[0];
  CHECK(m.vertex_count() == 4);
  CHECK(m.value(2, 0) == 128.5);
  REQUIRE(m.triangles.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) CHECK(m.doubled_area(k) > 0);
}

TEST_CASE("writer output reads back identically") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> frac(0, 1);
  for (int rep = 0; rep < 5; ++rep) {
    Triangulation t;
    t.width = 70;
    t.height = 50;
    t.space = rep % 2 ? ColorSpace::rgb : ColorSpace::grey;
    Mesh m = tristream::testing::random_lattice_mesh(70, 50, 100, 20 + rep, 20, t.channels());
    for (double& v : m.values) v = std::floor(v) + (rep > 2 ? frac(rng) : 0.0);  // decimals too
    for (std::size_t i = 4; i < m.points.size(); ++i)
      if (rep > 2) m.points[i].x = std::min(69.0, m.points[i].x + frac(rng) * 0.1);
    t.layers = {m};
    const std::string text = format_tri(t);
    const Triangulation back = parse_tri(text, "round.tri");
    CHECK(same(t, back));
    CHECK(format_tri(back) == text);
  }
}

TEST_CASE("layered files round-trip and need rgb or ycbcr") {
  Triangulation t;
  t.width = 30;
  t.height = 20;
  t.space = ColorSpace::ycbcr;
  for (int c = 0; c < 3; ++c) t.layers.push_back(tristream::testing::random_lattice_mesh(30, 20, 10 + 5 * c, 40 + c));
  const std::string text = format_tri(t);
  CHECK(text.find("layer cb\n") != std::string::npos);
  CHECK(same(t, parse_tri(text, "layers.tri")));
  CHECK_THAT(error_of("tri 1\nsize 10 10\nchannels grey\nlayers 3\n"), Catch::Contains("in.tri:4:"));
  CHECK_THAT(error_of("tri 1\nsize 10 10\nchannels rgb\nlayers 3\nlayer g\n"),
             Catch::Contains("in.tri:5: expected layer 'r'"));
}

TEST_CASE("no triangles section means Delaunay") {
  std::string text = header(9);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      text += std::to_string(x * 4) + " " + std::to_string(y * 4) + " 1\n";  // cocircular lattice
  const Triangulation a = parse_tri(text, "a.tri");
  const Triangulation b = parse_tri(text + "triangles 0\n", "b.tri");
  CHECK(a.layers[0].triangles.size() == 8);
  CHECK(same(a, b));
  CHECK_THAT(error_of(header(3) + "0 0 1\n1 1 1\n2 2 1\n"), Catch::Contains("collinear"));
}

TEST_CASE("errors name the line, what was expected and what was found") {
  CHECK_THAT(error_of(""), Catch::Contains("in.tri:1: expected 'tri 1', found end of file"));
  CHECK_THAT(error_of("tri 2\n"), Catch::Contains("in.tri:1: expected format version 1"));
  CHECK_THAT(error_of("tri 1\nsize 0 10\n"), Catch::Contains("in.tri:2: expected an image width"));
  CHECK_THAT(error_of("tri 1\nsize 10 10\nchannels cmyk\n"),
             Catch::Contains("in.tri:3: expected 'grey', 'rgb' or 'ycbcr', found 'cmyk'"));
  CHECK_THAT(error_of(header(2)), Catch::Contains("in.tri:4: expected a vertex count"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n"), Catch::Contains("in.tri:6: expected vertex line 2 of 3"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n9 0 256\n"),
             Catch::Contains("in.tri:6: expected a value (a number in 0..255), found '256'"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n10 0 2\n"),
             Catch::Contains("in.tri:6: expected an x coordinate inside the image"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n9 nan 2\n"), Catch::Contains("in.tri:6: expected a y coordinate"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n9 0 2 3\n"),
             Catch::Contains("in.tri:6: expected a vertex line '<x> <y> <value>'"));
  CHECK_THAT(error_of(header(3, "rgb") + "0 0 1\n"), Catch::Contains("'<x> <y> <v0> <v1> <v2>'"));
  CHECK_THAT(
      error_of(header(3) + "0 0 1\n9 0 2\n0 0 5\n"),
      Catch::Contains("in.tri:7: expected distinct vertex positions, found a duplicate of the vertex on line 5"));
  const std::string three = header(3) + "0 0 1\n9 0 2\n0 9 3\n";
  CHECK_THAT(error_of(three + "triangles 1\n0 1 3\n"),
             Catch::Contains("in.tri:9: expected a vertex index (an integer in 0..2), found '3'"));
  CHECK_THAT(error_of(three + "triangles 1\n0 1 1\n"),
             Catch::Contains("in.tri:9: expected three distinct vertex indices"));
  CHECK_THAT(error_of(three + "triangles 2\n0 1 2\n"), Catch::Contains("in.tri:10: expected triangle line 2 of 2"));
  CHECK_THAT(error_of(three + "triangles 1\n0 1 2\nextra\n"),
             Catch::Contains("in.tri:10: expected end of file, found 'extra'"));
  CHECK_THAT(error_of(header(3) + "0 0 1\n4 4 2\n9 9 3\ntriangles 1\n0 1 2\n"),
             Catch::Contains("in.tri:9: expected a triangle of non-zero area"));
  // Two triangles that overlap: (0,0) (9,0) (0,9) and (9,9) (0,9)... shifted so they cross.
  const std::string four = header(4) + "0 0 1\n9 0 2\n0 9 3\n9 9 4\n";
  CHECK(error_of(four + "triangles 2\n0 1 2\n1 3 2\n").empty());
  CHECK_THAT(error_of(four + "triangles 2\n0 1 2\n0 1 3\n"),
             Catch::Contains("in.tri:11: expected triangles whose interiors do not overlap, found a triangle "
                             "overlapping the one on line 10"));
  CHECK_THAT(error_of(four + "triangles 2\n0 1 2\n2 1 0\n"), Catch::Contains("overlapping"));
  // Not edge to edge (issue 17): (10,10) lies inside the edge (0,0)-(20,20) of the first triangle.
  const std::string t_junction =
      "tri 1\nsize 21 21\nchannels grey\nvertices 5\n0 0 0\n20 0 0\n0 20 0\n20 20 0\n10 10 0\n"
      "triangles 3\n0 1 3\n0 4 2\n4 3 2\n";
  CHECK_THAT(error_of(t_junction),
             Catch::Contains("in.tri:11: expected triangles that meet edge to edge (no vertex inside another "
                             "triangle's edge), found the vertex on line 9 inside an edge of this triangle"));
  // Crossing edges, and a triangle inside another.
  CHECK(error_of(four + "triangles 2\n0 1 3\n0 3 2\n").empty());
  CHECK_THAT(error_of(four + "triangles 2\n0 1 3\n1 3 2\n"),
             Catch::Contains("in.tri:11: expected triangles whose interiors do not overlap"));
  CHECK_THAT(error_of(header(6) + "0 0 1\n9 0 2\n0 9 3\n1 1 4\n3 1 5\n1 3 6\ntriangles 2\n0 1 2\n3 4 5\n"),
             Catch::Contains("in.tri:13: expected triangles whose interiors do not overlap, found a triangle "
                             "overlapping the one on line 12"));
}

TEST_CASE("small things of issue 17: a BOM, leading zeros, underflow") {
  const std::string body = "size 10 10\nchannels grey\nvertices 3\n0 0 1\n9 0 2\n0 9 3\n";
  CHECK_NOTHROW(parse_tri("\xEF\xBB\xBFtri 1\n" + body, "bom.tri"));
  CHECK_THAT(error_of("tri 01\n" + body), Catch::Contains("in.tri:1: expected format version 1"));
  CHECK_THAT(error_of("tri 1\nsize 010 10\n"), Catch::Contains("in.tri:2: expected an image width"));
  CHECK_THAT(error_of("tri 1\nsize 10 10\nchannels grey\nvertices +3\n"),
             Catch::Contains("in.tri:4: expected a vertex count"));
  // Too small for a double is zero (as a denormal is nearly zero); too large is out of range.
  const Triangulation t =
      parse_tri("tri 1\nsize 10 10\nchannels grey\nvertices 3\n1e-400 0 1e-400\n9 0 2\n0 9 -1e-999\n", "u.tri");
  CHECK(t.layers[0].points[0].x == 0);
  CHECK(t.layers[0].value(0, 0) == 0);
  CHECK(t.layers[0].value(2, 0) == 0);
  CHECK_NOTHROW(parse_tri("tri 1\nsize 10 10\nchannels grey\nvertices 3\n1e-320 0 1\n9 0 2\n0 9 3\n", "d.tri"));
  CHECK_THAT(error_of("tri 1\nsize 10 10\nchannels grey\nvertices 3\n1e400 0 1\n"),
             Catch::Contains("in.tri:5: expected an x coordinate"));
}

TEST_CASE("files that are missing give InputError") {
  CHECK_THROWS_AS(read_tri_file("/nonexistent/x.tri"), InputError);
}

TEST_CASE("a gradients section: read, written back, and its errors") {
  const std::string three = header(3) + "0 0 1\n9 0 2\n0 9 3\n";
  const Triangulation t = parse_tri(three + "gradients 3\n1.5 -2\n0 0\n0.015625 1e3\ntriangles 1\n0 1 2\n", "in.tri");
  const Mesh& m = t.layers[0];
  REQUIRE(m.has_gradients());
  CHECK(m.gradients == std::vector<double>{1.5, -2, 0, 0, 0.015625, 1000});
  CHECK(m.gradient(2, 0, 1) == 1000);
  const std::string text = format_tri(t);
  CHECK_THAT(text, Catch::Contains("gradients 3\n1.5 -2\n0 0\n0.015625 1000\ntriangles 1\n"));
  CHECK(parse_tri(text, "again.tri").layers[0].gradients == m.gradients);
  CHECK(format_tri(parse_tri(text, "again.tri")) == text);
  // Without the section a mesh has none, and the writer writes none.
  CHECK(!parse_tri(three, "in.tri").layers[0].has_gradients());
  CHECK_THAT(format_tri(parse_tri(three, "in.tri")), !Catch::Contains("gradients"));
  // RGB: six numbers a line; with the Delaunay triangulation (no triangles section).
  const Triangulation rgb = parse_tri(
      header(3, "rgb") + "0 0 1 2 3\n9 0 2 3 4\n0 9 3 4 5\ngradients 3\n1 2 3 4 5 6\n0 0 0 0 0 0\n-1 -2 -3 -4 -5 -6\n",
      "rgb.tri");
  CHECK(rgb.layers[0].gradient(0, 2, 1) == 6);
  CHECK(rgb.layers[0].gradient(2, 1, 0) == -3);
  CHECK_THAT(error_of(three + "gradients 2\n0 0\n0 0\n"),
             Catch::Contains("in.tri:8: expected a gradient count equal to the vertex count 3"));
  CHECK_THAT(error_of(three + "gradients 3\n0 0\n0\n0 0\n"),
             Catch::Contains("in.tri:10: expected a gradient line '<gx> <gy>', found '0'"));
  CHECK_THAT(error_of(three + "gradients 3\n0 0\n0 nan\n0 0\n"),
             Catch::Contains("in.tri:10: expected a gradient in values per pixel"));
  CHECK_THAT(error_of(three + "gradients 3\n0 0\n0 70000\n0 0\n"), Catch::Contains("found '70000'"));
  CHECK_THAT(error_of(three + "gradients 3\n0 0\n"), Catch::Contains("in.tri:10: expected gradient line 2 of 3"));
  CHECK_THAT(error_of(header(3, "rgb") + "0 0 1 2 3\n9 0 2 3 4\n0 9 3 4 5\ngradients 3\n1 2\n"),
             Catch::Contains("'<gx0> <gy0> <gx1> <gy1> <gx2> <gy2>'"));
}
