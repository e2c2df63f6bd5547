// PNM (PGM/PPM) reader, see pnm.hpp. Written for hostile input: every read is bounds-checked,
// sizes are limited before anything is allocated, and every failure is a facet::Error.
#include "core/pnm.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet::io {
namespace {

// The largest raster is 16384 * 16384 texels * 3 samples * 2 bytes = 1.5 GiB, and the RGBA
// output 1 GiB: both fit in size_t even on 32-bit targets, so no size product below overflows.
static_assert(std::uint64_t{kMaxPnmSize} * kMaxPnmSize * 3 * 2 <=
              std::numeric_limits<std::size_t>::max());

constexpr int kMaxDigits = 9;  // more digits than any valid field needs: reported as too large

bool is_space(std::uint8_t c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
bool is_digit(std::uint8_t c) { return c >= '0' && c <= '9'; }

// A byte as it should appear in a message: 'x' if printable, else its hex code.
std::string describe(std::uint8_t c) {
  if (c >= 0x21 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
  static const char kHex[] = "0123456789abcdef";
  return std::string("byte 0x") + kHex[c >> 4] + kHex[c & 15];
}

class PnmParser {
 public:
  PnmParser(const std::uint8_t* data, std::size_t size, const std::string& name)
      : data_(data), size_(data ? size : 0), name_(name) {}

  PnmImage parse() {
    const int type = read_magic();
    const int channels = (type == 3 || type == 6) ? 3 : 1;
    PnmImage image;
    image.width = read_size("width");
    image.height = read_size("height");
    const std::uint64_t maxval = read_number("maxval");
    if (maxval < 1 || maxval > 65535) {
      fail("maxval " + std::to_string(maxval) + " outside 1..65535");
    }
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    const bool plain = type == 2 || type == 3;
    image.rgba = plain ? read_plain(pixels, channels, static_cast<unsigned>(maxval))
                       : read_binary(pixels, channels, static_cast<unsigned>(maxval));
    return image;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(name_ + ": " + what + " (line " + std::to_string(line_) + ")");
  }
  [[noreturn]] void fail_at_byte(const std::string& what, std::size_t offset) const {
    throw Error(name_ + ": " + what + " (byte " + std::to_string(offset) + ")");
  }

  // "P" and one digit, then whitespace (or a comment). Returns the digit.
  int read_magic() {
    if (size_ < 2 || data_[0] != 'P' || !is_digit(data_[1])) {
      fail("not a PNM image (the file does not start with P2, P3, P5 or P6)");
    }
    const int type = data_[1] - '0';
    if (type != 2 && type != 3 && type != 5 && type != 6) {
      fail("PNM type P" + std::to_string(type) + " is not supported (only P2, P3, P5, P6)");
    }
    pos_ = 2;
    if (pos_ < size_ && !is_space(data_[pos_]) && data_[pos_] != '#') {
      fail("expected whitespace after the magic number P" + std::to_string(type) + ", found " +
           describe(data_[pos_]));
    }
    return type;
  }

  // Skips whitespace and '#' comments (to the end of the line), counting lines for messages.
  void skip_space_and_comments() {
    while (pos_ < size_) {
      const std::uint8_t c = data_[pos_];
      if (c == '#') {
        while (pos_ < size_ && data_[pos_] != '\n' && data_[pos_] != '\r') ++pos_;
      } else if (is_space(c)) {
        line_ += c == '\n';
        ++pos_;
      } else {
        return;
      }
    }
  }

  // An unsigned decimal number after optional whitespace/comments; `what` names it in errors.
  std::uint64_t read_number(const char* what) {
    skip_space_and_comments();
    if (pos_ >= size_) fail(std::string("missing ") + what + " (the file ends)");
    const std::uint8_t c = data_[pos_];
    if (c == '-') fail(std::string(what) + " is negative");
    if (!is_digit(c)) fail(std::string("expected ") + what + ", found " + describe(c));
    std::uint64_t value = 0;
    int digits = 0;
    for (; pos_ < size_ && is_digit(data_[pos_]); ++pos_, ++digits) {
      if (digits == kMaxDigits) fail(std::string(what) + " is too large");
      value = value * 10 + (data_[pos_] - '0');
    }
    return value;
  }

  int read_size(const char* what) {
    const std::uint64_t value = read_number(what);
    if (value < 1 || value > kMaxPnmSize) {
      fail(std::string(what) + " " + std::to_string(value) + " outside 1.." +
           std::to_string(kMaxPnmSize));
    }
    return static_cast<int>(value);
  }

  // 0..maxval -> 0..255, rounded to nearest.
  static std::vector<std::uint8_t> scale_table(unsigned maxval) {
    std::vector<std::uint8_t> table(maxval + 1);
    for (unsigned v = 0; v <= maxval; ++v) {
      table[v] = static_cast<std::uint8_t>((v * 255u + maxval / 2) / maxval);
    }
    return table;
  }

  // Stores one scaled sample; gray (one channel) is copied to r, g and b.
  static void store(std::vector<std::uint8_t>& rgba, std::size_t sample, int channels,
                    std::uint8_t value) {
    if (channels == 1) {
      rgba[sample * 4] = rgba[sample * 4 + 1] = rgba[sample * 4 + 2] = value;
    } else {
      rgba[sample / 3 * 4 + sample % 3] = value;
    }
  }

  // P2/P3: whitespace-separated decimal samples.
  std::vector<std::uint8_t> read_plain(std::size_t pixels, int channels, unsigned maxval) {
    const std::size_t count = pixels * channels;
    // Each sample takes at least one digit and all but the last a separator, so a file that
    // cannot hold `count` of them is refused before the (possibly huge) image is allocated.
    if ((size_ - pos_ + 1) / 2 < count) {
      skip_space_and_comments();
      fail("pixel data too short: " + std::to_string(count) + " samples expected");
    }
    const std::vector<std::uint8_t> table = scale_table(maxval);
    std::vector<std::uint8_t> rgba(pixels * 4, 255);
    for (std::size_t i = 0; i < count; ++i) {
      skip_space_and_comments();
      if (pos_ >= size_) {
        fail("pixel data ends after " + std::to_string(i) + " of " + std::to_string(count) +
             " samples");
      }
      const std::uint64_t value = read_number("a sample value");
      if (value > maxval) {
        fail("sample value " + std::to_string(value) + " above maxval " + std::to_string(maxval));
      }
      store(rgba, i, channels, table[value]);
    }
    return rgba;
  }

  // P5/P6: exactly one whitespace byte after maxval, then 1 byte per sample (maxval < 256) or
  // 2 bytes, most significant first.
  std::vector<std::uint8_t> read_binary(std::size_t pixels, int channels, unsigned maxval) {
    if (pos_ >= size_) fail("missing the whitespace byte after maxval (the file ends)");
    if (!is_space(data_[pos_])) {
      fail("expected one whitespace byte after maxval, found " + describe(data_[pos_]));
    }
    ++pos_;
    const std::size_t count = pixels * channels;
    const std::size_t bytes_per_sample = maxval < 256 ? 1 : 2;
    const std::size_t needed = count * bytes_per_sample;
    if (size_ - pos_ < needed) {
      fail_at_byte("pixel data too short: " + std::to_string(needed) + " bytes expected, " +
                       std::to_string(size_ - pos_) + " present",
                   pos_);
    }
    const std::vector<std::uint8_t> table = scale_table(maxval);
    std::vector<std::uint8_t> rgba(pixels * 4, 255);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t offset = pos_ + i * bytes_per_sample;
      const unsigned value = bytes_per_sample == 1
                                 ? data_[offset]
                                 : (unsigned{data_[offset]} << 8) | data_[offset + 1];
      if (value > maxval) {
        fail_at_byte(
            "sample value " + std::to_string(value) + " above maxval " + std::to_string(maxval),
            offset);
      }
      store(rgba, i, channels, table[value]);
    }
    return rgba;
  }

  const std::uint8_t* data_;
  std::size_t size_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

PnmImage parse_pnm(const std::uint8_t* data, std::size_t size, const std::string& name) {
  return PnmParser(data, size, name).parse();
}

}  // namespace facet::io
