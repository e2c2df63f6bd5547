// Opaque and cut-out draws cover what they draw: the image's alpha is 1 there whatever the
// texture's alpha channel holds, on every raster path (whole blocks, edges, small triangles,
// multisampled); a blended draw keeps its alpha.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/texture.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kSize = 64;

// An sRGB texture of one color with alpha 0.25.
std::shared_ptr<const Texture> quarter_alpha_texture() {
  std::vector<std::uint8_t> rgba(4 * 4 * 4);
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    rgba[i] = 200, rgba[i + 1] = 120, rgba[i + 2] = 40, rgba[i + 3] = 64;
  }
  return Texture::from_rgba8(4, 4, rgba, true, "quarter-alpha");
}

// A quad filling the view (whole blocks and edges) and a grid of tiny ones (small triangles),
// on a transparent background; returns the lowest alpha inside the quad (pixels 12 to 41 of
// every row: its whole blocks among them) and the tiny quads' highest.
struct Alphas {
  std::uint8_t big = 0, tiny = 0;
};
Alphas render_alphas(AlphaMode mode, int msaa, bool lit) {
  RenderSettings settings;
  settings.msaa = msaa;
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Material material;
  material.shading = lit ? ShadingModel::lambert : ShadingModel::unlit;
  material.alpha_mode = mode;
  material.alpha_cutoff = 0.1f;  // the mask keeps the texture's 0.25
  material.cull = CullMode::none;
  material.base_color_map.texture = quarter_alpha_texture();
  auto quad = std::make_shared<const Mesh>(rectangle(1.0f, 1.0f));
  renderer.begin_frame(test_camera(kSize, kSize));
  const glm::mat4 big =
      glm::scale(glm::translate(glm::mat4(1.0f), {-0.2f, 0.0f, -2.0f}), {1.2f, 2.4f, 1.0f});
  renderer.draw(quad, material, big);
  for (int i = 0; i < 8; ++i) {  // about 4 pixels wide: inner pixels have every sample covered
    const glm::mat4 tiny = glm::scale(
        glm::translate(glm::mat4(1.0f), {0.7f + 0.15f * (i % 2), -0.9f + 0.2f * i, -2.0f}),
        {0.15f, 0.15f, 1.0f});
    renderer.draw(quad, material, tiny);
  }
  Framebuffer fb(kSize, kSize);
  renderer.finish(fb);
  Alphas a;
  a.big = 255;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 12; x < 42; ++x) a.big = std::min(a.big, fb.rgba8()[(y * kSize + x) * 4 + 3]);
  }
  for (int y = 0; y < kSize; ++y) {
    for (int x = kSize * 3 / 4; x < kSize; ++x) {
      a.tiny = std::max(a.tiny, fb.rgba8()[(y * kSize + x) * 4 + 3]);
    }
  }
  return a;
}

TEST(OpaqueAlpha, OpaqueAndCutOutDrawsWriteAlphaOneWhateverTheTexture) {
  for (AlphaMode mode : {AlphaMode::opaque, AlphaMode::mask}) {
    for (int msaa : {1, 4}) {
      // Under MSAA a cut-out's alpha becomes coverage (alpha to coverage: msaa_test.cpp).
      if (mode == AlphaMode::mask && msaa > 1) continue;
      for (bool lit : {false, true}) {
        const Alphas a = render_alphas(mode, msaa, lit);
        EXPECT_EQ(a.big, 255) << to_string(mode) << " msaa " << msaa << " lit " << lit;
        EXPECT_EQ(a.tiny, 255) << to_string(mode) << " msaa " << msaa << " lit " << lit;
      }
    }
  }
}

TEST(OpaqueAlpha, BlendedDrawsKeepTheirAlpha) {
  const Alphas a = render_alphas(AlphaMode::blend, 1, false);
  EXPECT_EQ(a.big, 64);
}

}  // namespace
}  // namespace facet::test
