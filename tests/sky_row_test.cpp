// The SIMD background (pipeline/output/sky_row.cpp) gives the bits of the sky's scalar definition
// (support/sky_reference.hpp) on every SIMD target, above and below the horizon, in rows all of
// sky and rows partly covered, and leaves covered pixels alone; with an image environment, the
// image's radiance along the scalar view direction of each pixel.
#include "pipeline/output/sky_row.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "core/simd_target.hpp"
#include "facet/camera.hpp"
#include "facet/texture.hpp"
#include "shading/environment.hpp"
#include "support/forced_target.hpp"
#include "support/sky_reference.hpp"
#include "support/texture_reference.hpp"

namespace facet::test {
namespace {

// Random rows of random views of `environment` through the row kernel on every target, each
// pixel the sky showed compared with expected(view, x, y).
void expect_rows_alike_on_every_target(const Environment& environment,
                                       glm::vec3 (*expected)(const pipeline::SkyView&,
                                                             const Environment&, int, int)) {
  constexpr int kWidth = 203, kHeight = 117;
  constexpr float kClear = 1.0f;
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<float> any(-1.0f, 1.0f);
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
      const SimdTarget chosen = chosen_simd_target();
      pipeline::sky_row_kernel(chosen)(view, environment, sample_at_kernel(chosen), x0, y, count,
                                       depth.data(), kClear, row.data());
      for (int i = 0; i < count; ++i) {
        const glm::vec4 want = depth[i] == kClear
                                   ? glm::vec4(expected(view, environment, x0 + i, y), 1.0f)
                                   : untouched;
        ASSERT_EQ(std::memcmp(&want, &row[i], sizeof want), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel (" << x0 + i << ", " << y
            << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 500);
}

TEST(SkyRow, GivesTheSkysDefinitionBitsOnEveryTarget) {
  Environment sky;
  sky.intensity = 1.7f;
  expect_rows_alike_on_every_target(sky, background_sky);
}

TEST(SkyRow, ReadsAnImageAlongEachPixelsViewDirectionOnEveryTarget) {
  // An equirectangular image of distinct texels, and the same as a sphere map.
  constexpr int kSide = 16;
  std::vector<float> rgba(kSide * kSide * 4);
  for (int i = 0; i < kSide * kSide; ++i) {
    rgba[i * 4] = static_cast<float>(i % kSide) / kSide;
    rgba[i * 4 + 1] = static_cast<float>(i / kSide) / kSide;
    rgba[i * 4 + 2] = static_cast<float>(i % 7) / 7.0f;
    rgba[i * 4 + 3] = 1.0f;
  }
  Environment environment;
  environment.image = Texture::from_rgba32f(kSide, kSide, std::move(rgba), "texels");
  environment.intensity = 1.3f;
  // The image at the direction's texture coordinates, clamped at the poles (and at the sphere
  // map's rim), at its base level.
  const auto image = [](const pipeline::SkyView& view, const Environment& env, int x, int y) {
    const glm::vec3 d = background_direction(view, x, y);
    const bool sphere = env.projection == EnvironmentProjection::sphere_map;
    const Sampler sampler{Filter::trilinear, sphere ? Wrap::clamp_to_edge : Wrap::repeat,
                          Wrap::clamp_to_edge};
    const glm::vec2 uv = sphere ? shading::sphere_map_uv(d) : shading::equirectangular_uv(d);
    return glm::vec3(reference_sample(*env.image, sampler, uv, 0.0f)) * env.intensity;
  };
  expect_rows_alike_on_every_target(environment, image);
  environment.projection = EnvironmentProjection::sphere_map;
  expect_rows_alike_on_every_target(environment, image);
}

}  // namespace
}  // namespace facet::test
