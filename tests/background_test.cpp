// The environment background is drawn late, only into pixels no opaque triangle covered
// (pipeline/output/output.cpp fill_background): the image must be exactly sky where nothing is
// drawn and exactly the scene elsewhere, and blended surfaces must still blend over the sky.
#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 131, kHeight = 77;  // partial tiles

Lighting sky_lighting(bool show_sky) {
  Lighting lighting;
  lighting.environment.show_as_background = show_sky;
  return lighting;
}

Material unlit(glm::vec4 color, AlphaMode alpha = AlphaMode::opaque) {
  Material m;
  m.shading = ShadingModel::unlit;
  m.base_color = color;
  m.alpha_mode = alpha;
  return m;
}

Framebuffer render(const std::vector<std::pair<const Mesh*, Material>>& draws, bool show_sky) {
  Renderer renderer;
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight), sky_lighting(show_sky));
  for (const auto& [mesh, material] : draws) renderer.draw(*mesh, material);
  renderer.finish(fb);
  return fb;
}

TEST(Background, SkyExactlyWhereNothingOpaqueIsDrawn) {
  Mesh left = soup_quad(-3, -1, 0.5f, 2, -5), right = soup_quad(0, -2, 4, 1, -6);
  const std::vector<std::pair<const Mesh*, Material>> scene = {{&left, unlit({1, 0, 0, 1})},
                                                               {&right, unlit({0, 1, 0, 1})}};
  Framebuffer with_sky = render(scene, true);
  Framebuffer sky_only = render({}, true);
  Framebuffer no_sky = render(scene, false);
  int sky_pixels = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const bool drawn = no_sky.depth()[i] < 1.0f;
    sky_pixels += !drawn;
    for (int c = 0; c < 4; ++c) {
      const std::uint8_t expected = drawn ? no_sky.rgba8()[i * 4 + c] : sky_only.rgba8()[i * 4 + c];
      ASSERT_EQ(with_sky.rgba8()[i * 4 + c], expected) << "pixel " << i << " channel " << c;
    }
  }
  EXPECT_GT(sky_pixels, 1000);
  EXPECT_LT(sky_pixels, kWidth * kHeight - 1000);
}

TEST(Background, BlendedSurfacesBlendOverTheSky) {
  // A half-transparent quad over the sky: the sky under it must already be there.
  Mesh glass = soup_quad(-4, -4, 4, 4, -5);
  Framebuffer with_glass = render({{&glass, unlit({1, 0, 0, 0.5f}, AlphaMode::blend)}}, true);
  Framebuffer sky_only = render({}, true);
  const int centre = (kHeight / 2) * kWidth + kWidth / 2;
  // Red rises above the sky's, green and blue fall to about half: the sky shows through.
  EXPECT_GT(with_glass.rgba8()[centre * 4 + 0], sky_only.rgba8()[centre * 4 + 0]);
  EXPECT_LT(with_glass.rgba8()[centre * 4 + 2], sky_only.rgba8()[centre * 4 + 2]);
  EXPECT_GT(with_glass.rgba8()[centre * 4 + 2], 0);
}

}  // namespace
}  // namespace facet::test
