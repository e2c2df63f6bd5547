// Frames too big to reserve room for every triangle (Frame::max_triangle_region_bytes, a
// quarter of the machine's memory: meshes of about 100 million triangles) set their triangles
// up without regions, into the chunks' overflow buffers: the image, depth and counts must be
// those of the ordinary path.
// Here the limit is lowered so that small scenes take that path.
#include <gtest/gtest.h>

#include "facet/renderer.hpp"
#include "facet/scene.hpp"
#include "facet/worlds.hpp"
#include "pipeline/record/custom_draw.hpp"

namespace facet::test {
namespace {

struct Rendered {
  Framebuffer framebuffer{320, 200};
  FrameStats stats;
};

// The teapot world from its own camera, its near plane through the target when `cut`, at 4
// samples a pixel, with or without triangle regions.
Rendered render_teapot(bool cut, bool regions) {
  const Scene scene = make_builtin_scene("teapot");
  RenderSettings settings;
  settings.threads = 2;
  settings.msaa = 4;
  Renderer renderer(settings);
  if (!regions) pipeline::set_max_triangle_region_bytes(renderer, 0);
  Rendered out;
  Camera camera = scene.camera;
  if (cut) camera.near_plane = glm::length(camera.target - camera.eye);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(out.framebuffer);
  out.stats = renderer.stats();
  return out;
}

TEST(BigFrames, TrianglesSetUpWithoutRegionsDrawTheSameImage) {
  // Seen whole, and cut in two by the near plane (clipping's extra triangles overflow in both
  // paths).
  for (bool cut : {false, true}) {
    const Rendered regions = render_teapot(cut, true);
    const Rendered overflow = render_teapot(cut, false);
    EXPECT_GT(regions.stats.drawn, 1000u);
    EXPECT_EQ(overflow.stats.drawn, regions.stats.drawn);
    EXPECT_EQ(overflow.stats.culled, regions.stats.culled);
    EXPECT_EQ(overflow.stats.clipped, regions.stats.clipped);
    EXPECT_EQ(overflow.framebuffer.rgba8(), regions.framebuffer.rgba8());
    EXPECT_EQ(overflow.framebuffer.depth(), regions.framebuffer.depth());
  }
  EXPECT_GT(render_teapot(true, true).stats.clipped, 0u);
}

}  // namespace
}  // namespace facet::test
