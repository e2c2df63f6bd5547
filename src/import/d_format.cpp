// The classic course format `.d`: a reader that names the file and line of every problem.
// Written here at load time; the mesh it returns is read by the renderer like any other. (Reading
// a file of it is d_import.cpp: this file parses text alone, so its fuzz target links it alone.)
//
//   data <vertices> <polygons>     optional header
//   x y z                          one line per vertex
//   n i1 i2 ... in                 one line per convex polygon, 1-based, fan-triangulated
//
// `#` starts a comment; blank lines are allowed anywhere. Without a header, vertex lines are
// the leading lines of exactly three numbers and every line after them is a polygon.
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "facet/error.hpp"
#include "import/import_internal.hpp"

namespace facet {
namespace io {
namespace {

// A polygon line costs at least 2 bytes per index ("1 "), so no honest file has more.
constexpr std::size_t kMaxPolygonVertices = 1u << 20;

struct Line {
  std::size_t number = 0;                // 1-based, for messages
  std::vector<std::string_view> tokens;  // comment stripped
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  // The next line with at least one token, or false at the end of the text.
  bool next(Line& line) {
    while (position_ < text_.size()) {
      std::size_t end = text_.find('\n', position_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view content = text_.substr(position_, end - position_);
      position_ = end + 1;
      ++number_;
      content = content.substr(0, content.find('#'));
      split(content, line.tokens);
      if (!line.tokens.empty()) {
        line.number = number_;
        return true;
      }
    }
    return false;
  }

  std::size_t last_line() const { return number_; }

  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw Error(name_ + ":" + std::to_string(line) + ": " + what);
  }

 private:
  static void split(std::string_view s, std::vector<std::string_view>& out) {
    out.clear();
    constexpr std::string_view kSpace = " \t\r\v\f";
    std::size_t i = s.find_first_not_of(kSpace);
    while (i != std::string_view::npos) {
      std::size_t j = s.find_first_of(kSpace, i);
      out.push_back(s.substr(i, j == std::string_view::npos ? j : j - i));
      i = j == std::string_view::npos ? j : s.find_first_not_of(kSpace, j);
    }
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t position_ = 0;
  std::size_t number_ = 0;
};

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 24;  // keep one-line messages short whatever the input
  std::string out = "'";
  out.append(token.substr(0, kShown));
  out.append(token.size() > kShown ? "...'" : "'");
  return out;
}

bool parse_integer(std::string_view token, long long& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), out);
  return error == std::errc() && end == token.data() + token.size();
}

float parse_coordinate(const Reader& reader, const Line& line, std::string_view token) {
  std::string_view digits = token;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  float value = 0.0f;
  auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range || (error == std::errc() && !std::isfinite(value))) {
    reader.fail(line.number, "coordinate " + quoted(token) + " is not a finite number");
  }
  if (error != std::errc() || end != digits.data() + digits.size()) {
    reader.fail(line.number, quoted(token) + " is not a number");
  }
  return value;
}

bool is_header(const Line& line) { return line.tokens[0] == "data"; }

struct Header {
  long long vertices = -1;  // -1: no header
  long long polygons = -1;
};

Header parse_header(const Reader& reader, const Line& line) {
  Header h;
  if (line.tokens.size() != 3 || !parse_integer(line.tokens[1], h.vertices) ||
      !parse_integer(line.tokens[2], h.polygons) || h.vertices < 0 || h.polygons < 0) {
    reader.fail(line.number, "the header must be 'data <vertex count> <polygon count>'");
  }
  return h;
}

glm::vec3 parse_vertex(const Reader& reader, const Line& line) {
  if (line.tokens.size() != 3) {
    reader.fail(line.number, "a vertex needs 3 coordinates (x y z), found " +
                                 std::to_string(line.tokens.size()) + " numbers");
  }
  return {parse_coordinate(reader, line, line.tokens[0]),
          parse_coordinate(reader, line, line.tokens[1]),
          parse_coordinate(reader, line, line.tokens[2])};
}

// Appends the polygon's fan triangles (0-based indices) to mesh.indices.
void parse_polygon(const Reader& reader, const Line& line, Mesh& mesh) {
  long long count = 0;
  if (!parse_integer(line.tokens[0], count)) {
    reader.fail(line.number,
                "a polygon line starts with its vertex count, found " + quoted(line.tokens[0]));
  }
  if (count < 3) {
    reader.fail(line.number,
                "a polygon needs at least 3 vertices, this one has " + std::to_string(count));
  }
  const std::size_t listed = line.tokens.size() - 1;
  if (static_cast<unsigned long long>(count) != listed) {
    reader.fail(line.number, "the polygon says " + std::to_string(count) + " vertices but lists " +
                                 std::to_string(listed));
  }
  if (listed > kMaxPolygonVertices) reader.fail(line.number, "the polygon is too large");
  const long long vertex_count = static_cast<long long>(mesh.positions.size());
  std::vector<std::uint32_t> corners(listed);
  for (std::size_t k = 0; k < listed; ++k) {
    long long index = 0;
    std::string_view token = line.tokens[k + 1];
    bool parsed = parse_integer(token, index);
    if (!parsed && token.find_first_not_of("+-0123456789") != std::string_view::npos) {
      reader.fail(line.number, "polygon index " + quoted(token) + " is not a whole number");
    }
    if (!parsed || index < 1 || index > vertex_count) {  // not parsed: too many digits
      reader.fail(line.number, "polygon index " + std::string(token.substr(0, 24)) +
                                   " is out of range (1.." + std::to_string(vertex_count) + ")");
    }
    corners[k] = static_cast<std::uint32_t>(index - 1);
  }
  for (std::size_t k = 1; k + 1 < listed; ++k) {
    mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
  }
}

// The format does not say which way polygons wind. A closed model wound clockwise has a negative
// signed volume; reversing it makes the smooth normals point outward.
void orient_outward(Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
        c(mesh.positions[mesh.indices[i + 2]]);
    volume += glm::dot(a, glm::cross(b, c));
  }
  if (!(volume < 0.0)) return;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  }
}

}  // namespace

Mesh parse_d_geometry(std::string_view text, const std::string& name) {
  Reader reader(text, name);
  Mesh mesh;
  Line line;
  bool have_line = reader.next(line);
  Header header;
  if (have_line && is_header(line)) {
    header = parse_header(reader, line);
    have_line = reader.next(line);
  }
  // Vertex lines: as many as the header says, or (without one) every leading 3-number line.
  while (have_line &&
         (header.vertices >= 0 ? static_cast<long long>(mesh.positions.size()) < header.vertices
                               : line.tokens.size() == 3)) {
    if (header.vertices >= 0 && line.tokens.size() != 3) {
      reader.fail(line.number, "the header says " + std::to_string(header.vertices) +
                                   " vertices but only " + std::to_string(mesh.positions.size()) +
                                   " come before this line (a vertex is x y z)");
    }
    mesh.positions.push_back(parse_vertex(reader, line));
    have_line = reader.next(line);
  }
  if (header.vertices > static_cast<long long>(mesh.positions.size())) {
    reader.fail(reader.last_line(), "the header says " + std::to_string(header.vertices) +
                                        " vertices but the file has " +
                                        std::to_string(mesh.positions.size()));
  }
  long long polygons = 0;
  for (; have_line; have_line = reader.next(line), ++polygons) {
    if (header.polygons >= 0 && polygons == header.polygons) {
      reader.fail(line.number, "the header says " + std::to_string(header.polygons) +
                                   " polygons but there are more lines");
    }
    parse_polygon(reader, line, mesh);
  }
  if (header.polygons > polygons) {
    reader.fail(reader.last_line(), "the header says " + std::to_string(header.polygons) +
                                        " polygons but the file has " + std::to_string(polygons));
  }
  orient_outward(mesh);
  return mesh;
}

}  // namespace io

Mesh parse_d(const std::string& text, const std::string& name) {
  Mesh mesh = io::parse_d_geometry(text, name);
  compute_smooth_normals(mesh);
  return mesh;
}

}  // namespace facet
