// The arithmetic of `facet render --frames` (apps/facet/frame_sequence.cpp): ranges with an
// exclusive end, shards that split a range exactly, and numbered output names.
#include "frame_sequence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet::cli {
namespace {

// The message of the facet::Error `call` throws, or "" if it throws none.
template <class Call>
std::string error_of(Call call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(FrameSequence, RangesEndBeforeTheirEnd) {
  FrameRange range = parse_frames("2:5");
  EXPECT_EQ(range.first, 2);
  EXPECT_EQ(range.end, 5);
  EXPECT_EQ(range.count(), 3);
  EXPECT_EQ(parse_frames("0:1").count(), 1);
}

TEST(FrameSequence, BadRangesNameTheFlag) {
  for (const char* text : {"5:2", "2:2", "", ":", "1:", ":3", "-1:3", "1-3", "a:b", "1:2:3", "+1:3",
                           " 1:3", "1:99999999999"}) {
    std::string message = error_of([&] { parse_frames(text); });
    EXPECT_EQ(message.rfind("--frames: ", 0), 0u) << "'" << text << "': " << message;
  }
  EXPECT_NE(error_of([] { parse_frames("5:2"); }).find("ends before it starts"), std::string::npos);
  EXPECT_NE(error_of([] { parse_frames("2:2"); }).find("2:3 is frame 2 alone"), std::string::npos);
}

TEST(FrameSequence, ShardsSplitARangeExactlyOnce) {
  for (FrameRange range : {FrameRange{0, 1}, FrameRange{0, 10}, FrameRange{7, 30}}) {
    for (int count : {1, 2, 3, 7, 40}) {
      std::vector<int> all;
      for (int index = 0; index < count; ++index) {
        std::vector<int> part = shard_frames(range, {index, count});
        for (std::size_t i = 1; i < part.size(); ++i) EXPECT_EQ(part[i] - part[i - 1], count);
        all.insert(all.end(), part.begin(), part.end());
      }
      std::sort(all.begin(), all.end());
      std::vector<int> expected;
      for (int frame = range.first; frame < range.end; ++frame) expected.push_back(frame);
      EXPECT_EQ(all, expected) << range.first << ":" << range.end << " in " << count;
    }
  }
  EXPECT_EQ(shard_frames({10, 20}, {1, 4}), (std::vector<int>{11, 15, 19}));
  // Near the top of int the step does not overflow.
  EXPECT_EQ(shard_frames({INT_MAX - 3, INT_MAX}, {1, 2}), (std::vector<int>{INT_MAX - 2}));
}

TEST(FrameSequence, BadShardsNameTheFlag) {
  for (const char* text : {"3/2", "2/2", "0/0", "-1/2", "1", "1/", "/2", "a/b", "1/2/3"}) {
    std::string message = error_of([&] { parse_shard(text); });
    EXPECT_EQ(message.rfind("--shard: ", 0), 0u) << "'" << text << "': " << message;
  }
  EXPECT_NE(error_of([] { parse_shard("3/2"); }).find("0/2 to 1/2"), std::string::npos);
  Shard shard = parse_shard("3/8");
  EXPECT_EQ(shard.index, 3);
  EXPECT_EQ(shard.count, 8);
}

TEST(FrameSequence, PatternsNumberTheName) {
  EXPECT_EQ(FramePattern("out/frame_%04d.png").path(7), "out/frame_0007.png");
  EXPECT_EQ(FramePattern("f%d.exr").path(123), "f123.exr");
  EXPECT_EQ(FramePattern("f_%09d.npz").path(12345), "f_000012345.npz");
  EXPECT_EQ(FramePattern("f_%02d.png").path(12345), "f_12345.png");  // widths pad, never cut
  EXPECT_EQ(FramePattern("100%%_%d.png").path(3), "100%_3.png");
  EXPECT_TRUE(FramePattern("%d.png").numbered());
  FramePattern plain("dir.v2/still%%.png");
  EXPECT_FALSE(plain.numbered());
  EXPECT_EQ(plain.path(5), "dir.v2/still%.png");
}

TEST(FrameSequence, BadPatternsNameTheFlag) {
  for (const char* text : {"f_%s.png", "f_%4d.png", "f_%010d.png", "f_%00d.png", "f%", "f_%x.png",
                           "f_%d_%d.png", "out%d/f.png", "%04d/f_%d.png"}) {
    std::string message = error_of([&] { FramePattern pattern(text); });
    EXPECT_EQ(message.rfind("--output: ", 0), 0u) << "'" << text << "': " << message;
  }
  EXPECT_NE(error_of([] { FramePattern("out%d/f.png"); }).find("not in its folder"),
            std::string::npos);
}

}  // namespace
}  // namespace facet::cli
