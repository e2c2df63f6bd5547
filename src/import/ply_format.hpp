// Internal to the PLY reader: the header as ply_header.cpp parses it, which ply_format.cpp (with
// ply_values.hpp) reads the body by. All work on the whole file in memory, never outside it.
//
// The format (Greg Turk, "The PLY Polygon File Format", 1994; the header keywords as Blender,
// MeshLab/VCG, rply and assimp write them):
//
//   ply
//   format ascii 1.0             or binary_little_endian 1.0, binary_big_endian 1.0
//   comment ...                  also obj_info; `comment TextureFile NAME` names a texture
//   element vertex 8             then the element's properties, in the order of their values:
//   property float x             scalar: char uchar short ushort int uint float double, or
//   property list uchar int vertex_indices   int8 uint8 int16 uint16 int32 uint32 float32 float64
//   end_header
//
// then each element's items in header order: one item per line in ASCII, packed in binary.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace facet::io::ply {

enum class Format { ascii, binary_little_endian, binary_big_endian };

enum class Type : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

// A token for a message: in quotes, cut at 24 characters (one line whatever the input).
std::string quoted(std::string_view token);

// Bytes a value of the type takes in a binary body.
std::size_t size_of(Type type);

struct Property {
  std::string name;
  Type type = Type::float32;  // a scalar's type, or a list's items'
  bool is_list = false;
  Type count_type = Type::uint8;  // a list's length
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  // the header line declaring it, for messages
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::size_t body_offset = 0;  // the first byte after end_header's line
  std::size_t body_line = 0;    // that byte's line number (ASCII messages count lines)
  std::string texture_file;     // `comment TextureFile NAME`; empty: none
};

// Smallest size of one item of the element in the body: its binary size without list items, or
// 2 bytes a property in ASCII (a digit and a separator).
std::size_t smallest_item_size(const Element& element, Format format);

// Parses the header and checks that the body could hold what it declares (every element's count
// times its smallest item size), so nothing is sized from a count before it is checked. Throws
// facet::Error "<name>: <what> (line N)".
Header parse_header(std::string_view bytes, const std::string& name);

}  // namespace facet::io::ply
