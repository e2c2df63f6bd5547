// Which frames a `facet render` run draws and what each is called: the range of --frames A:B,
// the share of it one --shard I/N takes, and the frame number put into the output name's %d.
// Parsing and arithmetic only; nothing here touches a file.
#pragma once

#include <string>
#include <vector>

namespace facet::cli {

// Frames first, first + 1, ..., end - 1: the end is exclusive, as in a Python range, so
// 0:240 is 240 frames (8 seconds at 30 frames per second).
struct FrameRange {
  int first = 0;
  int end = 1;
  int count() const { return end - first; }
};

// "A:B" with whole numbers 0 <= A < B. Throws facet::Error starting "--frames: ".
FrameRange parse_frames(const std::string& text);

// Shard `index` of `count`: the frames first + index, first + index + count, ... of a range,
// so shards 0/N .. N-1/N together render every frame exactly once.
struct Shard {
  int index = 0;
  int count = 1;
};

// "I/N" with whole numbers 0 <= I < N. Throws facet::Error starting "--shard: ".
Shard parse_shard(const std::string& text);

// The frame numbers of `range` that `shard` renders, in order (possibly none).
std::vector<int> shard_frames(FrameRange range, Shard shard);

// An output name with at most one printf-style frame number, %d or %0Nd (N from 1 to 9,
// zero-padded to N digits), and %% for a percent sign. The number must be in the file's
// name, not in its folder, so that one folder check covers every frame.
class FramePattern {
 public:
  // Throws facet::Error starting "--output: " for any other %-sequence or a second number.
  explicit FramePattern(const std::string& text);

  bool numbered() const { return width_ >= 0; }
  // The name of frame `frame` (the name itself, %% made %, if not numbered).
  std::string path(int frame) const;
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::string before_, after_;  // around the number, %% already made %
  int width_ = -1;              // digits to pad to; 0 for %d; -1: no number
};

}  // namespace facet::cli
