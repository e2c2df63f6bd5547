// The library's sRGB encode (core/srgb_row.cpp) gives the reference's codes
// (support/srgb_reference.hpp) on every SIMD target: at and around every code's threshold and the
// edges of its table's runs, at the ends and beyond them, for NaN and infinities, with and without
// exposure, and for rows of every length up to past a chunk.
#include "core/srgb_row.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
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
  // The first and last float of each of the row encoder's runs (color.hpp), and the float
  // below the first run. With a run's code and threshold right, all its floats are.
  using Tables = shading::SrgbTables;
  for (int r = 0; r < Tables::kRuns; ++r) {
    const std::uint32_t start =
        Tables::kRunBase + (static_cast<std::uint32_t>(r) << Tables::kRunBits);
    values.insert(values.end(), {std::bit_cast<float>(start), std::bit_cast<float>(start - 1)});
  }
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> any(-0.1f, 1.1f);
  for (int i = 0; i < 2000; ++i) values.push_back(any(rng));
  return values;
}

// Both ways of fetching the table's entries (a gather, a load a lane), whichever the machine's
// own choice is.
TEST(SrgbRow, GivesTheScalarCodesOnEveryTarget) {
  const std::vector<float> values = probe_values();
  const int n = static_cast<int>(values.size());
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (const bool gathering : {false, true}) {
      for (float scale : {1.0f, 0.35f, 2.83f}) {
        // Rows shorter than a vector, of whole vectors, and around the 64-color chunk; each
        // value goes through every channel (the shift moves it by one).
        for (int count : {1, 2, 3, 5, 16, 63, 64, 65, 129, 150}) {
          for (int shift = 0; shift < 4; ++shift) {
            for (int start = 0; start < n; start += 4 * count) {
              std::vector<glm::vec4> row(count);
              for (int i = 0; i < count; ++i) {
                for (int c = 0; c < 4; ++c) row[i][c] = values[(start + 4 * i + c + shift) % n];
              }
              std::vector<std::uint8_t> simd(4 * count), scalar(4 * count);
              shading::encode_srgb_row_kernel(chosen_simd_target(), gathering)(row.data(), count,
                                                                               scale, simd.data());
              for (int i = 0; i < count; ++i) encode_scalar(row[i], scale, &scalar[4 * i]);
              for (int i = 0; i < 4 * count; ++i) {
                ASSERT_EQ(simd[i], scalar[i])
                    << hwy::TargetName(target) << (gathering ? " gathering" : "") << ", scale "
                    << scale << ", row of " << count << ", channel " << i << ": "
                    << row[i / 4][i % 4];
              }
              compared += 4 * count;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 200000);
}

// What lets the encoders look each channel up once: no run of their table (color.hpp) holds
// two thresholds, and each entry gives the code at the run's start and where the next begins,
// by the definition: the largest code whose threshold is at most the value.
TEST(SrgbTables, EachRunHoldsOneThresholdAtMost) {
  using Tables = shading::SrgbTables;
  const Tables& tables = shading::srgb_tables();
  auto code_at = [&](std::uint32_t bits) {
    const float* after = std::upper_bound(
        tables.thresholds.begin() + 1, tables.thresholds.begin() + 256, std::bit_cast<float>(bits));
    return static_cast<std::uint32_t>(after - tables.thresholds.begin() - 1);
  };
  int thresholds_in_runs = 0;
  for (int r = 0; r < Tables::kRuns; ++r) {
    const std::uint32_t start =
        Tables::kRunBase + (static_cast<std::uint32_t>(r) << Tables::kRunBits);
    const std::uint32_t end = start + Tables::kRunMask + 1;
    int inside = 0;
    for (int code = 1; code < 256; ++code) {
      const std::uint32_t t = std::bit_cast<std::uint32_t>(tables.thresholds[code]);
      inside += t >= start && t < end;
    }
    ASSERT_LE(inside, 1) << "run " << r;
    thresholds_in_runs += inside;
    const std::uint32_t entry = tables.run_code[r];
    const std::uint32_t offset = entry & Tables::kRunOffsetMask;
    ASSERT_EQ(entry >> Tables::kRunCodeShift, code_at(start)) << "run " << r;
    ASSERT_EQ(offset <= Tables::kRunMask, inside == 1) << "run " << r;
    if (inside == 1) {
      ASSERT_EQ(code_at(start + offset), (entry >> Tables::kRunCodeShift) + 1) << "run " << r;
      ASSERT_EQ(code_at(start + offset - 1), entry >> Tables::kRunCodeShift) << "run " << r;
    }
  }
  // Every threshold lies in some run, none in run 0, which also takes every value below it.
  EXPECT_EQ(thresholds_in_runs, 255);
  EXPECT_GT(tables.thresholds[1], std::bit_cast<float>(Tables::kRunBase + Tables::kRunMask + 1));
}

// Display-referred frames' resolve: every code's display value (code / 255) back to the code,
// and every channel of the probe values (NaN, infinities, values outside [0, 1] among them)
// clamped and rounded as alpha is, on every target.
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
