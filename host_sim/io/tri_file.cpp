#include "io/tri_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/errors.h"
#include "geometry/delaunay.h"
#include "geometry/predicates.h"
#include "io/atomic_file.h"
#include "io/limits.h"

namespace tristream {
namespace {

// Limits that keep a hostile file from asking for absurd amounts of memory.
using limits::max_image_side;
constexpr long max_vertices = 50'000'000;
constexpr long max_triangles = 100'000'000;

struct Line {
  std::string_view text;  // comment stripped, trimmed
  int number = 0;         // 1-based line number in the file
};

std::string quoted(std::string_view s) {
  constexpr std::size_t shown = 60;
  std::string out = "'";
  out.append(s.substr(0, shown));
  if (s.size() > shown) out += "...";
  return out + "'";
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& name) : name_(name) {
    int number = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++number;
      std::string_view line = text.substr(start, end - start);
      if (std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      const auto first = line.find_first_not_of(" \t\r\f\v");
      if (first != std::string_view::npos) {
        const auto last = line.find_last_not_of(" \t\r\f\v");
        lines_.push_back({line.substr(first, last - first + 1), number});
      }
      if (end == text.size()) break;
      start = end + 1;
    }
    last_line_ = number;
  }

  [[noreturn]] void fail(int line, const std::string& expected, const std::string& found) const {
    throw DataError(name_ + ":" + std::to_string(line) + ": expected " + expected + ", found " + found);
  }

  bool at_end() const { return pos_ == lines_.size(); }
  const Line& peek() const { return lines_[pos_]; }

  Line next(const std::string& expected) {
    if (at_end()) fail(last_line_, expected, "end of file");
    return lines_[pos_++];
  }

  static std::vector<std::string_view> split(std::string_view s) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
      std::size_t j = i;
      while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
      if (j > i) out.push_back(s.substr(i, j - i));
      i = j;
    }
    return out;
  }

  // A line "<keyword> <arg>..." with exactly `args` arguments.
  std::vector<std::string_view> keyword_line(std::string_view keyword, std::size_t args, const std::string& usage) {
    Line line = next("'" + usage + "'");
    auto tokens = split(line.text);
    if (tokens.empty() || tokens[0] != keyword || tokens.size() != args + 1)
      fail(line.number, "'" + usage + "'", quoted(line.text));
    current_ = line.number;
    return tokens;
  }

  long integer(std::string_view token, int line, const std::string& what, long lo, long hi) const {
    long value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size() || value < lo || value > hi)
      fail(line, what + " (an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ")", quoted(token));
    return value;
  }

  double number(std::string_view token, int line, const std::string& what, double lo, double hi) const {
    double value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size() || !std::isfinite(value) || value < lo ||
        value > hi) {
      char range[64];
      std::snprintf(range, sizeof range, " (a number in %g..%g)", lo, hi);
      fail(line, what + range, quoted(token));
    }
    return value + 0.0;  // folds -0 into +0
  }

  int current_line() const { return current_; }

 private:
  const std::string& name_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  int last_line_ = 0;
  int current_ = 0;
};

std::vector<std::string_view> layer_names(ColorSpace space) {
  if (space == ColorSpace::rgb) return {"r", "g", "b"};
  return {"y", "cb", "cr"};
}

// Rejects triangles whose interiors overlap. Pairs are found through a uniform grid of
// about one cell per triangle; each pair is tested once, by the separating-axis test with
// exact orientation predicates (triangles are normalized to positive orientation).
void check_no_overlap(const Mesh& mesh, const std::vector<int>& lines, const Parser& parser) {
  const std::size_t n = mesh.triangles.size();
  if (n < 2) return;
  struct Box {
    double x0, y0, x1, y1;
  };
  std::vector<Box> boxes(n);
  Box all{1e300, 1e300, -1e300, -1e300};
  for (std::size_t t = 0; t < n; ++t) {
    Box b{1e300, 1e300, -1e300, -1e300};
    for (auto v : mesh.triangles[t].v) {
      const Point& p = mesh.points[v];
      b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
    }
    boxes[t] = b;
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
  }
  const int side = std::max(1, int(std::sqrt(double(n))));
  const double cw = std::max(all.x1 - all.x0, 1e-9) / side;
  const double ch = std::max(all.y1 - all.y0, 1e-9) / side;
  auto cell_x = [&](double x) { return std::clamp(int((x - all.x0) / cw), 0, side - 1); };
  auto cell_y = [&](double y) { return std::clamp(int((y - all.y0) / ch), 0, side - 1); };

  std::vector<std::uint32_t> start(std::size_t(side) * side + 1, 0);
  for (std::size_t t = 0; t < n; ++t)
    for (int cy = cell_y(boxes[t].y0); cy <= cell_y(boxes[t].y1); ++cy)
      for (int cx = cell_x(boxes[t].x0); cx <= cell_x(boxes[t].x1); ++cx) ++start[cy * side + cx + 1];
  for (std::size_t c = 0; c + 1 < start.size(); ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> items(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int cy = cell_y(boxes[t].y0); cy <= cell_y(boxes[t].y1); ++cy)
      for (int cx = cell_x(boxes[t].x0); cx <= cell_x(boxes[t].x1); ++cx) items[fill[cy * side + cx]++] = t;

  auto separated = [&](std::uint32_t a, std::uint32_t b) {
    const auto& ta = mesh.triangles[a].v;
    const auto& tb = mesh.triangles[b].v;
    for (int e = 0; e < 3; ++e) {
      const Point& p = mesh.points[ta[e]];
      const Point& q = mesh.points[ta[(e + 1) % 3]];
      if (orient2d(p, q, mesh.points[tb[0]]) <= 0 && orient2d(p, q, mesh.points[tb[1]]) <= 0 &&
          orient2d(p, q, mesh.points[tb[2]]) <= 0)
        return true;
    }
    return false;
  };

  for (int cy = 0; cy < side; ++cy)
    for (int cx = 0; cx < side; ++cx) {
      const std::size_t c = std::size_t(cy) * side + cx;
      for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
        for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
          const std::uint32_t a = items[i], b = items[j];
          const Box& ba = boxes[a];
          const Box& bb = boxes[b];
          const double ix0 = std::max(ba.x0, bb.x0), iy0 = std::max(ba.y0, bb.y0);
          if (ix0 > std::min(ba.x1, bb.x1) || iy0 > std::min(ba.y1, bb.y1)) continue;
          if (cell_x(ix0) != cx || cell_y(iy0) != cy) continue;  // the pair is tested in one cell only
          if (!separated(a, b) && !separated(b, a)) {
            const auto [first, second] = std::minmax(a, b);
            parser.fail(lines[second], "triangles whose interiors do not overlap",
                        "a triangle overlapping the one on line " + std::to_string(lines[first]));
          }
        }
    }
}

Mesh parse_mesh(Parser& parser, int value_count, int width, int height, const std::string& layer) {
  Mesh mesh;
  mesh.name = layer;
  mesh.value_count = value_count;
  auto header = parser.keyword_line("vertices", 1, "vertices <N>");
  const long n = parser.integer(header[1], parser.current_line(), "a vertex count", 3, max_vertices);
  mesh.points.reserve(std::size_t(std::min(n, 1L << 20)));
  mesh.values.reserve(std::size_t(std::min(n, 1L << 20)) * value_count);

  std::vector<int> vertex_lines;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> by_x;  // duplicate detection
  const std::string values_usage = value_count == 1 ? "<x> <y> <value>" : "<x> <y> <v0> <v1> <v2>";
  for (long i = 0; i < n; ++i) {
    Line line = parser.next("vertex line " + std::to_string(i + 1) + " of " + std::to_string(n) + " ('" +
                            values_usage + "')");
    auto tokens = Parser::split(line.text);
    if (tokens.size() != std::size_t(2 + value_count))
      parser.fail(line.number, "a vertex line '" + values_usage + "'", quoted(line.text));
    Point p{parser.number(tokens[0], line.number, "an x coordinate inside the image", 0, width - 1),
            parser.number(tokens[1], line.number, "a y coordinate inside the image", 0, height - 1)};
    std::uint64_t key;
    std::memcpy(&key, &p.x, sizeof key);
    auto& same_x = by_x[key];
    for (std::uint32_t other : same_x)
      if (mesh.points[other].y == p.y)
        parser.fail(line.number, "distinct vertex positions",
                    "a duplicate of the vertex on line " + std::to_string(vertex_lines[other]));
    same_x.push_back(std::uint32_t(mesh.points.size()));
    mesh.points.push_back(p);
    vertex_lines.push_back(line.number);
    for (int c = 0; c < value_count; ++c)
      mesh.values.push_back(parser.number(tokens[2 + c], line.number, "a value", 0, 255));
  }

  const bool has_triangles = !parser.at_end() && Parser::split(parser.peek().text)[0] == "triangles";
  long m = 0;
  int triangles_line = 0;
  if (has_triangles) {
    auto th = parser.keyword_line("triangles", 1, "triangles <M>");
    triangles_line = parser.current_line();
    m = parser.integer(th[1], triangles_line, "a triangle count", 0, max_triangles);
  }
  if (m == 0) {
    mesh.triangles = delaunay_triangulation(mesh.points);
    if (mesh.triangles.empty())
      parser.fail(triangles_line ? triangles_line : vertex_lines.back(),
                  "vertices that are not all collinear (for the Delaunay triangulation)", "collinear vertices");
    return mesh;
  }

  std::vector<int> triangle_lines;
  mesh.triangles.reserve(std::size_t(std::min(m, 1L << 20)));
  for (long t = 0; t < m; ++t) {
    Line line = parser.next("triangle line " + std::to_string(t + 1) + " of " + std::to_string(m) + " ('<i> <j> <k>')");
    auto tokens = Parser::split(line.text);
    if (tokens.size() != 3) parser.fail(line.number, "a triangle line '<i> <j> <k>'", quoted(line.text));
    Triangle tri;
    for (int k = 0; k < 3; ++k)
      tri.v[k] = std::uint32_t(parser.integer(tokens[k], line.number, "a vertex index", 0, n - 1));
    if (tri.v[0] == tri.v[1] || tri.v[1] == tri.v[2] || tri.v[0] == tri.v[2])
      parser.fail(line.number, "three distinct vertex indices", quoted(line.text));
    const auto o = orient2d(mesh.points[tri.v[0]], mesh.points[tri.v[1]], mesh.points[tri.v[2]]);
    if (o == 0) parser.fail(line.number, "a triangle of non-zero area", "three collinear vertices");
    if (o < 0) std::swap(tri.v[1], tri.v[2]);
    mesh.triangles.push_back(tri);
    triangle_lines.push_back(line.number);
  }
  check_no_overlap(mesh, triangle_lines, parser);
  return mesh;
}

std::string format_number(double v) {
  char buf[64];
  auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, ptr);
}

void format_mesh(std::string& out, const Mesh& mesh) {
  out += "vertices " + std::to_string(mesh.points.size()) + "\n";
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    out += format_number(mesh.points[i].x);
    out += ' ';
    out += format_number(mesh.points[i].y);
    for (int c = 0; c < mesh.value_count; ++c) {
      out += ' ';
      out += format_number(mesh.value(i, c));
    }
    out += '\n';
  }
  out += "triangles " + std::to_string(mesh.triangles.size()) + "\n";
  for (const Triangle& t : mesh.triangles)
    out += std::to_string(t.v[0]) + " " + std::to_string(t.v[1]) + " " + std::to_string(t.v[2]) + "\n";
}

}  // namespace

Triangulation parse_tri(std::string_view text, const std::string& source_name) {
  Parser parser(text, source_name);
  Triangulation tri;

  auto magic = parser.keyword_line("tri", 1, "tri 1");
  parser.integer(magic[1], parser.current_line(), "format version 1", 1, 1);

  auto size = parser.keyword_line("size", 2, "size <W> <H>");
  tri.width = int(parser.integer(size[1], parser.current_line(), "an image width", 1, max_image_side));
  tri.height = int(parser.integer(size[2], parser.current_line(), "an image height", 1, max_image_side));
  if (tri.width < 2 && tri.height < 2)
    parser.fail(parser.current_line(), "an image of at least 2 pixels", "1 x 1");

  auto channels = parser.keyword_line("channels", 1, "channels <grey|rgb|ycbcr>");
  if (channels[1] == "grey") tri.space = ColorSpace::grey;
  else if (channels[1] == "rgb") tri.space = ColorSpace::rgb;
  else if (channels[1] == "ycbcr") tri.space = ColorSpace::ycbcr;
  else parser.fail(parser.current_line(), "'grey', 'rgb' or 'ycbcr'", quoted(channels[1]));

  const bool layered = !parser.at_end() && Parser::split(parser.peek().text)[0] == "layers";
  if (layered) {
    auto layers = parser.keyword_line("layers", 1, "layers 3");
    if (tri.space == ColorSpace::grey)
      parser.fail(parser.current_line(), "no 'layers' line for a grey image (layers need rgb or ycbcr)",
                  "'layers'");
    parser.integer(layers[1], parser.current_line(), "3 layers (one per channel)", 3, 3);
    const auto names = layer_names(tri.space);
    for (std::string_view name : names) {
      auto header = parser.keyword_line("layer", 1, "layer " + std::string(name));
      if (header[1] != name)
        parser.fail(parser.current_line(), "layer '" + std::string(name) + "' (layers come in channel order)",
                    quoted(header[1]));
      tri.layers.push_back(parse_mesh(parser, 1, tri.width, tri.height, std::string(name)));
    }
  } else {
    tri.layers.push_back(parse_mesh(parser, tri.channels(), tri.width, tri.height, ""));
  }
  if (!parser.at_end()) parser.fail(parser.peek().number, "end of file", quoted(parser.peek().text));
  return tri;
}

Triangulation read_tri_file(const std::string& path) { return parse_tri(read_file(path), path); }

std::string format_tri(const Triangulation& tri) {
  std::string out = "tri 1\n";
  out += "size " + std::to_string(tri.width) + " " + std::to_string(tri.height) + "\n";
  out += "channels " + std::string(to_string(tri.space)) + "\n";
  if (tri.layered()) {
    out += "layers " + std::to_string(tri.layers.size()) + "\n";
    const auto names = layer_names(tri.space);
    for (std::size_t i = 0; i < tri.layers.size(); ++i) {
      out += "layer " + std::string(names.at(i)) + "\n";
      format_mesh(out, tri.layers[i]);
    }
  } else {
    format_mesh(out, tri.layers.at(0));
  }
  return out;
}

void write_tri_file(const std::string& path, const Triangulation& tri) {
  write_file_atomically(path, format_tri(tri));
}

}  // namespace tristream
