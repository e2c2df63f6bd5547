// The tiled fast path against the scalar reference rasterizer (src/pipeline/reference.cpp):
// identical coverage and identical depth on random triangle soups.
#include "pipeline/reference.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "support/random_soup.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 67;  // odd sizes: partial tiles on both edges
constexpr int kHeight = 43;

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
