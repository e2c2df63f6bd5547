// Hidden work skipped: a tile's bin starts at the last triangle that hides everything before
// it (pipeline/occlusion.cpp), and 8x8 blocks behind what is drawn are rejected (raster.hpp).
// Both must leave every pixel as drawing everything would.
#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 160, kHeight = 96;

// A quad at depth z (camera at the origin looking down -Z) spanning [x0, x1] x [y0, y1].
Mesh quad(float x0, float y0, float x1, float y1, float z) {
  return soup({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}});
}

struct Layer {
  Mesh mesh;
  glm::vec4 color;
};

// Draws the layers in order, each an unlit single color; returns the image and the stats.
// Small tiles, so that most of them lie off the quads' diagonals.
Framebuffer draw_layers(const std::vector<Layer>& layers, FrameStats* stats) {
  RenderSettings settings;
  settings.tile_size = 16;
  Renderer renderer(settings);
  Framebuffer fb(kWidth, kHeight);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  for (const Layer& layer : layers) {
    Material material;
    material.shading = ShadingModel::unlit;
    material.base_color = layer.color;
    renderer.draw(layer.mesh, material);
  }
  renderer.finish(fb);
  if (stats) *stats = renderer.stats();
  return fb;
}

// Full-screen quads (at 60 degrees the view at depth d spans about +-0.58 d vertically).
Layer full_screen(float z, glm::vec4 color) {
  const float half = -z * 2.0f;
  return {quad(-half, -half, half, half, z), color};
}

TEST(Occlusion, BackToFrontLayersShadeLittleMoreThanTheFrontOne) {
  std::vector<Layer> layers;
  for (int i = 0; i < 6; ++i) {
    layers.push_back(full_screen(-10.0f + i, {0.1f * i, 0.5f, 1.0f - 0.1f * i, 1.0f}));
  }
  FrameStats stats;
  Framebuffer fb = draw_layers(layers, &stats);
  Framebuffer front = draw_layers({layers.back()}, nullptr);
  EXPECT_EQ(fb.rgba8(), front.rgba8());
  EXPECT_EQ(fb.depth(), front.depth());
  // All six layers would be 6 * pixels; only tiles a quad's diagonal crosses keep them all.
  const std::uint64_t pixels = std::uint64_t{kWidth} * kHeight;
  EXPECT_LT(stats.pixels_shaded, 3 * pixels);
  EXPECT_GE(stats.pixels_shaded, pixels);
}

TEST(Occlusion, FrontToBackLayersGiveTheFrontOne) {
  std::vector<Layer> layers;
  for (int i = 0; i < 6; ++i) layers.push_back(full_screen(-4.0f - i, {0.15f * i, 1, 0, 1}));
  FrameStats stats;
  Framebuffer fb = draw_layers(layers, &stats);
  Framebuffer front = draw_layers({layers.front()}, nullptr);
  EXPECT_EQ(fb.rgba8(), front.rgba8());
  EXPECT_EQ(fb.depth(), front.depth());
  EXPECT_EQ(stats.pixels_shaded, std::uint64_t{kWidth} * kHeight);
}

TEST(Occlusion, NearerSurfacesDrawnEarlierStayVisible) {
  // A small near quad first, then a full-screen far one, then a tilted full-screen one that
  // is nearer than the small quad on its left and farther on its right.
  Layer small{quad(-0.5f, -0.5f, 0.5f, 0.5f, -3.0f), {1, 0, 0, 1}};
  Layer far_wall = full_screen(-20.0f, {0, 0, 1, 1});
  Layer tilted{soup({{-40, -40, -1.0f},
                     {40, -40, -30.0f},
                     {40, 40, -30.0f},
                     {-40, -40, -1.0f},
                     {40, 40, -30.0f},
                     {-40, 40, -1.0f}}),
               {0, 1, 0, 1}};
  Framebuffer fb = draw_layers({small, far_wall, tilted}, nullptr);
  // The same picture drawn nearest-first can hide nothing early (no later triangle is nearer).
  Framebuffer expected = draw_layers({tilted, small, far_wall}, nullptr);
  EXPECT_EQ(fb.rgba8(), expected.rgba8());
  EXPECT_EQ(fb.depth(), expected.depth());
  // And the small red quad does show somewhere (the comparison is not between empty images).
  bool red = false;
  for (std::size_t i = 0; i < fb.rgba8().size(); i += 4) red |= fb.rgba8()[i] == 255;
  EXPECT_TRUE(red);
}

}  // namespace
}  // namespace facet::test
