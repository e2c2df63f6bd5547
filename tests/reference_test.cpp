// The tiled fast path against the scalar reference rasterizer (src/pipeline/reference.cpp):
// identical coverage and identical depth on random triangle soups.
#include "pipeline/reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// Setup drops small triangles that cover no pixel centre (setup.hpp's kProbedBoxSide), and only
// those: of tiny triangles, the renderer draws exactly the ones the reference covers a pixel
// with.
TEST(ReferenceEquality, TinyTrianglesAreDrawnExactlyWhenTheyCoverAPixelCentre) {
  std::mt19937 rng(20261123);
  const Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  // At 3 units from the eye a pixel is about 0.1 units: vertices within 0.12 of a point are
  // a few pixels apart, their boxes at most 3 pixel centres a side.
  std::uniform_real_distribution<float> across(-2.5f, 2.5f), up(-1.6f, 1.6f), near(-0.12f, 0.12f);
  std::vector<glm::vec3> positions;
  std::uint64_t covering = 0;
  constexpr int kTriangles = 2000;
  for (int i = 0; i < kTriangles; ++i) {
    const glm::vec3 centre{across(rng), up(rng), -3.0f};
    std::vector<glm::vec3> triangle;
    for (int v = 0; v < 3; ++v) triangle.push_back(centre + glm::vec3(near(rng), near(rng), 0.0f));
    const pipeline::ReferenceImage alone = pipeline::reference_rasterize(
        triangle, camera.view_projection(), CullMode::none, kWidth, kHeight);
    covering += std::count_if(alone.coverage.begin(), alone.coverage.end(),
                              [](int n) { return n > 0; }) > 0;
    positions.insert(positions.end(), triangle.begin(), triangle.end());
  }
  // Both kinds are there.
  ASSERT_GT(covering, 200u);
  ASSERT_LT(covering, kTriangles - 200u);
  const Mesh mesh = soup(positions);
  Renderer renderer;
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  renderer.begin_frame(camera);
  renderer.draw(mesh, material);
  Framebuffer fb(kWidth, kHeight);
  renderer.finish(fb);
  EXPECT_EQ(renderer.stats().drawn, covering);
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
