// Tiles where nothing is drawn write the clear color and depth only where the framebuffer does not
// hold them already (pipeline/output/output.cpp, write_cleared_row): a framebuffer drawn into
// again, whatever it held, must end exactly as a new one does.
#include <gtest/gtest.h>

#include <algorithm>

#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 200,
              kHeight = 150;  // empty tiles around the quad, partial ones at the edges

// A small quad in the middle of the frame, cleared to `clear`, into `target`.
void render_quad(const glm::vec4& clear, Framebuffer& target) {
  RenderSettings settings;
  settings.clear_color = clear;
  Renderer renderer(settings);
  Material material;
  material.shading = ShadingModel::unlit;
  material.base_color = {1.0f, 0.5f, 0.0f, 1.0f};
  const Mesh quad = soup_quad(-0.5f, -0.5f, 0.5f, 0.5f, -5.0f);
  renderer.begin_frame(test_camera(kWidth, kHeight), Lighting{});
  renderer.draw(quad, material);
  renderer.finish(target);
}

Framebuffer fresh_render(const glm::vec4& clear) {
  Framebuffer target(kWidth, kHeight);
  render_quad(clear, target);
  return target;
}

TEST(ClearedRows, AFramebufferDrawnIntoAgainEndsAsANewOne) {
  const glm::vec4 blue{0.1f, 0.2f, 0.6f, 1.0f}, grey{0.5f, 0.5f, 0.5f, 1.0f};
  const Framebuffer expected_blue = fresh_render(blue), expected_grey = fresh_render(grey);
  ASSERT_NE(expected_blue.rgba8(), expected_grey.rgba8());
  Framebuffer reused(kWidth, kHeight);
  std::fill(reused.rgba8().begin(), reused.rgba8().end(), std::uint8_t{0x5A});
  std::fill(reused.depth().begin(), reused.depth().end(), 0.25f);
  // Each frame over what the one before left: garbage, then the other clear, then the same.
  for (const glm::vec4* clear : {&blue, &grey, &grey, &blue}) {
    render_quad(*clear, reused);
    const Framebuffer& expected = clear == &blue ? expected_blue : expected_grey;
    ASSERT_EQ(reused.rgba8(), expected.rgba8());
    ASSERT_EQ(reused.depth(), expected.depth());
  }
}

}  // namespace
}  // namespace facet::test
