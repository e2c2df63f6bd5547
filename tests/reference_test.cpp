// The tiled fast path against the scalar reference rasterizer (src/pipeline/reference.cpp):
// identical coverage and identical depth on random triangle soups.
#include "pipeline/reference.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 67;  // odd sizes: partial tiles on both edges
constexpr int kHeight = 43;

// Random triangles of every kind: small, large, slivers, partly off screen, crossing the near
// plane or with vertices behind the eye (the camera looks down -Z from the origin).
std::vector<glm::vec3> random_soup(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 4);
  std::uniform_int_distribution<int> count(1, 24);
  std::vector<glm::vec3> positions;
  int n = count(rng);
  for (int t = 0; t < n; ++t) {
    float depth = 1.0f + 9.0f * (unit(rng) + 1.0f);
    glm::vec3 centre{unit(rng) * depth, unit(rng) * depth * 0.6f, -depth};
    glm::vec3 v[3];
    switch (kind(rng)) {
      case 0:  // small
        for (auto& p : v) p = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.3f;
        break;
      case 1:  // large, partly off screen
        for (auto& p : v) p = centre + glm::vec3(unit(rng), unit(rng), unit(rng) * 0.3f) * 25.0f;
        break;
      case 2: {  // sliver: the third vertex almost on the line of the first two
        v[0] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 4.0f;
        v[1] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 4.0f;
        v[2] = glm::mix(v[0], v[1], 0.5f * (unit(rng) + 1.0f)) + glm::vec3(unit(rng)) * 0.002f;
        break;
      }
      case 3:  // crossing the near plane / behind the eye
        for (auto& p : v) p = glm::vec3(unit(rng) * 4.0f, unit(rng) * 3.0f, unit(rng) * 3.0f);
        break;
      default:  // shared edge with the previous triangle, when there is one
        if (positions.size() >= 3) {
          v[0] = positions[positions.size() - 1];
          v[1] = positions[positions.size() - 2];
        } else {
          v[0] = centre, v[1] = centre + glm::vec3(1, 0, 0);
        }
        v[2] = centre + glm::vec3(unit(rng), unit(rng), unit(rng)) * 3.0f;
        break;
    }
    positions.insert(positions.end(), {v[0], v[1], v[2]});
  }
  return positions;
}

TEST(ReferenceEquality, RandomSoupsGiveIdenticalCoverageAndDepth) {
  std::mt19937 rng(20261121);
  Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  RenderSettings settings;
  settings.tile_size = 16;
  for (int soup_index = 0; soup_index < 1000; ++soup_index) {
    std::vector<glm::vec3> positions = random_soup(rng);
    Mesh mesh = soup(positions);
    CullMode cull = soup_index % 3 == 0 ? CullMode::back : CullMode::none;
    pipeline::ReferenceImage expected =
        pipeline::reference_rasterize(positions, camera.view_projection(), cull, kWidth, kHeight);
    std::vector<int> counts = coverage_counts({&mesh}, camera, kWidth, kHeight, cull, settings);
    Framebuffer fb = render_unlit({&mesh}, camera, kWidth, kHeight, cull, settings);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      ASSERT_EQ(counts[i], expected.coverage[i]) << "coverage differs at pixel " << i % kWidth
                                                 << "," << i / kWidth << " in soup " << soup_index;
      // Bitwise: the same plane evaluated the same way must give the same float.
      ASSERT_EQ(std::memcmp(&fb.depth()[i], &expected.depth[i], sizeof(float)), 0)
          << "depth differs at pixel " << i % kWidth << "," << i / kWidth << " in soup "
          << soup_index << ": " << fb.depth()[i] << " vs " << expected.depth[i];
    }
  }
}

TEST(ReferenceEquality, ReferenceSeesADifference) {
  // Guard against a comparison that cannot fail: a soup and the same soup shifted by a pixel.
  Camera camera = test_camera(kWidth, kHeight);
  std::vector<glm::vec3> a = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
  std::vector<glm::vec3> b = a;
  for (auto& p : b) p.x += 0.05f;
  auto ra =
      pipeline::reference_rasterize(a, camera.view_projection(), CullMode::none, kWidth, kHeight);
  auto rb =
      pipeline::reference_rasterize(b, camera.view_projection(), CullMode::none, kWidth, kHeight);
  EXPECT_NE(ra.coverage, rb.coverage);
}

}  // namespace
}  // namespace facet::test
