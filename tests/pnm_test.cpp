// facet's PGM/PPM reader (src/io/pnm.cpp): the four formats with comments in odd places,
// maxval other than 255, and malformed files, each of which must give a facet::Error that
// names the file and the problem, never a crash.
#include "core/pnm.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet::io {
namespace {

PnmImage parse(const std::string& bytes, const std::string& name = "t.pnm") {
  return parse_pnm(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), name);
}

std::vector<std::uint8_t> rgba(std::initializer_list<int> values) {
  return {values.begin(), values.end()};
}

// Parsing must fail with a message that starts with the name and contains `part`.
void expect_error(const std::string& bytes, const std::string& part) {
  try {
    parse(bytes, "bad.pnm");
    ADD_FAILURE() << "no error for: " << bytes;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("bad.pnm: ", 0), 0u) << message;
    EXPECT_NE(message.find(part), std::string::npos) << "want '" << part << "' in: " << message;
  }
}

TEST(Pnm, PlainPpmWithCommentsEverywhere) {
  const PnmImage image = parse(
      "P3# right after the magic\n"
      "# a whole line\n"
      "2 # width\n"
      "  1\t#height\n"
      "#\n"
      "255\n"
      "255 0 0 # red\n"
      "# between pixels\n"
      "0 255\r\n"
      "  0\n");
  EXPECT_EQ(image.width, 2);
  EXPECT_EQ(image.height, 1);
  EXPECT_EQ(image.rgba, rgba({255, 0, 0, 255, 0, 255, 0, 255}));
}

TEST(Pnm, PlainPgmWithMaxval15) {
  // 255 / 15 = 17: every level maps exactly; gray goes to r, g and b.
  const PnmImage image = parse("P2\n# 15 levels\n3 1\n15\n0 7 15\n");
  EXPECT_EQ(image.rgba, rgba({0, 0, 0, 255, 119, 119, 119, 255, 255, 255, 255, 255}));
}

TEST(Pnm, ScalingRoundsToNearest) {
  // maxval 10: 3 -> 76.5 -> 77; 1 -> 25.5 -> 26; 4 -> 102.
  const PnmImage image = parse("P2 3 1 10 3 1 4");
  EXPECT_EQ(image.rgba[0], 77);
  EXPECT_EQ(image.rgba[4], 26);
  EXPECT_EQ(image.rgba[8], 102);
}

TEST(Pnm, BinaryPgm) {
  const std::string header = "P5\n#comment\n3 # w\n1\n255\n";
  const PnmImage image = parse(header + std::string("\x00\x80\xff", 3) + "trailing bytes");
  EXPECT_EQ(image.rgba, rgba({0, 0, 0, 255, 128, 128, 128, 255, 255, 255, 255, 255}));
}

TEST(Pnm, BinaryPpm) {
  // The data may start with a byte that looks like whitespace or '#'.
  const PnmImage image = parse(std::string("P6 1 2 255\n") + "# \n\x01\x02\x03");
  EXPECT_EQ(image.rgba, rgba({'#', ' ', '\n', 255, 1, 2, 3, 255}));
}

TEST(Pnm, SixteenBitSamplesAreBigEndian) {
  // 0xffff -> 255; 0x8000 = 32768 -> 127.50...2 -> 128; 0x0101 = 257 -> 1 exactly.
  const PnmImage image = parse(std::string("P6\n1 1\n65535\n\xff\xff\x80\x00\x01\x01", 19));
  EXPECT_EQ(image.rgba, rgba({255, 128, 1, 255}));
  const PnmImage gray = parse(std::string("P5 2 1 65535\n\x00\xff\xff\x00", 17));
  EXPECT_EQ(gray.rgba, rgba({1, 1, 1, 255, 254, 254, 254, 255}));
  const PnmImage plain = parse("P2 2 1 65535 65535 0");
  EXPECT_EQ(plain.rgba, rgba({255, 255, 255, 255, 0, 0, 0, 255}));
}

TEST(Pnm, BadMagic) {
  expect_error("", "not a PNM image");
  expect_error("P", "not a PNM image");
  expect_error("Q6 1 1 255\n...", "not a PNM image");
  expect_error("\x89PNG\r\n", "not a PNM image");
  expect_error("P1 1 1\n1", "P1 is not supported");
  expect_error("P4 1 1\n\x80", "P4 is not supported");
  expect_error("P7\nWIDTH 1\n", "P7 is not supported");
  expect_error("P62 1 255\n", "expected whitespace after the magic number P6, found '2'");
}

TEST(Pnm, BadSizes) {
  expect_error("P6 -1 1 255\n", "width is negative (line 1)");
  expect_error("P6\n1\n-5 255\n", "height is negative (line 3)");
  expect_error("P6 0 1 255\n", "width 0 outside 1..16384");
  expect_error("P3 1 0 255\n", "height 0 outside 1..16384");
  expect_error("P6 16385 1 255\n", "width 16385 outside 1..16384");
  expect_error("P6 99999999999999999999 1 255\n", "width is too large");
  expect_error("P6 1x1 255\n", "expected height, found 'x'");
  expect_error("P6 1", "missing height (the file ends)");
  // The largest allowed size with almost no data: refused before 1 GiB is allocated.
  expect_error("P6 16384 16384 255\n\x01\x02", "pixel data too short");
  expect_error("P3 16384 16384 255\n1 2 3", "pixel data too short");
}

TEST(Pnm, BadMaxval) {
  expect_error("P6 1 1", "missing maxval (the file ends) (line 1)");
  expect_error("P6 1 1\n# no maxval\n", "missing maxval (the file ends) (line 3)");
  expect_error("P6 1 1 0\nabc", "maxval 0 outside 1..65535");
  expect_error("P2 1 1 65536\n1", "maxval 65536 outside 1..65535");
  expect_error("P2 1 1 abc\n1", "expected maxval, found 'a'");
  expect_error("P5 1 1 255", "missing the whitespace byte after maxval");
  expect_error("P5 1 1 255#x\n\x01", "expected one whitespace byte after maxval, found '#'");
}

TEST(Pnm, SampleAboveMaxval) {
  expect_error("P2\n2 1\n15\n3\n16\n", "sample value 16 above maxval 15 (line 5)");
  expect_error("P3 1 1 255\n0 0 99999999999\n", "a sample value is too large (line 2)");
  expect_error(std::string("P5 1 1 15\n\xc8", 11), "sample value 200 above maxval 15 (byte 10)");
  expect_error(std::string("P5 2 1 1000\n\x03\xe8\x03\xe9", 16), "value 1001 above maxval");
}

TEST(Pnm, TruncatedData) {
  expect_error("P6 2 1 255\n\x01\x02\x03\x04\x05",
               "pixel data too short: 6 bytes expected, 5 present (byte 11)");
  expect_error(std::string("P5 2 1 65535\n\x01\x02\x03", 16), "4 bytes expected, 3 present");
  expect_error("P3 1 1 255\n1    2     ", "pixel data ends after 2 of 3 samples (line 2)");
  expect_error("P2 2 2 255\n1 2 3", "pixel data too short: 4 samples expected");
}

TEST(Pnm, TextGarbage) {
  expect_error("P3 1 1 255\n1 x 3\n", "expected a sample value, found 'x' (line 2)");
  expect_error("P2 1 1 255\n-4\n", "a sample value is negative (line 2)");
  expect_error(std::string("P2 1 1 255\n\x01 ", 13), "found byte 0x01 (line 2)");
  expect_error("P3 one 1 255\n", "expected width, found 'o'");
}

// Every prefix of a valid file, and random byte changes to it, either parse or throw
// facet::Error; under ASan this also shows that no read leaves the buffer.
TEST(Pnm, PrefixesAndMutationsNeverCrash) {
  const std::vector<std::string> files = {
      "P3\n# c\n2 2\n255\n1 2 3 4 5 6 7 8 9 10 11 12\n",
      "P2 3 1 15 0 7 15",
      std::string("P5 2 1 65535\n\x00\xff\xff\x00", 17),
      std::string("P6\n1 2\n255\n\x01\x02\x03\x04\x05\x06", 17),
  };
  std::mt19937 random(12345);
  for (const std::string& file : files) {
    for (std::size_t n = 0; n <= file.size(); ++n) {
      try {
        const PnmImage image = parse(file.substr(0, n));
        EXPECT_EQ(image.rgba.size(), static_cast<std::size_t>(image.width) * image.height * 4);
      } catch (const Error&) {
      }
    }
    for (int round = 0; round < 2000; ++round) {
      std::string mutated = file;
      const int changes = 1 + static_cast<int>(random() % 3);
      for (int c = 0; c < changes; ++c) {
        mutated[random() % mutated.size()] = static_cast<char>(random() % 256);
      }
      try {
        const PnmImage image = parse(mutated);
        EXPECT_EQ(image.rgba.size(), static_cast<std::size_t>(image.width) * image.height * 4);
      } catch (const Error&) {
      }
    }
  }
}

TEST(Pnm, NullDataIsAnErrorNotACrash) { EXPECT_THROW(parse_pnm(nullptr, 10, "null"), Error); }

}  // namespace
}  // namespace facet::io
