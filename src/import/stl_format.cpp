// STL bytes to welded geometry (stl_format.hpp says the format): binary files read in parallel
// chunks straight into the corner list, ASCII files token by token; both then welded
// (stl_weld.cpp). Runs once per model at load time; the renderer reads the mesh.
//
// Every count is checked against the file's size before anything is sized from it, so a
// damaged or hostile file gives one facet::Error "<name>: <what>", never a crash, a hang or an
// allocation the file cannot back.
#include "import/stl_format.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "facet/error.hpp"

namespace facet::io::stl {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kRecordBytes = 50;
// Triangles a task reads at once: 1.6 MB of file, enough to outweigh a task's start and a read.
constexpr std::size_t kTrianglesPerTask = 1 << 15;

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

float little_endian_float(const unsigned char* bytes) {
  const std::uint32_t word = std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 |
                             std::uint32_t{bytes[2]} << 16 | std::uint32_t{bytes[3]} << 24;
  return std::bit_cast<float>(word);
}

glm::vec3 little_endian_vec3(const unsigned char* bytes) {
  // + 0: -0 becomes +0, so the two weld (they are the same point).
  return glm::vec3(little_endian_float(bytes) + 0.0f, little_endian_float(bytes + 4) + 0.0f,
                   little_endian_float(bytes + 8) + 0.0f);
}

// Whether the facet normals can shade the model (Geometry::facet_normals_usable), gathered per
// range of triangles and then merged in range order.
struct NormalCheck {
  bool any = false, bad = false, differ = false;
  glm::vec3 first{0.0f};
  void add(const glm::vec3& n) {
    if (!finite(n) || (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f)) bad = true;
    if (!any) {
      any = true;
      first = n;
    } else if (n != first) {
      differ = true;
    }
  }
  void merge(const NormalCheck& other) {
    if (!other.any) return;
    bad = bad || other.bad;
    if (any) {
      differ = differ || other.differ || other.first != first;
    } else {
      *this = other;
    }
  }
  bool usable() const { return any && !bad && differ; }
};

std::string plural(std::uint64_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// ---- binary ------------------------------------------------------------------------------

// Materialise's "COLOR=" followed by red, green, blue and alpha bytes, anywhere in the header.
std::optional<glm::vec4> header_color(const unsigned char* header) {
  const std::string_view text(reinterpret_cast<const char*>(header), kHeaderBytes);
  const std::size_t at = text.find("COLOR=");
  if (at == std::string_view::npos || at + 10 > kHeaderBytes) return std::nullopt;
  const unsigned char* c = header + at + 6;
  return glm::vec4(c[0], c[1], c[2], c[3]) / 255.0f;
}

Geometry parse_binary(const Source& source, const std::string& name) {
  Geometry out;
  out.binary = true;
  unsigned char header[kHeaderBytes + 4];
  if (source.size < sizeof header) {
    throw Error(name + ": binary STL of " + std::to_string(source.size) +
                " bytes is shorter than its 84-byte header");
  }
  source.read(0, sizeof header, reinterpret_cast<char*>(header));
  const std::uint64_t count = std::uint64_t{header[80]} | std::uint64_t{header[81]} << 8 |
                              std::uint64_t{header[82]} << 16 | std::uint64_t{header[83]} << 24;
  const std::uint64_t needed = sizeof header + kRecordBytes * count;
  if (source.size < needed) {
    throw Error(name + ": binary STL claims " + plural(count, "triangle") + " (" +
                std::to_string(needed) + " bytes) but the file is " + std::to_string(source.size) +
                " bytes: truncated or not an STL file");
  }
  if (count > kMaxTriangles) {
    throw Error(name + ": " + plural(count, "triangle") + ", more than facet can index (" +
                std::to_string(kMaxTriangles) + ")");
  }
  out.color = header_color(header);

  // Each task reads its range of records and writes the triangles it keeps to the start of its
  // range of corners; the ranges are closed up afterwards if any triangle was left out.
  struct Range {
    std::size_t kept = 0, non_finite = 0, colored = 0;
    NormalCheck normals;
  };
  const auto triangles = static_cast<std::size_t>(count);
  const int tasks = static_cast<int>((triangles + kTrianglesPerTask - 1) / kTrianglesPerTask);
  std::vector<Range> ranges(static_cast<std::size_t>(tasks));
  std::vector<glm::vec3> corners(triangles * 3);
  parallel_tasks(tasks, [&](int task) {
    const std::size_t begin = static_cast<std::size_t>(task) * kTrianglesPerTask;
    const std::size_t end = std::min(triangles, begin + kTrianglesPerTask);
    std::vector<unsigned char> bytes((end - begin) * kRecordBytes);
    source.read(sizeof header + begin * kRecordBytes, bytes.size(),
                reinterpret_cast<char*>(bytes.data()));
    Range& range = ranges[static_cast<std::size_t>(task)];
    for (std::size_t t = 0; t < end - begin; ++t) {
      const unsigned char* record = bytes.data() + t * kRecordBytes;
      const glm::vec3 a = little_endian_vec3(record + 12), b = little_endian_vec3(record + 24),
                      c = little_endian_vec3(record + 36);
      if (!finite(a) || !finite(b) || !finite(c)) {
        ++range.non_finite;
        continue;
      }
      range.normals.add(little_endian_vec3(record));
      range.colored += (record[49] & 0x80) != 0;  // bit 15 of the attribute: "has a color"
      glm::vec3* corner = &corners[(begin + range.kept++) * 3];
      corner[0] = a, corner[1] = b, corner[2] = c;
    }
  });
  std::size_t kept = 0;
  NormalCheck normals;
  for (int task = 0; task < tasks; ++task) {
    const Range& range = ranges[static_cast<std::size_t>(task)];
    const std::size_t begin = static_cast<std::size_t>(task) * kTrianglesPerTask;
    if (kept != begin) {
      std::copy_n(corners.begin() + static_cast<std::ptrdiff_t>(begin * 3), range.kept * 3,
                  corners.begin() + static_cast<std::ptrdiff_t>(kept * 3));
    }
    kept += range.kept;
    out.non_finite += range.non_finite;
    out.colored_facets += range.colored;
    normals.merge(range.normals);
  }
  corners.resize(kept * 3);
  out.facet_normals_usable = normals.usable();
  out.mesh = weld(std::move(corners));
  return out;
}

// ---- ASCII -------------------------------------------------------------------------------

class AsciiReader {
 public:
  AsciiReader(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  Geometry read() {
    Geometry out;
    std::vector<glm::vec3> corners;
    NormalCheck normals;
    glm::vec3 normal(0.0f), facet[3];
    int vertices = -1;  // in the open facet; -1: none open
    std::size_t facet_line = 0;
    for (std::string_view token = next(); !token.empty(); token = next()) {
      if (token == "solid" || token == "endsolid") {
        skip_line();  // the solid's name, which may have spaces
      } else if (token == "facet") {
        if (vertices >= 0) fail(facet_line, "facet without endfacet");
        vertices = 0;
        facet_line = line_;
        normal = glm::vec3(0.0f);
        std::string_view word = next();
        if (word == "normal") {
          normal = vec3();
        } else if (!word.empty()) {
          fail(line_, "'facet' not followed by 'normal'");
        }
      } else if (token == "vertex") {
        if (vertices < 0) fail(line_, "vertex outside a facet");
        if (vertices == 3) fail(facet_line, "facet with more than 3 vertices");
        facet[vertices++] = vec3();
      } else if (token == "endfacet") {
        if (vertices != 3) {
          fail(facet_line,
               "facet with " + std::to_string(std::max(vertices, 0)) + " vertices, not 3");
        }
        vertices = -1;
        if (!finite(facet[0]) || !finite(facet[1]) || !finite(facet[2])) {
          ++out.non_finite;
          continue;
        }
        if (corners.size() / 3 >= kMaxTriangles) fail(line_, "more triangles than facet indexes");
        normals.add(normal);
        corners.insert(corners.end(), facet, facet + 3);
      } else if (token != "outer" && token != "loop" && token != "endloop") {
        fail(line_, "unexpected '" + shown(token) + "'");
      }
    }
    if (vertices >= 0) fail(facet_line, "facet not closed before the end of the file");
    out.facet_normals_usable = normals.usable();
    out.mesh = weld(std::move(corners));
    return out;
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw Error(name_ + ": " + what + " (line " + std::to_string(line) + ")");
  }

  static std::string shown(std::string_view token) {
    std::string out(token.substr(0, 24));
    for (char& c : out) {
      if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    }
    return token.size() > 24 ? out + "..." : out;
  }

  static bool space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
  }

  // The next whitespace-separated token; empty at the end.
  std::string_view next() {
    while (at_ < text_.size() && space(text_[at_])) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    const std::size_t begin = at_;
    while (at_ < text_.size() && !space(text_[at_])) ++at_;
    return text_.substr(begin, at_ - begin);
  }

  void skip_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  float number() {
    const std::string_view token = next();
    if (token.empty()) fail(line_, "a number was expected before the end of the file");
    const char* first = token.data() + (token.front() == '+' ? 1 : 0);
    float value = 0.0f;
    const auto [end, error] = std::from_chars(first, token.data() + token.size(), value);
    if (error == std::errc::result_out_of_range) {
      // Beyond a float: strtof gives what C does (infinite, or zero when tiny), and an infinite
      // vertex leaves its triangle out.
      return std::strtof(std::string(token).c_str(), nullptr) + 0.0f;
    }
    if (error != std::errc() || end != token.data() + token.size()) {
      fail(line_, "'" + shown(token) + "' is not a number");
    }
    return value + 0.0f;  // -0 welds with +0
  }

  glm::vec3 vec3() {
    const float x = number(), y = number();
    return glm::vec3(x, y, number());
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

// "solid" after any leading white space, as ASCII files begin.
bool starts_with_solid(const Source& source) {
  char start[256];
  const std::size_t n =
      static_cast<std::size_t>(std::min<std::uint64_t>(source.size, sizeof start));
  source.read(0, n, start);
  const std::string_view text(start, n);
  const std::size_t at = text.find_first_not_of(" \t\r\n\f\v");
  return at != std::string_view::npos && text.substr(at).starts_with("solid");
}

}  // namespace

bool is_binary(const Source& source, const std::string&) {
  if (source.size >= kHeaderBytes + 4) {
    unsigned char count_bytes[4];
    source.read(kHeaderBytes, 4, reinterpret_cast<char*>(count_bytes));
    const std::uint64_t count = std::uint64_t{count_bytes[0]} | std::uint64_t{count_bytes[1]} << 8 |
                                std::uint64_t{count_bytes[2]} << 16 |
                                std::uint64_t{count_bytes[3]} << 24;
    if (kHeaderBytes + 4 + kRecordBytes * count == source.size) return true;
  }
  return !starts_with_solid(source);
}

Geometry parse(const Source& source, const std::string& name) {
  if (is_binary(source, name)) return parse_binary(source, name);
  std::string text(static_cast<std::size_t>(source.size), '\0');
  source.read(0, text.size(), text.data());
  Geometry out = AsciiReader(text, name).read();
  return out;
}

Source memory_source(const char* data, std::size_t size) {
  Source source;
  source.size = size;
  source.read = [data](std::uint64_t offset, std::size_t count, char* out) {
    std::memcpy(out, data + offset, count);
  };
  return source;
}

}  // namespace facet::io::stl
