// The PLY header (format in ply_format.hpp): its keywords to elements and properties, and the
// check that the body can hold every count it declares. Written here at load time; the body is
// read by ply_format.cpp from what this returns.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "facet/error.hpp"
#include "import/ply_format.hpp"

namespace facet::io::ply {
namespace {

struct TypeName {
  std::string_view name;
  Type type;
};

// The 1994 names and the sized aliases VCG and others write.
constexpr TypeName kTypeNames[] = {
    {"char", Type::int8},      {"int8", Type::int8},       {"uchar", Type::uint8},
    {"uint8", Type::uint8},    {"short", Type::int16},     {"int16", Type::int16},
    {"ushort", Type::uint16},  {"uint16", Type::uint16},   {"int", Type::int32},
    {"int32", Type::int32},    {"uint", Type::uint32},     {"uint32", Type::uint32},
    {"float", Type::float32},  {"float32", Type::float32}, {"double", Type::float64},
    {"float64", Type::float64}};

class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  Header parse() {
    std::vector<std::string_view> tokens;
    if (!next_line(tokens) || tokens.size() != 1 || tokens[0] != "ply") {
      line_ = 1;
      fail("not a PLY file (it does not start with a line 'ply')");
    }
    bool have_format = false;
    while (true) {
      if (!next_line(tokens)) fail("the file ends before the header's end_header line");
      if (tokens.empty()) continue;
      const std::string_view keyword = tokens[0];
      if (keyword == "end_header") break;
      if (keyword == "format") {
        parse_format(tokens);
        have_format = true;
      } else if (keyword == "element") {
        parse_element(tokens);
      } else if (keyword == "property") {
        parse_property(tokens);
      } else if (keyword == "comment" && tokens.size() >= 3 && tokens[1] == "TextureFile") {
        // MeshLab's way to name a texture; the name is the rest of the line (it may hold spaces).
        const std::size_t start = tokens[2].data() - bytes_.data();
        header_.texture_file = std::string(bytes_.substr(start, line_end_ - start));
      }
      // comment, obj_info and lines of no keyword (a Blender 2.4 exporter wrote its banner
      // without `comment`) say nothing about the data.
    }
    if (!have_format) fail("the header has no format line");
    header_.body_offset = position_;
    header_.body_line = line_ + 1;
    check_counts();
    return header_;
  }

 private:
  // The next line's tokens (a '\r' before the '\n' is a separator); false at the end of the
  // bytes without a line.
  bool next_line(std::vector<std::string_view>& tokens) {
    tokens.clear();
    if (position_ >= bytes_.size()) return false;
    std::size_t end = bytes_.find('\n', position_);
    const bool terminated = end != std::string_view::npos;
    if (!terminated) end = bytes_.size();
    std::string_view line = bytes_.substr(position_, end - position_);
    ++line_;
    position_ = terminated ? end + 1 : end;
    while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    line_end_ = static_cast<std::size_t>(line.data() - bytes_.data()) + line.size();
    constexpr std::string_view kSpace = " \t\r\v\f";
    std::size_t i = line.find_first_not_of(kSpace);
    while (i != std::string_view::npos) {
      const std::size_t j = line.find_first_of(kSpace, i);
      tokens.push_back(line.substr(i, j == std::string_view::npos ? j : j - i));
      i = j == std::string_view::npos ? j : line.find_first_not_of(kSpace, j);
    }
    return true;
  }

  void parse_format(const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 3) fail("the format line must be 'format <ascii|binary_...> 1.0'");
    if (tokens[1] == "ascii") {
      header_.format = Format::ascii;
    } else if (tokens[1] == "binary_little_endian") {
      header_.format = Format::binary_little_endian;
    } else if (tokens[1] == "binary_big_endian") {
      header_.format = Format::binary_big_endian;
    } else {
      fail("unknown format " + quoted(tokens[1]) +
           " (ascii, binary_little_endian or binary_big_endian)");
    }
    if (tokens[2] != "1.0" && tokens[2] != "1") {
      fail("PLY version " + quoted(tokens[2]) + " is not supported (only 1.0)");
    }
  }

  void parse_element(const std::vector<std::string_view>& tokens) {
    if (tokens.size() != 3) fail("an element line must be 'element <name> <count>'");
    Element element;
    element.name = std::string(tokens[1]);
    const std::string_view count = tokens[2];
    auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), element.count);
    if (error == std::errc::result_out_of_range) {
      fail("element " + quoted(tokens[1]) + " has too many items: " + quoted(count));
    }
    if (error != std::errc() || end != count.data() + count.size()) {
      fail("the count of element " + quoted(tokens[1]) +
           " is not a whole number: " + quoted(count));
    }
    element.line = line_;
    header_.elements.push_back(std::move(element));
  }

  Type parse_type(std::string_view token) const {
    for (const TypeName& known : kTypeNames) {
      if (known.name == token) return known.type;
    }
    fail("unknown property type " + quoted(token));
  }

  void parse_property(const std::vector<std::string_view>& tokens) {
    if (header_.elements.empty()) fail("a property comes before any element");
    Property property;
    if (tokens.size() >= 2 && tokens[1] == "list") {
      if (tokens.size() != 5)
        fail("a list property must be 'property list <count type> <type> <name>'");
      property.is_list = true;
      property.count_type = parse_type(tokens[2]);
      if (property.count_type == Type::float32 || property.count_type == Type::float64) {
        fail("a list's length must be an integer type, not " + quoted(tokens[2]));
      }
      property.type = parse_type(tokens[3]);
      property.name = std::string(tokens[4]);
    } else {
      if (tokens.size() != 3) fail("a property line must be 'property <type> <name>'");
      property.type = parse_type(tokens[1]);
      property.name = std::string(tokens[2]);
    }
    header_.elements.back().properties.push_back(std::move(property));
  }

  // Every item of every element takes at least smallest_item_size bytes, so a count the body
  // cannot hold is refused here, before anything is allocated or looped over.
  void check_counts() const {
    const std::uint64_t body = bytes_.size() - header_.body_offset;
    std::uint64_t needed = 0;
    for (const Element& element : header_.elements) {
      const std::uint64_t item = smallest_item_size(element, header_.format);
      if (item == 0) continue;  // no properties: its items hold nothing
      if (element.count > (body - needed) / item) {
        // In double: the product may not fit in 64 bits, and the message needs no exact figure.
        char need[32];
        std::snprintf(need, sizeof need, "%.15g",
                      static_cast<double>(needed) + static_cast<double>(element.count) * item);
        line_ = element.line;
        fail("element " + quoted(element.name) + " (" + std::to_string(element.count) +
             " items) does not fit: the elements up to it need at least " + need +
             " bytes, the file has " + std::to_string(body) + " after the header");
      }
      needed += element.count * item;
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ": " + what + " (line " + std::to_string(line_) + ")");
  }

  std::string_view bytes_;
  const std::string& name_;
  std::size_t position_ = 0;
  std::size_t line_end_ = 0;  // the current line's end, without its line break
  mutable std::size_t line_ = 0;
  Header header_;
};

}  // namespace

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 24;
  std::string out = "'";
  out.append(token.substr(0, kShown));
  out.append(token.size() > kShown ? "...'" : "'");
  return out;
}

std::size_t size_of(Type type) {
  switch (type) {
    case Type::int8:
    case Type::uint8:
      return 1;
    case Type::int16:
    case Type::uint16:
      return 2;
    case Type::int32:
    case Type::uint32:
    case Type::float32:
      return 4;
    case Type::float64:
      return 8;
  }
  return 8;
}

std::size_t smallest_item_size(const Element& element, Format format) {
  std::size_t size = 0;
  for (const Property& property : element.properties) {
    if (format == Format::ascii) {
      size += 2;
    } else {
      size += size_of(property.is_list ? property.count_type : property.type);
    }
  }
  return size;
}

Header parse_header(std::string_view bytes, const std::string& name) {
  return HeaderParser(bytes, name).parse();
}

}  // namespace facet::io::ply
