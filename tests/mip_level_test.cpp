// A texture's mip levels against their definitions, texel by texel: each the average of the
// 2x2 texels above it in linear light, rounded as an 8-bit level is (sRGB: decoded, averaged,
// encoded by the reference; unorm: averaged as floats and rounded, which the integer filter must
// give exactly).
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <random>
#include <vector>

#include "core/color.hpp"
#include "facet/texture.hpp"
#include "support/forced_target.hpp"
#include "support/srgb_reference.hpp"

namespace facet::test {
namespace {

// The mip builder's sRGB level against the plain decode / average / reference encode.
TEST(MipLevels, SrgbLevelMatchesAScalarReference) {
  std::mt19937 random(7);
  std::vector<std::uint8_t> rgba(std::size_t{64} * 64 * 4);
  for (auto& value : rgba) value = static_cast<std::uint8_t>(random());
  auto t = Texture::from_rgba8(64, 64, rgba, true);
  const auto& level1 = t->level(1).rgba8;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      for (int c = 0; c < 3; ++c) {
        float sum = 0.0f;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            sum += shading::decode_srgb8(rgba[((2 * y + dy) * 64 + 2 * x + dx) * 4 + c]);
          }
        }
        ASSERT_EQ(level1[(y * 32 + x) * 4 + c], test::encode_srgb8(sum * 0.25f)) << x << y;
      }
    }
  }
}

// The 8-bit unorm levels (filtered in integers) against the float average of the decoded
// texels, rounded: every level of a random texture with odd sides and levels tall enough to be
// filtered in several parallel bands, on every SIMD target (rows of several vectors and a few
// texels more, down to rows shorter than a vector).
TEST(MipLevels, UnormLevelsMatchTheFloatAverage) {
  std::mt19937 random(11);
  const int width = 258, height = 134;
  std::vector<std::uint8_t> rgba(std::size_t{width} * height * 4);
  for (auto& value : rgba) value = static_cast<std::uint8_t>(random());
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    auto t = Texture::from_rgba8(width, height, rgba, false);
    for (int l = 1; l < t->level_count(); ++l) {
      const Texture::Level& above = t->level(l - 1);
      const Texture::Level& level = t->level(l);
      const int nx = above.width > 1 ? 2 : 1, ny = above.height > 1 ? 2 : 1;
      for (int y = 0; y < level.height; ++y) {
        for (int x = 0; x < level.width; ++x) {
          for (int c = 0; c < 4; ++c) {
            float sum = 0.0f;
            for (int dy = 0; dy < ny; ++dy) {
              for (int dx = 0; dx < nx; ++dx) {
                const std::size_t i =
                    ((std::size_t{2} * y + dy) * above.width + 2 * x + dx) * 4 + c;
                sum += static_cast<float>(above.rgba8[i]) / 255.0f;
              }
            }
            const float average = sum * (1.0f / static_cast<float>(nx * ny));
            ASSERT_EQ(level.rgba8[(static_cast<std::size_t>(y) * level.width + x) * 4 + c],
                      test::encode_unorm8(average))
                << hwy::TargetName(target) << ": level " << l << " texel " << x << "," << y
                << " channel " << c;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace facet::test
