// Frame ranges, shards and numbered output names (see frame_sequence.hpp).
#include "frame_sequence.hpp"

#include <charconv>
#include <cstdio>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

// Two whole numbers separated by `separator`, nothing else (no sign, no spaces).
bool parse_pair(const std::string& text, char separator, int& a, int& b) {
  std::size_t at = text.find(separator);
  if (at == std::string::npos) return false;
  const char* begin = text.data();
  const char* middle = begin + at;
  const char* end = begin + text.size();
  auto first = std::from_chars(begin, middle, a);
  auto second = std::from_chars(middle + 1, end, b);
  return begin != middle && first.ec == std::errc() && first.ptr == middle &&
         second.ec == std::errc() && second.ptr == end && middle + 1 != end;
}

}  // namespace

FrameRange parse_frames(const std::string& text) {
  FrameRange range;
  if (!parse_pair(text, ':', range.first, range.end) || range.first < 0 || range.end < 0) {
    throw Error("--frames: expected A:B with whole numbers 0 <= A < B such as 0:120, got '" + text +
                "'");
  }
  if (range.end < range.first) {
    throw Error("--frames: " + text + " ends before it starts (A:B is frames A to B - 1)");
  }
  if (range.end == range.first) {
    throw Error("--frames: " + text + " holds no frame; the end is exclusive, so " +
                std::to_string(range.first) + ":" + std::to_string(range.first + 1) + " is frame " +
                std::to_string(range.first) + " alone");
  }
  return range;
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  if (!parse_pair(text, '/', shard.index, shard.count) || shard.index < 0 || shard.count < 1) {
    throw Error("--shard: expected I/N with whole numbers 0 <= I < N such as 0/4, got '" + text +
                "'");
  }
  if (shard.index >= shard.count) {
    throw Error("--shard: " + text + ": I counts from 0, so the shards of " +
                std::to_string(shard.count) + " are 0/" + std::to_string(shard.count) + " to " +
                std::to_string(shard.count - 1) + "/" + std::to_string(shard.count));
  }
  return shard;
}

std::vector<int> shard_frames(FrameRange range, Shard shard) {
  std::vector<int> frames;
  // Stepped in 64 bits: first + index + count may pass INT_MAX near the top of the range.
  for (long long frame = static_cast<long long>(range.first) + shard.index; frame < range.end;
       frame += shard.count) {
    frames.push_back(static_cast<int>(frame));
  }
  return frames;
}

FramePattern::FramePattern(const std::string& text) : text_(text) {
  const std::string hint = " (use %d or %04d for the frame number, %% for a percent sign)";
  std::string* out = &before_;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      *out += text[i];
      continue;
    }
    if (i + 1 < text.size() && text[i + 1] == '%') {
      *out += '%';
      ++i;
      continue;
    }
    // %d, or %0Nd with one digit N from 1 to 9.
    int width = -1;
    std::size_t length = 0;
    if (text.compare(i, 2, "%d") == 0) {
      width = 0, length = 2;
    } else if (i + 3 < text.size() && text[i + 1] == '0' && text[i + 2] >= '1' &&
               text[i + 2] <= '9' && text[i + 3] == 'd') {
      width = text[i + 2] - '0', length = 4;
    }
    if (width < 0) {
      throw Error("--output: '" + text + "': '" + text.substr(i, 2) + "' is not a frame number" +
                  hint);
    }
    if (numbered()) throw Error("--output: '" + text + "' has two frame numbers; one is enough");
    if (text.find('/', i) != std::string::npos) {
      throw Error("--output: '" + text +
                  "': the frame number must be in the file's name, not in its folder");
    }
    width_ = width;
    out = &after_;
    i += length - 1;
  }
}

std::string FramePattern::path(int frame) const {
  if (!numbered()) return before_;
  char digits[16];
  std::snprintf(digits, sizeof digits, "%0*d", width_, frame);
  return before_ + digits + after_;
}

}  // namespace facet::cli
