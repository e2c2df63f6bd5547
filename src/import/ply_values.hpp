// Internal to the PLY reader (ply_format.cpp): where a body's values come from. An ASCII body
// (one item per line) and a binary one (values packed in either byte order) offer the same
// calls, so the element reader is written once as a template over them; every read is checked
// against the end of the bytes and fails with "<name>: <what> (line N)" or "(byte N)".
#pragma once

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "facet/error.hpp"
#include "import/ply_format.hpp"

namespace facet::io::ply {

// A number for a message: whole numbers in full (4000000000, not 4e+09), others to 15 digits.
inline std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return text;
}

// Which item is being read, for messages.
struct Place {
  std::string_view element;
  std::uint64_t index = 0;
  std::uint64_t count = 0;
  std::string item() const {
    return std::string(element) + " " + std::to_string(index) + " (of " + std::to_string(count) +
           ")";
  }
};

// A list's length, checked to be a whole number that is not negative and (binary) to fit in what
// is left of the file.
template <class Source>
std::uint64_t list_length(Source& source, const Property& property);

// ASCII bodies: one item per line, values separated by spaces or tabs; blank lines are skipped.
class AsciiSource {
 public:
  AsciiSource(std::string_view bytes, const Header& header, const std::string& name,
              const Place& place)
      : bytes_(bytes),
        name_(name),
        place_(place),
        position_(header.body_offset),
        next_line_(header.body_line) {}

  // Moves to the next item's line.
  void begin_item() {
    while (true) {
      if (position_ >= bytes_.size()) fail("the file ends before " + place_.item());
      std::size_t end = bytes_.find('\n', position_);
      if (end == std::string_view::npos) end = bytes_.size();
      cursor_ = position_;
      line_end_ = end;
      line_ = next_line_++;
      position_ = end + 1;
      if (!at_item_end()) return;
    }
  }

  // True when the item's line has no more values.
  bool at_item_end() {
    while (cursor_ < line_end_ && is_space(bytes_[cursor_])) ++cursor_;
    return cursor_ >= line_end_;
  }

  double value(Type) {
    if (at_item_end()) fail("the line ends before the last value of " + place_.item());
    std::size_t end = cursor_;
    while (end < line_end_ && !is_space(bytes_[end])) ++end;
    const std::string_view token = bytes_.substr(cursor_, end - cursor_);
    cursor_ = end;
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double out = 0.0;
    auto [stop, error] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
    if (error == std::errc::result_out_of_range) fail(quoted(token) + " is out of range");
    if (error != std::errc() || stop != digits.data() + digits.size()) {
      fail(quoted(token) + " is not a number (in " + place_.item() + ")");
    }
    return out;
  }

  // A list's length: trailing lists a line leaves out are empty (assimp's issue623.ply declares
  // a vertex list its lines do not have, and other readers take it so).
  bool list_left_out() { return at_item_end(); }
  void check_list(std::uint64_t, Type) const {}  // each item is read from the line, which ends
  void skip_values(std::uint64_t count, Type type) {
    for (std::uint64_t i = 0; i < count; ++i) value(type);
  }
  void skip_items(std::uint64_t count, const Element& element) {
    for (std::uint64_t i = 0; i < count; ++i) {
      begin_item();
      for (const Property& property : element.properties) {
        if (property.is_list) {
          skip_values(list_length(*this, property), property.type);
        } else {
          value(property.type);
        }
      }
      end_item();
    }
  }

  void end_item() {
    if (!at_item_end()) {
      fail(place_.item() + " has more values than the header declares properties");
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ": " + what + " (line " + std::to_string(line_) + ")");
  }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }

  std::string_view bytes_;
  const std::string& name_;
  const Place& place_;
  std::size_t position_;   // the next line's first byte
  std::size_t next_line_;  // its number
  std::size_t line_ = 0;   // the current line's number
  std::size_t cursor_ = 0;
  std::size_t line_end_ = 0;
};

// Binary bodies: values packed without padding in the header's byte order.
template <std::endian kOrder>
class BinarySource {
 public:
  BinarySource(std::string_view bytes, const Header& header, const std::string& name,
               const Place& place)
      : bytes_(bytes), name_(name), place_(place), position_(header.body_offset) {}

  void begin_item() {}
  void end_item() {}
  bool list_left_out() { return false; }

  double value(Type type) {
    const std::size_t size = size_of(type);
    if (size > bytes_.size() - position_) fail("the file ends in " + place_.item());
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, size);
    if constexpr (kOrder != std::endian::native) std::reverse(raw, raw + size);
    position_ += size;
    switch (type) {
      case Type::int8:
        return load<std::int8_t>(raw);
      case Type::uint8:
        return load<std::uint8_t>(raw);
      case Type::int16:
        return load<std::int16_t>(raw);
      case Type::uint16:
        return load<std::uint16_t>(raw);
      case Type::int32:
        return load<std::int32_t>(raw);
      case Type::uint32:
        return load<std::uint32_t>(raw);
      case Type::float32:
        return load<float>(raw);
      case Type::float64:
        return load<double>(raw);
    }
    return 0.0;
  }

  // A list of `count` values must fit in what is left of the file.
  void check_list(std::uint64_t count, Type type) const {
    if (count > (bytes_.size() - position_) / size_of(type)) {
      fail("the list in " + place_.item() + " has " + std::to_string(count) +
           " values, more than the rest of the file holds");
    }
  }
  void skip_values(std::uint64_t count, Type type) {
    check_list(count, type);
    position_ += count * size_of(type);
  }
  void skip_items(std::uint64_t count, const Element& element) {
    const bool has_list = std::any_of(element.properties.begin(), element.properties.end(),
                                      [](const Property& p) { return p.is_list; });
    if (!has_list) {  // items of one size: skipped at once
      const std::uint64_t size = smallest_item_size(element, format());
      if (count > (bytes_.size() - position_) / size) {
        fail("the file ends in element " + quoted(element.name));
      }
      position_ += count * size;
      return;
    }
    for (std::uint64_t i = 0; i < count; ++i) {
      for (const Property& property : element.properties) {
        if (property.is_list) {
          skip_values(list_length(*this, property), property.type);
        } else {
          value(property.type);
        }
      }
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ": " + what + " (byte " + std::to_string(position_) + ")");
  }

 private:
  static constexpr Format format() {
    return kOrder == std::endian::little ? Format::binary_little_endian : Format::binary_big_endian;
  }
  template <class T>
  static double load(const unsigned char* raw) {
    T out;
    std::memcpy(&out, raw, sizeof out);
    return static_cast<double>(out);
  }

  std::string_view bytes_;
  const std::string& name_;
  const Place& place_;
  std::size_t position_;
};

template <class Source>
std::uint64_t list_length(Source& source, const Property& property) {
  if (source.list_left_out()) return 0;
  const double length = source.value(property.count_type);
  if (!(length >= 0.0) || length != std::floor(length) || length > 1e18) {
    source.fail("list " + quoted(property.name) + " has a length of " + number(length));
  }
  const auto count = static_cast<std::uint64_t>(length);
  source.check_list(count, property.type);
  return count;
}

}  // namespace facet::io::ply
