// Debug views (RenderSettings::debug_view): the overdraw heat map counts every covering
// triangle with no depth test, and the tile-bin view tints each tile by its bin size.
#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kSize = 128;  // two 64x64 tiles each way

// Two full-screen quads, one behind the other, drawn back to front: the depth test would hide
// nothing new, but the overdraw count must still see both.
Framebuffer render_two_layers(DebugView view, bool second_layer) {
  RenderSettings settings;
  settings.debug_view = view;
  settings.clear_color = glm::vec4(0.2f, 0.3f, 0.4f, 1.0f);
  Renderer renderer(settings);
  Framebuffer fb(kSize, kSize);
  Mesh far = soup({{-9, -9, -5}, {9, -9, -5}, {9, 9, -5}, {-9, -9, -5}, {9, 9, -5}, {-9, 9, -5}});
  Mesh near = soup({{-9, -9, -2}, {9, -9, -2}, {9, 9, -2}, {-9, -9, -2}, {9, 9, -2}, {-9, 9, -2}});
  Material material;
  material.cull = CullMode::none;
  renderer.begin_frame(test_camera(kSize, kSize));
  renderer.draw(far, material);
  if (second_layer) renderer.draw(near, material);
  renderer.finish(fb);
  return fb;
}

glm::vec3 rgb(const Framebuffer& fb, int x, int y) {
  const std::uint8_t* p = fb.rgba8().data() + (static_cast<std::size_t>(y) * fb.width() + x) * 4;
  return glm::vec3(p[0], p[1], p[2]);
}

TEST(DebugView, OverdrawCountsEveryLayerWithoutDepthTest) {
  Framebuffer one = render_two_layers(DebugView::overdraw, false);
  Framebuffer two = render_two_layers(DebugView::overdraw, true);
  // Ramp: 1 hit is blue, 2 hits green (sRGB display values, see debug_view.cpp).
  EXPECT_EQ(rgb(one, 10, 10), glm::vec3(26, 51, 230));
  EXPECT_EQ(rgb(two, 10, 10), glm::vec3(26, 204, 51));
  // The view is uniform: every pixel of a layer counts the same.
  EXPECT_EQ(rgb(two, 100, 90), rgb(two, 10, 10));
}

TEST(DebugView, OverdrawOfNothingIsBlackWhateverTheClearColor) {
  RenderSettings settings;
  settings.debug_view = DebugView::overdraw;
  settings.clear_color = glm::vec4(1.0f);
  Renderer renderer(settings);
  Framebuffer fb(64, 64);
  renderer.begin_frame(test_camera(64, 64));
  renderer.finish(fb);
  EXPECT_EQ(rgb(fb, 5, 5), glm::vec3(0.0f));
}

TEST(DebugView, TileBinsTintTilesByTheirBinSizeAndOutlineThem) {
  // One small triangle in the top-left tile only: that tile has 1 primitive, the others 0.
  RenderSettings settings;
  settings.debug_view = DebugView::tile_bins;
  settings.clear_color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Renderer renderer(settings);
  Framebuffer fb(kSize, kSize);
  Mesh small = soup({{-0.9f, 0.5f, -2}, {-0.6f, 0.5f, -2}, {-0.6f, 0.8f, -2}});
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  renderer.begin_frame(test_camera(kSize, kSize));
  renderer.draw(small, material);
  renderer.finish(fb);
  glm::vec3 busy = rgb(fb, 4, 60);       // top-left tile, away from the triangle
  glm::vec3 empty = rgb(fb, 100, 100);   // bottom-right tile
  glm::vec3 outline = rgb(fb, 64, 100);  // the bottom-right tile's left edge
  // Half of the ramp color over black: blue (1 primitive) and dark blue-black (0).
  EXPECT_EQ(busy, glm::vec3(13, 26, 115));
  EXPECT_EQ(empty, glm::vec3(0, 0, 0));
  EXPECT_EQ(outline, glm::vec3(0, 0, 0));
  // The same frame without the debug view is not tinted.
  Renderer plain;
  Framebuffer shaded(kSize, kSize);
  plain.begin_frame(test_camera(kSize, kSize));
  plain.draw(small, material);
  plain.finish(shaded);
  EXPECT_EQ(rgb(shaded, 4, 60), glm::vec3(0, 0, 0));
}

TEST(DebugView, ImagesAreTheSameForAnyThreadCount) {
  Scene scene = make_shapes_scene();
  for (DebugView view : {DebugView::overdraw, DebugView::tile_bins}) {
    std::vector<std::uint8_t> first;
    for (int threads : {1, 3}) {
      RenderSettings settings;
      settings.debug_view = view;
      settings.threads = threads;
      Renderer renderer(settings);
      Framebuffer fb(200, 120);
      renderer.begin_frame(frame_scene(scene, 200.0f / 120.0f), scene.lighting);
      draw_scene(renderer, scene);
      renderer.finish(fb);
      if (first.empty()) first = fb.rgba8();
      EXPECT_TRUE(fb.rgba8() == first) << "threads " << threads;
    }
  }
}

}  // namespace
}  // namespace facet::test
