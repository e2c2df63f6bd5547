// The library's sRGB encode (core/srgb_row.cpp) gives the reference's codes
// (support/srgb_reference.hpp) on every SIMD target: at and around every code's threshold and the
// edges of its lines, at the ends and beyond them, for NaN and infinities, with and without
// exposure, and for rows of every length; and its lines give the exact code, or one next to it,
// the exact one for all but a small share of values.
#include "core/srgb_row.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/color.hpp"
#include "core/simd_target.hpp"
#include "support/forced_target.hpp"
#include "support/srgb_reference.hpp"

namespace facet::test {
namespace {

// The reference, a channel at a time: color scaled and encoded, alpha clamped and rounded.
void encode_scalar(const glm::vec4& c, float scale, std::uint8_t* out) {
  for (int k = 0; k < 3; ++k) out[k] = encode_srgb8(c[k] * scale);
  const float a = c.a > 0.0f ? std::min(c.a, 1.0f) : 0.0f;
  out[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
}

// Values that probe every code: each threshold and the floats just below and above it, the
// ends of [0, 1] and what lies outside it, random values in between.
std::vector<float> probe_values() {
  const shading::SrgbTables& tables = shading::srgb_tables();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,
                               -0.0f,
                               1.0f,
                               -1.0f,
                               2.0f,
                               1e-30f,
                               -1e-30f,
                               kInf,
                               -kInf,
                               std::numeric_limits<float>::quiet_NaN(),
                               std::numeric_limits<float>::denorm_min(),
                               std::nextafter(1.0f, 0.0f),
                               std::nextafter(1.0f, 2.0f)};
  for (int code = 1; code < 256; ++code) {
    const float t = tables.thresholds[code];
    values.insert(values.end(), {t, std::nextafter(t, 0.0f), std::nextafter(t, 1.0f)});
  }
  // The first and last float of each of the encode's lines (color.hpp), and the float below
  // the first line.
  using Tables = shading::SrgbTables;
  for (int line = 0; line <= Tables::kEncodeLines; ++line) {
    const std::uint32_t start =
        Tables::kEncodeBase + (static_cast<std::uint32_t>(line) << Tables::kEncodeLineShift);
    values.insert(values.end(), {std::bit_cast<float>(start), std::bit_cast<float>(start - 1)});
  }
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> any(-0.1f, 1.1f);
  for (int i = 0; i < 2000; ++i) values.push_back(any(rng));
  return values;
}

TEST(SrgbRow, GivesTheScalarCodesOnEveryTarget) {
  const std::vector<float> values = probe_values();
  const int n = static_cast<int>(values.size());
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (float scale : {1.0f, 0.35f, 2.83f}) {
      // Rows shorter than a vector, of whole vectors, and of whole ones and a part; each value
      // goes through every channel (the shift moves it by one).
      for (int count : {1, 2, 3, 5, 16, 63, 64, 65, 129, 150}) {
        for (int shift = 0; shift < 4; ++shift) {
          for (int start = 0; start < n; start += 4 * count) {
            std::vector<glm::vec4> row(count);
            for (int i = 0; i < count; ++i) {
              for (int c = 0; c < 4; ++c) row[i][c] = values[(start + 4 * i + c + shift) % n];
            }
            std::vector<std::uint8_t> simd(4 * count), scalar(4 * count);
            shading::encode_srgb_row_kernel(chosen_simd_target())(row.data(), count, scale,
                                                                  simd.data());
            for (int i = 0; i < count; ++i) encode_scalar(row[i], scale, &scalar[4 * i]);
            for (int i = 0; i < 4 * count; ++i) {
              ASSERT_EQ(simd[i], scalar[i])
                  << hwy::TargetName(target) << ", scale " << scale << ", row of " << count
                  << ", channel " << i << ": " << row[i / 4][i % 4];
            }
            compared += 4 * count;
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 200000);
}

// The encode's lines against the exact encode: never more than one code away, on every float
// within 2^14 floats of a code's threshold (where they may differ) and every 61st float of
// [0, 1] (and the one above) besides; the exact code for all but 0.5 % of the latter; exact at
// both ends and at every code's own value (decode_srgb8), so 8-bit sRGB round-trips.
TEST(SrgbLines, AreWithinOneCodeOfTheExactEncode) {
  const shading::SrgbTables& tables = shading::srgb_tables();
  auto expect_near = [](std::uint32_t bits) {
    const float v = std::bit_cast<float>(bits);
    const int lines = encode_srgb8(v), exact = exact_srgb8(v);
    EXPECT_LE(std::abs(lines - exact), 1) << v;
    return lines != exact;
  };
  for (int code = 1; code < 256; ++code) {
    const auto threshold = std::bit_cast<std::int32_t>(tables.thresholds[code]);
    for (std::int32_t bits = threshold - (1 << 14); bits <= threshold + (1 << 14); ++bits) {
      expect_near(static_cast<std::uint32_t>(bits));
    }
  }
  std::uint64_t floats = 0, off_by_one = 0;
  for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(1.0f) + 1; bits += 61) {
    off_by_one += expect_near(bits);
    ++floats;
  }
  EXPECT_LT(static_cast<double>(off_by_one), 0.005 * static_cast<double>(floats));
  EXPECT_GT(off_by_one, 0u);  // an approximation: the share above is what it measures
  EXPECT_EQ(encode_srgb8(0.0f), 0);
  EXPECT_EQ(encode_srgb8(1.0f), 255);
  for (int code = 0; code < 256; ++code) {
    EXPECT_EQ(encode_srgb8(shading::decode_srgb8(static_cast<std::uint8_t>(code))), code);
  }
}

// Each line stays within 0.07 of a code of the exact curve, 255 * linear_to_srgb(v) in double,
// over its whole range (every 7th float of [2^-13, 1)): what keeps a code within one of the
// exact code, and what tests comparing codes with the curve allow beyond half a code.
TEST(SrgbLines, StayWithinAFifteenthOfACodeOfTheCurve) {
  using Tables = shading::SrgbTables;
  const Tables& tables = shading::srgb_tables();
  double farthest = 0.0;
  for (std::uint32_t bits = Tables::kEncodeBase; bits <= Tables::kEncodeTop; bits += 7) {
    const double v = std::bit_cast<float>(bits);
    const double curve =
        255.0 * (v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
    const double line =
        static_cast<double>(srgb_line_value(tables, static_cast<float>(v))) / 65536.0 - 0.5;
    farthest = std::max(farthest, std::abs(line - curve));
  }
  EXPECT_LT(farthest, 0.07);
}

// The SIMD encode multiplies the lines' 16-bit halves as signed numbers: each below 2^15. The
// entries outside the lines are zero, and each line sits at its values' entry (line_entry).
TEST(SrgbLines, HalvesArePositiveSigned16BitNumbersAtTheirEntries) {
  using Tables = shading::SrgbTables;
  const Tables& tables = shading::srgb_tables();
  for (int entry = 0; entry < Tables::kEncodeEntries; ++entry) {
    const std::uint32_t line = tables.encode_lines[entry];
    const bool holds_a_line = entry >= Tables::kEncodeFirstEntry &&
                              entry < Tables::kEncodeFirstEntry + Tables::kEncodeLines;
    EXPECT_EQ(line != 0, holds_a_line) << "entry " << entry;
    EXPECT_LT(line >> 16, 1u << 15) << "entry " << entry;
    EXPECT_LT(line & 0xFFFF, 1u << 15) << "entry " << entry;
  }
  EXPECT_EQ(Tables::line_entry(Tables::kEncodeBase), Tables::kEncodeFirstEntry);
  EXPECT_EQ(Tables::line_entry(Tables::kEncodeTop),
            Tables::kEncodeFirstEntry + Tables::kEncodeLines - 1);
}

// Display-referred frames' resolve: every code's display value (code / 255) back to the code,
// and every channel of the probe values (NaN, infinities, values outside [0, 1] among them)
// clamped and rounded as alpha is, on every target.
// The resolve's encode that knows its background's codes gives the plain encode's bytes on every
// target, the background color's runs mixed with other colors, with those of -0.0 and NaN that
// share its values but not its bits, at every row length and position; and it does take the
// known codes for runs of the background: given wrong ones, a row of nothing else shows them (on
// targets of four lanes or more, which compare a vector of colors at a time).
TEST(SrgbRowKnowing, GivesThePlainEncodesBytesOnEveryTarget) {
  const glm::vec4 background{0.2f, 0.0f, 0.7f, 1.0f};
  const std::vector<float> values = probe_values();
  std::mt19937 rng(20261206);
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const SimdTarget chosen = chosen_simd_target();
    for (float scale : {1.0f, 0.35f}) {
      shading::KnownCodes known{background, 0};
      shading::encode_srgb_row_kernel(chosen)(&background, 1, scale,
                                              reinterpret_cast<std::uint8_t*>(&known.codes));
      for (int count : {1, 3, 4, 5, 16, 17, 63, 64, 128}) {
        for (int round = 0; round < 40; ++round) {
          std::vector<glm::vec4> row(count, background);
          // Some rows all background; the others with a run of it and colors besides.
          const int others = round % 4 == 0 ? 0 : std::uniform_int_distribution<int>(1, count)(rng);
          for (int k = 0; k < others; ++k) {
            glm::vec4& c = row[std::uniform_int_distribution<int>(0, count - 1)(rng)];
            switch (k % 3) {
              case 0:  // a value of the probe
                c[k % 4] = values[rng() % values.size()];
                break;
              case 1:  // equal to the background's, other bits
                c.g = -0.0f;
                break;
              default:
                c.r = std::numeric_limits<float>::quiet_NaN();
            }
          }
          std::vector<std::uint8_t> plain(4 * count), knowing(4 * count);
          shading::encode_srgb_row_kernel(chosen)(row.data(), count, scale, plain.data());
          shading::encode_srgb_row_knowing_kernel(chosen)(row.data(), count, scale, known,
                                                          knowing.data());
          ASSERT_EQ(knowing, plain) << hwy::TargetName(target) << ", row of " << count;
          compared += count;
        }
      }
    }
    // Wrong codes for the background show where the kernel took them.
    const shading::KnownCodes wrong{background, 0x01020304u};
    std::vector<glm::vec4> row(64, background);
    std::vector<std::uint8_t> out(4 * 64);
    shading::encode_srgb_row_knowing_kernel(chosen)(row.data(), 64, 1.0f, wrong, out.data());
    std::uint32_t first;
    std::memcpy(&first, out.data(), 4);
    if (hwy::TargetName(target) != std::string("SCALAR")) {
      EXPECT_EQ(first, wrong.codes) << hwy::TargetName(target);
    }
  }
  EXPECT_GT(compared, 10000);
}

TEST(Unorm8Row, RoundsEveryChannelAsAlphaOnEveryTarget) {
  std::vector<glm::vec4> codes(64);
  std::vector<float> values = probe_values();
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int first = 0; first < 256; first += 64) {
      for (int i = 0; i < 64; ++i) {
        const float shown = static_cast<float>(first + i) * shading::kInverse255;
        codes[i] = glm::vec4(shown, shown, shown, shown);
      }
      std::vector<std::uint8_t> out(4 * 64);
      shading::round_unorm8_row_kernel(chosen_simd_target())(codes.data(), 64, out.data());
      for (int i = 0; i < 4 * 64; ++i) {
        ASSERT_EQ(out[i], first + i / 4) << hwy::TargetName(target) << ", code " << first + i / 4;
      }
    }
    for (int count : {1, 3, 16, 65}) {
      for (std::size_t start = 0; start + 4 * count <= values.size(); start += 4 * count) {
        std::vector<std::uint8_t> out(4 * count);
        shading::round_unorm8_row_kernel(chosen_simd_target())(
            reinterpret_cast<const glm::vec4*>(&values[start]), count, out.data());
        for (int i = 0; i < 4 * count; ++i) {
          const float v = values[start + i];
          ASSERT_EQ(out[i], encode_unorm8(v))
              << hwy::TargetName(target) << ", row of " << count << ": " << v;
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
