// The library's 8-bit encodes outside resolve go through the row kernels (core/srgb_row.hpp) and
// give the reference's codes (support/srgb_reference.hpp) on every SIMD target: texture mip
// levels (sRGB and unorm, rows longer than the mip builder's 64-texel chunks), float images
// written as 8-bit, and the clear color of a display-referred frame (display_value_of).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/color.hpp"
#include "core/simd_target.hpp"
#include "facet/color.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/image_io.hpp"
#include "facet/texture.hpp"
#include "pipeline/kernels.hpp"
#include "pipeline/output/output.hpp"
#include "support/forced_target.hpp"
#include "support/render_helpers.hpp"
#include "support/srgb_reference.hpp"

namespace facet::test {
namespace {

// Values around the codes and outside [0, 1], NaN and infinities among them, then random ones.
std::vector<float> probe_values(int count) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f, -0.0f, 1.0f,  -1.0f,
                               2.0f, kInf,  -kInf, std::numeric_limits<float>::quiet_NaN()};
  const shading::SrgbTables& tables = shading::srgb_tables();
  for (int code = 1; code < 256; code += 7) {
    const float t = tables.thresholds[code];
    values.insert(values.end(), {t, std::nextafter(t, 0.0f)});
  }
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> any(-0.1f, 1.1f);
  while (static_cast<int>(values.size()) < count) values.push_back(any(rng));
  values.resize(count);
  return values;
}

// Level `to` of an 8-bit texture against its definition: each texel the 2x2 box average of
// level `to - 1` (as stored) decoded, then encoded by the reference (alpha rounded).
void expect_level_is_the_reference(const Texture& texture, int to, const char* target) {
  const Texture::Level& src = texture.level(to - 1);
  const Texture::Level& dst = texture.level(to);
  const auto decode = [&](std::uint8_t code, int channel) {
    return texture.srgb() && channel < 3 ? shading::decode_srgb8(code)
                                         : static_cast<float>(code) / 255.0f;
  };
  for (int y = 0; y < dst.height; ++y) {
    for (int x = 0; x < dst.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        float sum = 0.0f;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            sum += decode(src.rgba8[((2 * y + dy) * src.width + 2 * x + dx) * 4 + c], c);
          }
        }
        const float average = sum * 0.25f;
        const std::uint8_t expected =
            texture.srgb() && c < 3 ? encode_srgb8(average) : encode_unorm8(average);
        ASSERT_EQ(dst.rgba8[(y * dst.width + x) * 4 + c], expected)
            << target << ", " << (texture.srgb() ? "sRGB" : "unorm") << " level " << to
            << ", texel " << x << "," << y << ", channel " << c;
      }
    }
  }
}

TEST(SrgbCallers, MipLevelsAreTheReferenceCodesOnEveryTarget) {
  // 262 x 6: level 1 is 131 wide (two whole chunks and three texels), level 2 65 wide.
  constexpr int kWidth = 262, kHeight = 6;
  std::mt19937 rng(11);
  std::vector<std::uint8_t> rgba(std::size_t{kWidth} * kHeight * 4);
  for (auto& value : rgba) value = static_cast<std::uint8_t>(rng());
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (bool srgb : {true, false}) {
      const auto texture = Texture::from_rgba8(kWidth, kHeight, rgba, srgb);
      ASSERT_EQ(texture->level(1).width, 131);
      expect_level_is_the_reference(*texture, 1, hwy::TargetName(target));
      expect_level_is_the_reference(*texture, 2, hwy::TargetName(target));
    }
  }
}

// Float levels keep the averages themselves, chunk after chunk in place.
TEST(SrgbCallers, FloatMipLevelsKeepTheAverages) {
  constexpr int kWidth = 262;
  std::vector<float> rgba = probe_values(kWidth * 2 * 4);
  for (float& v : rgba) v = std::isfinite(v) ? v : 0.5f;
  const auto texture = Texture::from_rgba32f(kWidth, 2, rgba);
  const Texture::Level& level1 = texture->level(1);
  ASSERT_EQ(level1.width, 131);
  for (int x = 0; x < level1.width; ++x) {
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) sum += rgba[(dy * kWidth + 2 * x + dx) * 4 + c];
      }
      ASSERT_EQ(level1.rgba32f[x * 4 + c], sum * 0.25f) << "texel " << x << ", channel " << c;
    }
  }
}

// A float framebuffer written as a PNG holds its colors sRGB-encoded and alpha rounded: read
// back as stored (unorm), byte for byte the reference's.
TEST(SrgbCallers, FloatImagesAreWrittenAsTheReferenceEncodes) {
  constexpr int kWidth = 150, kHeight = 3;
  const std::vector<float> values = probe_values(kWidth * kHeight * 4);
  Framebuffer frame(kWidth, kHeight, ColorFormat::rgba32f);
  frame.rgba32f() = values;
  std::vector<std::uint8_t> expected(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    expected[i] = i % 4 == 3 ? encode_unorm8(values[i]) : encode_srgb8(values[i]);
  }
  const auto dir = fresh_test_dir("facet_srgb_callers_", "float_image");
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const std::string path = (dir / (std::string(hwy::TargetName(target)) + ".png")).string();
    write_image(frame, path);
    const auto written = load_texture(path, false);
    ASSERT_EQ(written->width(), kWidth);
    const std::vector<std::uint8_t>& bytes = written->level(0).rgba8;
    ASSERT_EQ(bytes.size(), expected.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      ASSERT_EQ(bytes[i], expected[i])
          << hwy::TargetName(target) << ", value " << i << ": " << values[i];
    }
  }
}

// facet::encode_srgb8, the public encode (the OpenGL twin's readback): the reference's codes,
// the exposure's scale on color alone, on every target; too few bytes for the colors is an error.
TEST(SrgbCallers, PublicEncodeIsTheReferenceCodes) {
  constexpr int kColors = 150;
  const std::vector<float> values = probe_values(kColors * 4);
  std::vector<glm::vec4> colors(kColors);
  std::memcpy(colors.data(), values.data(), values.size() * sizeof(float));
  constexpr float kScale = 1.7f;
  std::vector<std::uint8_t> expected(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    expected[i] = i % 4 == 3 ? encode_unorm8(values[i]) : encode_srgb8(values[i] * kScale);
  }
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    std::vector<std::uint8_t> bytes(values.size());
    facet::encode_srgb8(colors, bytes, kScale);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      ASSERT_EQ(bytes[i], expected[i])
          << hwy::TargetName(target) << ", value " << i << ": " << values[i];
    }
  }
  std::vector<std::uint8_t> short_of_one(values.size() - 1);
  EXPECT_THROW(facet::encode_srgb8(colors, short_of_one), Error);
}

// The display value of a linear color: its color channels' codes / 255, alpha as it is.
TEST(SrgbCallers, DisplayValueOfIsTheReferenceCodes) {
  const std::vector<float> values = probe_values(400);
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const pipeline::Kernels kernels = pipeline::kernels_for(chosen_simd_target());
    for (std::size_t i = 0; i + 4 <= values.size(); i += 4) {
      const glm::vec4 linear(values[i], values[i + 1], values[i + 2], values[i + 3]);
      const glm::vec4 shown = pipeline::display_value_of(kernels, linear);
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(shown[c], static_cast<float>(encode_srgb8(linear[c])) * shading::kInverse255)
            << hwy::TargetName(target) << ": " << linear[c];
      }
      ASSERT_EQ(std::memcmp(&shown.a, &linear.a, sizeof(float)), 0) << linear.a;
    }
  }
}

}  // namespace
}  // namespace facet::test
