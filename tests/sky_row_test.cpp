// The SIMD sky-gradient background (pipeline/output/sky_row.cpp) gives the scalar background's bits
// on every SIMD target, above and below the horizon, in rows all of sky and rows partly covered,
// and leaves covered pixels alone.
#include "pipeline/output/sky_row.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/simd_target.hpp"
#include "facet/camera.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

TEST(SkyRow, GivesTheScalarBackgroundsBitsOnEveryTarget) {
  constexpr int kWidth = 203, kHeight = 117;
  constexpr float kClear = 1.0f;
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> any(-1.0f, 1.0f);
  Environment sky;
  sky.intensity = 1.7f;
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int round = 0; round < 20; ++round) {
      // Cameras looking up, down and level, so rows cross the horizon.
      const glm::vec3 eye{any(rng) * 10.0f, any(rng) * 10.0f, any(rng) * 10.0f};
      const glm::vec3 look{any(rng), any(rng) * 1.5f, any(rng) + 0.01f};
      const Camera camera =
          Camera::look_at(eye, eye + look, {0, 1, 0}, 30.0f + 60.0f * (any(rng) + 1.0f),
                          float(kWidth) / kHeight, 0.1f, 100.0f);
      const pipeline::SkyView view{glm::inverse(camera.view_projection()), eye, kWidth, kHeight};
      const int y = static_cast<int>(rng() % kHeight);
      const int x0 = static_cast<int>(rng() % 64), count = 1 + static_cast<int>(rng() % 64);
      std::vector<float> depth(count, kClear);
      for (float& z : depth) {
        // Covered (must stay as it was) in odd rounds only: even rounds' rows are all sky, which
        // whole vectors store at once.
        if (round % 2 == 1 && rng() % 4 == 0) z = 0.5f;
      }
      const glm::vec4 untouched{-1.0f, -2.0f, -3.0f, -4.0f};
      std::vector<glm::vec4> row(count, untouched);
      pipeline::sky_row_kernel(chosen_simd_target())(view, sky, x0, y, count, depth.data(), kClear,
                                                     row.data());
      for (int i = 0; i < count; ++i) {
        const glm::vec4 expected =
            depth[i] == kClear
                ? glm::vec4(pipeline::background_radiance(view, sky, x0 + i, y), 1.0f)
                : untouched;
        ASSERT_EQ(std::memcmp(&expected, &row[i], sizeof expected), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel (" << x0 + i << ", " << y
            << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500);
}

}  // namespace
}  // namespace facet::test
