// Determinism: the image is bit-identical whatever the thread count and tile size.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

Framebuffer render_with(ShadingModel model, int threads, int tile_size, int width, int height) {
  RenderSettings settings;
  settings.threads = threads;
  settings.tile_size = tile_size;
  return render_shapes(model, width, height, settings);
}

TEST(Determinism, ThreadsAndTileSizesGiveIdenticalImages) {
  for (ShadingModel model : {ShadingModel::lambert, ShadingModel::flat, ShadingModel::wireframe,
                             ShadingModel::wire_overlay, ShadingModel::depth}) {
    Framebuffer expected = render_with(model, 1, 64, 333, 201);
    for (int threads : {1, 2, 3, 8}) {
      for (int tile : {16, 32, 64}) {
        Framebuffer fb = render_with(model, threads, tile, 333, 201);
        ASSERT_EQ(fb.rgba8(), expected.rgba8())
            << to_string(model) << " with " << threads << " threads, tile " << tile;
        ASSERT_EQ(fb.depth(), expected.depth());
      }
    }
  }
}

TEST(Determinism, AColorOnlyFramebufferGetsTheSameColors) {
  Scene scene = make_shapes_scene();
  Renderer renderer;
  Framebuffer full(203, 117);
  Framebuffer color_only(203, 117, ColorFormat::rgba8_srgb, DepthImage::none);
  for (Framebuffer* fb : {&full, &color_only}) {
    renderer.begin_frame(scene.camera, scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(*fb);
  }
  EXPECT_TRUE(full.has_depth());
  EXPECT_FALSE(color_only.has_depth());
  EXPECT_TRUE(color_only.depth().empty());
  EXPECT_EQ(color_only.rgba8(), full.rgba8());
}

TEST(Determinism, RepeatedFramesFromOneRendererAreIdentical) {
  Scene scene = make_shapes_scene();
  RenderSettings settings;
  settings.threads = 2;
  Renderer renderer(settings);
  Framebuffer first(256, 144), second(256, 144);
  for (Framebuffer* fb : {&first, &second}) {
    renderer.begin_frame(scene.camera, scene.lighting);
    draw_scene(renderer, scene);
    renderer.finish(*fb);
  }
  EXPECT_EQ(first.rgba8(), second.rgba8());
}

// Points crossing tile edges, at many depths and sizes, over a scene's triangles: the same image
// and depth for any thread count and tile size.
TEST(Determinism, PointsGiveIdenticalImagesForAnyThreadsAndTileSize) {
  Scene scene = make_shapes_scene();
  Mesh cloud;
  cloud.topology = Topology::points;
  std::uint32_t state = 12345;  // a small LCG: the same cloud on every machine
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  for (int i = 0; i < 3000; ++i) {
    cloud.positions.push_back({next() * 12.0f - 6.0f, next() * 6.0f - 2.0f, next() * 12.0f - 8.0f});
    cloud.colors.push_back({next(), next(), next(), 1.0f});
  }
  auto render = [&](int threads, int tile_size) {
    RenderSettings settings;
    settings.threads = threads;
    settings.tile_size = tile_size;
    Renderer renderer(settings);
    Framebuffer fb(333, 201);
    renderer.begin_frame(scene.camera, scene.lighting);
    draw_scene(renderer, scene);
    for (float size : {1.0f, 3.0f, 6.5f}) {
      Material material;
      material.point_size = size;
      renderer.draw(cloud, material,
                    glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, size * 0.1f, 0.0f)));
    }
    renderer.finish(fb);
    EXPECT_GT(renderer.stats().points_drawn, 1000u);
    return fb;
  };
  const Framebuffer expected = render(1, 64);
  for (int threads : {1, 2, 3}) {
    for (int tile : {16, 32, 128}) {
      const Framebuffer fb = render(threads, tile);
      ASSERT_EQ(fb.rgba8(), expected.rgba8()) << threads << " threads, tile " << tile;
      ASSERT_EQ(fb.depth(), expected.depth()) << threads << " threads, tile " << tile;
    }
  }
}

}  // namespace
}  // namespace facet::test
