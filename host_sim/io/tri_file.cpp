// SPDX-License-Identifier: MIT
#include "io/tri_file.h"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/activity.h"
#include "common/errors.h"
#include "geometry/delaunay.h"
#include "geometry/mesh_check.h"
#include "geometry/predicates.h"
#include "io/atomic_file.h"
#include "io/limits.h"

namespace tristream {
namespace {

// Limits that keep a hostile file from asking for absurd amounts of memory.
using limits::max_image_side;
constexpr long max_vertices = 50'000'000;
constexpr long max_triangles = 100'000'000;
constexpr double max_gradient = 65536;  // values per pixel; the core takes far less (config.h)

// 64-bit: a file of more than 2^31 lines cannot reach the reader (limits::max_input_bytes),
// but parse_tri takes any text.
using LineNumber = long long;

struct Line {
  std::string_view text;  // comment stripped, trimmed
  LineNumber number = 0;  // 1-based line number in the file
};

// Whether a decimal number that does not fit a double is too small rather than too large.
bool underflows(std::string_view token) {
  const std::string copy(token);
  errno = 0;
  const double v = std::strtod(copy.c_str(), nullptr);
  return errno == ERANGE && std::fabs(v) < 1;
}

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
    LineNumber number = 0;
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

  [[noreturn]] void fail(LineNumber line, const std::string& expected, const std::string& found) const {
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

  long integer(std::string_view token, LineNumber line, const std::string& what, long lo, long hi) const {
    long value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    const bool digits_only = !token.empty() && token[0] >= '0' && token[0] <= '9';
    const bool leading_zero = token.size() > 1 && token[0] == '0';
    if (ec != std::errc() || ptr != token.data() + token.size() || !digits_only || leading_zero || value < lo ||
        value > hi)
      fail(line, what + " (an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ")", quoted(token));
    return value;
  }

  double number(std::string_view token, LineNumber line, const std::string& what, double lo, double hi) const {
    double value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    // A number too small for a double (1e-400) is 0, as 1e-320 is a denormal: only overflow is out of range.
    if (ec == std::errc::result_out_of_range && ptr == token.data() + token.size() && underflows(token)) {
      value = 0;
      ec = std::errc();
    }
    if (ec != std::errc() || ptr != token.data() + token.size() || !std::isfinite(value) || value < lo ||
        value > hi) {
      char range[64];
      std::snprintf(range, sizeof range, " (a number in %g..%g)", lo, hi);
      fail(line, what + range, quoted(token));
    }
    return value + 0.0;  // folds -0 into +0
  }

  LineNumber current_line() const { return current_; }

 private:
  const std::string& name_;
  std::vector<Line> lines_;
  std::size_t pos_ = 0;
  LineNumber last_line_ = 0;
  LineNumber current_ = 0;
};

std::vector<std::string_view> layer_names(ColorSpace space) {
  if (space == ColorSpace::rgb) return {"r", "g", "b"};
  return {"y", "cb", "cr"};
}

// Rejects triangles whose interiors overlap and meshes that are not edge to edge
// (geometry/mesh_check.h), naming the lines of the triangles and the vertex.
void check_mesh(const Mesh& mesh, const std::vector<LineNumber>& triangle_lines,
                const std::vector<std::uint32_t>& vertex_lines, const Parser& parser) {
  const auto defect = find_mesh_defect(mesh.points, mesh.triangles);
  if (!defect) return;
  if (defect->kind == MeshDefect::Kind::overlap) {
    const auto [first, second] = std::minmax(triangle_lines[defect->a], triangle_lines[defect->b]);
    parser.fail(second, "triangles whose interiors do not overlap",
                "a triangle overlapping the one on line " + std::to_string(first));
  }
  const Triangle& t = mesh.triangles[defect->a];
  parser.fail(triangle_lines[defect->a],
              "triangles that meet edge to edge (no vertex inside another triangle's edge)",
              "the vertex on line " + std::to_string(vertex_lines[defect->vertex]) +
                  " inside an edge of this triangle (vertices on lines " + std::to_string(vertex_lines[t.v[0]]) +
                  ", " + std::to_string(vertex_lines[t.v[1]]) + ", " + std::to_string(vertex_lines[t.v[2]]) + ")");
}

Mesh parse_mesh(Parser& parser, int value_count, int width, int height, const std::string& layer) {
  Mesh mesh;
  mesh.name = layer;
  mesh.value_count = value_count;
  auto header = parser.keyword_line("vertices", 1, "vertices <N>");
  const long n = parser.integer(header[1], parser.current_line(), "a vertex count", 3, max_vertices);
  mesh.points.reserve(std::size_t(std::min(n, 1L << 20)));
  mesh.values.reserve(std::size_t(std::min(n, 1L << 20)) * value_count);

  std::vector<std::uint32_t>& vertex_lines = mesh.vertex_lines;  // a file of at most 1 GiB has fewer lines
  // Duplicate detection: position -> vertex. Exact bit patterns (-0 is folded into +0 on reading).
  struct PointHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const {
      return std::hash<std::uint64_t>()(k.first * 0x9E3779B97F4A7C15ull ^ k.second);
    }
  };
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, std::uint32_t, PointHash> by_position;
  by_position.reserve(std::size_t(std::min(n, 1L << 20)));
  const std::string values_usage = value_count == 1 ? "<x> <y> <value>" : "<x> <y> <v0> <v1> <v2>";
  for (long i = 0; i < n; ++i) {
    Line line = parser.next("vertex line " + std::to_string(i + 1) + " of " + std::to_string(n) + " ('" +
                            values_usage + "')");
    auto tokens = Parser::split(line.text);
    if (tokens.size() != std::size_t(2 + value_count))
      parser.fail(line.number, "a vertex line '" + values_usage + "'", quoted(line.text));
    Point p{parser.number(tokens[0], line.number, "an x coordinate inside the image", 0, width - 1),
            parser.number(tokens[1], line.number, "a y coordinate inside the image", 0, height - 1)};
    std::pair<std::uint64_t, std::uint64_t> key;
    std::memcpy(&key.first, &p.x, sizeof key.first);
    std::memcpy(&key.second, &p.y, sizeof key.second);
    const auto [same, fresh] = by_position.try_emplace(key, std::uint32_t(mesh.points.size()));
    if (!fresh)
      parser.fail(line.number, "distinct vertex positions",
                  "a duplicate of the vertex on line " + std::to_string(vertex_lines[same->second]));
    mesh.points.push_back(p);
    vertex_lines.push_back(std::uint32_t(line.number));
    for (int c = 0; c < value_count; ++c)
      mesh.values.push_back(parser.number(tokens[2 + c], line.number, "a value", 0, 255));
  }

  if (!parser.at_end() && Parser::split(parser.peek().text)[0] == "gradients") {
    auto gh = parser.keyword_line("gradients", 1, "gradients <N>");
    const LineNumber gradients_line = parser.current_line();
    parser.integer(gh[1], gradients_line, "a gradient count equal to the vertex count " + std::to_string(n), n, n);
    const std::string usage = value_count == 1 ? "<gx> <gy>" : "<gx0> <gy0> <gx1> <gy1> <gx2> <gy2>";
    mesh.gradients.reserve(mesh.values.size() * 2);
    for (long i = 0; i < n; ++i) {
      Line line =
          parser.next("gradient line " + std::to_string(i + 1) + " of " + std::to_string(n) + " ('" + usage + "')");
      auto tokens = Parser::split(line.text);
      if (tokens.size() != std::size_t(2 * value_count))
        parser.fail(line.number, "a gradient line '" + usage + "'", quoted(line.text));
      for (const auto& token : tokens)
        mesh.gradients.push_back(
            parser.number(token, line.number, "a gradient in values per pixel", -max_gradient, max_gradient));
    }
  }

  const bool has_triangles = !parser.at_end() && Parser::split(parser.peek().text)[0] == "triangles";
  long m = 0;
  LineNumber triangles_line = 0;
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
    mesh.triangulated_by_reader = true;
    return mesh;
  }

  std::vector<LineNumber> triangle_lines;
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
  check_mesh(mesh, triangle_lines, vertex_lines, parser);
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
  if (mesh.has_gradients()) {
    out += "gradients " + std::to_string(mesh.points.size()) + "\n";
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
      for (int k = 0; k < 2 * mesh.value_count; ++k) {
        if (k) out += ' ';
        out += format_number(mesh.gradients[i * 2 * mesh.value_count + std::size_t(k)]);
      }
      out += '\n';
    }
  }
  out += "triangles " + std::to_string(mesh.triangles.size()) + "\n";
  for (const Triangle& t : mesh.triangles)
    out += std::to_string(t.v[0]) + " " + std::to_string(t.v[1]) + " " + std::to_string(t.v[2]) + "\n";
}

}  // namespace

Triangulation parse_tri(std::string_view text, const std::string& source_name) {
  constexpr std::string_view bom = "\xEF\xBB\xBF";  // a UTF-8 byte order mark is skipped
  if (text.substr(0, bom.size()) == bom) text.remove_prefix(bom.size());
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

Triangulation read_tri_file(const std::string& path) {
  const Activity activity("reading " + path);
  return parse_tri(read_file(path), path);
}

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
