// OBJ files of plain geometry, read by facet itself (see import_internal.hpp's read_plain_obj):
// text alone, so its fuzz target links it alone. A line either is one of the few kinds below,
// written in the one way below, or the whole file goes to assimp's reader instead, which knows
// the rest of OBJ (materials, groups, polygons, lines, points, and its own ways with odd files).
//
//   v x y z          a position: exactly three numbers
//   vn x y z         a normal
//   vt u v [w]       texture coordinates (w, which the renderer has no use for, left out)
//   f a b c          a triangle: three corners, every corner of the file in the same form,
//                    v, v/t, v//n or v/t/n; indices from 1, or negative: counted back from the
//                    last line of their kind so far
//   # ...            a comment; blank lines
//
// Numbers: an optional sign, digits with an optional point, an optional exponent (e or E, its
// own sign); converted correctly rounded (std::from_chars), finite. Lines end in LF or CRLF;
// spaces and tabs separate.
#include <charconv>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

#include "import/import_internal.hpp"

namespace facet::io {
namespace {

constexpr std::string_view kSpaces = " \t";

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The tokens of a line, at most `capacity` of them; false when it has more.
bool split(std::string_view line, std::string_view* tokens, int capacity, int& count) {
  count = 0;
  std::size_t i = line.find_first_not_of(kSpaces);
  while (i != std::string_view::npos) {
    if (count == capacity) return false;
    const std::size_t end = line.find_first_of(kSpaces, i);
    tokens[count++] = line.substr(i, end == std::string_view::npos ? end : end - i);
    i = end == std::string_view::npos ? end : line.find_first_not_of(kSpaces, end);
  }
  return true;
}

// A number as the header says, the whole token, or nothing.
std::optional<float> number(std::string_view token) {
  const bool plus = !token.empty() && token.front() == '+';
  if (plus) token.remove_prefix(1);  // from_chars takes '-' only
  const std::size_t first = !plus && !token.empty() && token.front() == '-' ? 1 : 0;
  // Digits or a point first: no "inf", "nan" or hexadecimal.
  if (token.size() <= first || !(is_digit(token[first]) || token[first] == '.')) return {};
  float value = 0.0f;
  const auto [end, error] =
      std::from_chars(token.data(), token.data() + token.size(), value, std::chars_format::general);
  if (error != std::errc() || end != token.data() + token.size()) return {};
  return value;
}

// An index into `count` items so far (1-based, or negative from the end) as 0-based.
std::optional<std::uint32_t> index(std::string_view token, std::size_t count) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || value == 0) return {};
  const std::int64_t at = value > 0 ? value - 1 : static_cast<std::int64_t>(count) + value;
  if (at < 0 || at >= static_cast<std::int64_t>(count)) return {};
  return static_cast<std::uint32_t>(at);
}

// Which of a corner's indices are written: v, v/t, v//n, v/t/n.
struct CornerForm {
  bool texcoord = false, normal = false;
  bool operator==(const CornerForm&) const = default;
};

class PlainReader {
 public:
  std::optional<Mesh> read(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size()) {
      std::size_t end = text.find('\n', at);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(at, end - at);
      at = end + 1;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (!take(line)) return {};
    }
    if (mesh_.positions.empty() || !assimp_keeps_as_read()) return {};
    mesh_.indices.resize(mesh_.positions.size());
    for (std::size_t i = 0; i < mesh_.indices.size(); ++i) {
      mesh_.indices[i] = static_cast<std::uint32_t>(i);
    }
    return std::move(mesh_);
  }

 private:
  bool take(std::string_view line) {
    const std::size_t start = line.find_first_not_of(kSpaces);
    if (start == std::string_view::npos || line[start] == '#') return true;  // blank, comment
    std::string_view tokens[5];
    int count = 0;
    if (!split(line, tokens, 5, count)) return false;
    const std::string_view kind = tokens[0];
    if (kind == "v" || kind == "vn") {
      glm::vec3 v;
      if (count != 4 || !numbers(tokens + 1, 3, &v.x)) return false;
      (kind == "v" ? positions_ : normals_).push_back(v);
      return true;
    }
    if (kind == "vt") {
      float uvw[3];
      if ((count != 3 && count != 4) || !numbers(tokens + 1, count - 1, uvw)) return false;
      texcoords_.push_back({uvw[0], uvw[1]});
      return true;
    }
    if (kind == "f" && count == 4) {
      for (int c = 1; c < 4; ++c) {
        if (!corner(tokens[c])) return false;
      }
      return true;
    }
    return false;
  }

  static bool numbers(const std::string_view* tokens, int n, float* out) {
    for (int i = 0; i < n; ++i) {
      const std::optional<float> value = number(tokens[i]);
      if (!value) return false;
      out[i] = *value;
    }
    return true;
  }

  // One face corner: its own vertex, as assimp makes one for every corner.
  bool corner(std::string_view token) {
    const std::size_t first = token.find('/');
    const std::size_t second = first == std::string_view::npos ? first : token.find('/', first + 1);
    if (second != std::string_view::npos && token.find('/', second + 1) != std::string_view::npos)
      return false;
    CornerForm form;
    form.texcoord = first != std::string_view::npos && second != first + 1;
    form.normal = second != std::string_view::npos;
    if (!form_) form_ = form;
    if (*form_ != form) return false;
    if (mesh_.positions.size() == std::numeric_limits<std::uint32_t>::max()) return false;
    const std::optional<std::uint32_t> v = index(token.substr(0, first), positions_.size());
    if (!v) return false;
    mesh_.positions.push_back(positions_[*v]);
    if (form.texcoord) {
      const std::size_t end = second == std::string_view::npos ? token.size() : second;
      const std::optional<std::uint32_t> t =
          index(token.substr(first + 1, end - first - 1), texcoords_.size());
      if (!t) return false;
      mesh_.texcoords.push_back(texcoords_[*t]);
    }
    if (form.normal) {
      const std::optional<std::uint32_t> n = index(token.substr(second + 1), normals_.size());
      if (!n) return false;
      mesh_.normals.push_back(normals_[*n]);
    }
    return true;
  }

  // What assimp's post-processing (aiProcess_FindInvalidData) would change, left to it: every
  // corner at one position, a normal of zero length, every normal or every texture coordinate
  // alike.
  bool assimp_keeps_as_read() const {
    auto all_alike = [](const auto& values) {
      for (std::size_t i = 1; i < values.size(); ++i) {
        if (values[i] != values[0]) return false;
      }
      return values.size() > 1;
    };
    for (const glm::vec3& n : mesh_.normals) {
      if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) return false;
    }
    return !all_alike(mesh_.positions) && !all_alike(mesh_.normals) && !all_alike(mesh_.texcoords);
  }

  std::vector<glm::vec3> positions_, normals_;
  std::vector<glm::vec2> texcoords_;
  std::optional<CornerForm> form_;
  Mesh mesh_;
};

}  // namespace

std::optional<Mesh> read_plain_obj(std::string_view text) { return PlainReader().read(text); }

}  // namespace facet::io
