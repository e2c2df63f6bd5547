// Every SIMD target the machine supports (Highway's runtime dispatch, block_raster.cpp) gives
// the same pixels: identical to the reference rasterizer for coverage and depth, and identical
// images to the most portable target (Highway's EMU128 or SCALAR) with every shading model.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <random>
#include <string>

#include "pipeline/raster/block_raster.hpp"
#include "pipeline/reference.hpp"
#include "support/forced_target.hpp"
#include "support/random_soup.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

std::vector<std::int64_t> targets() { return simd_targets(); }

// At a size with partial tiles and partial 8x8 blocks.
Framebuffer render_odd_size(ShadingModel model) { return render_shapes(model, 203, 117); }

TEST(SimdTargets, MoreThanOneTargetIsTested) {
  // On x86-64 Highway always builds at least SSE4 and a portable fallback (the machine may add
  // AVX2 and AVX-512); if this fails, the tests below compare a target with itself.
  EXPECT_GE(targets().size(), 2u);
}

TEST(SimdTargets, EachForcedTargetIsTheOneThatRuns) {
  for (std::int64_t target : targets()) {
    ForcedTarget forced(target);
    EXPECT_EQ(std::string(pipeline::simd_target_name()), hwy::TargetName(target));
  }
}

TEST(SimdTargets, RandomSoupsMatchTheReferenceOnEveryTarget) {
  constexpr int kWidth = 67, kHeight = 43;
  Camera camera = test_camera(kWidth, kHeight, 70.0f, 0.5f, 40.0f);
  RenderSettings settings;
  settings.tile_size = 32;
  for (std::int64_t target : targets()) {
    ForcedTarget forced(target);
    std::mt19937 rng(20261122);
    for (int soup_index = 0; soup_index < 200; ++soup_index) {
      std::vector<glm::vec3> positions = random_soup(rng);
      Mesh mesh = soup(positions);
      pipeline::ReferenceImage expected = pipeline::reference_rasterize(
          positions, camera.view_projection(), CullMode::none, kWidth, kHeight);
      std::vector<int> counts =
          coverage_counts({&mesh}, camera, kWidth, kHeight, CullMode::none, settings);
      Framebuffer fb = render_unlit({&mesh}, camera, kWidth, kHeight, CullMode::none, settings);
      ASSERT_EQ(counts, expected.coverage)
          << hwy::TargetName(target) << ": coverage differs in soup " << soup_index;
      ASSERT_EQ(std::memcmp(fb.depth().data(), expected.depth.data(), fb.depth().size() * 4), 0)
          << hwy::TargetName(target) << ": depth differs in soup " << soup_index;
    }
  }
}

TEST(SimdTargets, EveryShadingModelGivesThePortableTargetsImage) {
  for (ShadingModel model : {ShadingModel::unlit, ShadingModel::gouraud, ShadingModel::phong,
                             ShadingModel::pbr, ShadingModel::wire_overlay, ShadingModel::depth,
                             ShadingModel::normals, ShadingModel::texcoords}) {
    Framebuffer expected = [&] {
      ForcedTarget portable(targets().back());  // the list is best first
      return render_odd_size(model);
    }();
    for (std::int64_t target : targets()) {
      ForcedTarget forced(target);
      Framebuffer fb = render_odd_size(model);
      ASSERT_EQ(fb.rgba8(), expected.rgba8())
          << to_string(model) << " on " << hwy::TargetName(target);
      ASSERT_EQ(fb.depth(), expected.depth())
          << to_string(model) << " on " << hwy::TargetName(target);
    }
  }
}

}  // namespace
}  // namespace facet::test
