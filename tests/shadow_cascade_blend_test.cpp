// Where a sun's cascades meet (ShadowMaps' blend bands): along the view's depth across the
// split, the visibility moves from the near map's to the far map's without a jump, in the
// one-point definition (tests/support/light_reference.hpp) and, bit for bit the same, in the SIMD
// lookup (shadow_batch-inl.h) on every target; without the band it jumps by the whole difference.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "support/forced_target.hpp"
#include "support/light_reference.hpp"
#include "support/shadow_batch_probe.hpp"

namespace facet::test {
namespace {

constexpr int kMapSize = 64;

// A sun straight down over the ground (y = 0) with two maps that disagree everywhere: the near
// one holds an occluder over all of it (the ground in shadow), the far one nothing (lit). The
// view looks along +x from 1 above the ground; the near map serves depths up to 10, blending
// into the far one from 9 on.
struct TwoCascades {
  std::vector<float> occluded = std::vector<float>(kMapSize * kMapSize, 0.2f);
  std::vector<float> empty = std::vector<float>(kMapSize * kMapSize, 1.0f);
  shading::ShadowMaps maps;

  explicit TwoCascades(bool blend) {
    const float s = static_cast<float>(kMapSize);
    glm::mat4 to_map(1.0f);  // as pipeline/shadow/shadow_passes.cpp's shadow_map_of
    to_map[0][0] = 0.5f * s, to_map[3][0] = 0.5f * s - 0.5f;
    to_map[1][1] = -0.5f * s, to_map[3][1] = 0.5f * s - 0.5f;
    to_map[2][2] = 0.5f, to_map[3][2] = 0.5f;
    const glm::mat4 from_above =
        glm::lookAt(glm::vec3(0.0f, 20.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    maps.count = 2;
    maps.maps[0] = shading::make_shadow_map(
        to_map * glm::ortho(-16.0f, 16.0f, -16.0f, 16.0f, 1.0f, 40.0f) * from_above,
        occluded.data(), kMapSize, false);
    maps.maps[1] = shading::make_shadow_map(
        to_map * glm::ortho(-64.0f, 64.0f, -64.0f, 64.0f, 1.0f, 40.0f) * from_above, empty.data(),
        kMapSize, false);
    maps.eye = {0.0f, 1.0f, 0.0f};
    maps.forward = {1.0f, 0.0f, 0.0f};
    maps.far_depth[0] = 10.0f, maps.far_depth[1] = 1000.0f;
    maps.blend_from[0] = blend ? 9.0f : 10.0f;
    maps.blend_rate[0] = blend ? 1.0f : 0.0f;
  }
};

// Ground points from view depth 5 to 15, a step of 1/256 apart, facing up.
constexpr float kStep = 1.0f / 256.0f;
std::vector<glm::vec3> ground_along_view() {
  std::vector<glm::vec3> points;
  for (int i = 0; i <= 10 * 256; ++i) points.push_back({5.0f + kStep * i, 0.0f, 0.0f});
  return points;
}

// The largest change of the visibility between neighbouring points.
float largest_step(const std::vector<float>& visibility) {
  float largest = 0.0f;
  for (std::size_t i = 1; i < visibility.size(); ++i) {
    largest = std::max(largest, std::abs(visibility[i] - visibility[i - 1]));
  }
  return largest;
}

TEST(ShadowCascadeBlend, VisibilityIsContinuousAcrossTheSplit) {
  const std::vector<glm::vec3> points = ground_along_view();
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  for (const bool blend : {false, true}) {
    const TwoCascades sun(blend);
    std::vector<float> visibility;
    for (const glm::vec3& p : points) visibility.push_back(shadow_visibility(sun.maps, p, up));
    // Each map alone: the near one shadows the ground, the far one lights it.
    EXPECT_EQ(visibility.front(), 0.0f) << blend;
    EXPECT_EQ(visibility.back(), 1.0f) << blend;
    if (!blend) {
      EXPECT_EQ(largest_step(visibility), 1.0f);  // the seam
      continue;
    }
    // Over the band, a step of depth moves the visibility by that share of the difference (1).
    EXPECT_LE(largest_step(visibility), kStep * 1.001f);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const float depth = points[i].x;
      // Before the band the near map's, past the split the far map's, between them a line.
      const float expected = depth <= 9.0f ? 0.0f : depth > 10.0f ? 1.0f : depth - 9.0f;
      EXPECT_NEAR(visibility[i], expected, 1e-5f) << depth;
      if (depth <= 9.0f || depth > 10.0f) {
        EXPECT_EQ(visibility[i], expected) << depth;
      }
    }
    // The SIMD lookup on every target: the same bits.
    for (std::int64_t target : simd_targets()) {
      ForcedTarget forced(target);
      const std::vector<glm::vec3> normals(points.size(), up);
      std::vector<float> batch(points.size());
      shadow_visibility_batch(chosen_simd_target(), sun.maps, points.data(), normals.data(),
                              static_cast<int>(points.size()), batch.data());
      EXPECT_EQ(std::memcmp(batch.data(), visibility.data(), sizeof(float) * batch.size()), 0)
          << hwy::TargetName(target);
    }
  }
}

}  // namespace
}  // namespace facet::test
