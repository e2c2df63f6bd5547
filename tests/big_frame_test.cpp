// Frames too big to reserve room for every triangle (Frame::max_triangle_region_bytes, a
// quarter of the machine's memory: meshes of about 100 million triangles) set their triangles
// up without regions, into the chunks' overflow buffers: the image, depth and counts must be
// those of the ordinary path.
// Here the limit is lowered so that small scenes take that path.
// Draws with per-triangle hooks whose clip-space vertices would take too much memory
// (Frame::max_clip_vertex_bytes) keep none: primitive assembly computes the corners of the
// triangles culling keeps. The same check, with that limit lowered.
#include <gtest/gtest.h>

#include <memory>
#include <utility>

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

// The teapot world without vertex normals (face normals filled in: a hook), every material
// shaded `shading`, near plane cut as render_teapot's, with or without clip-space vertices.
Rendered render_teapot_faceted(ShadingModel shading, bool cut, bool clip_vertices) {
  Scene scene = make_builtin_scene("teapot");
  for (std::shared_ptr<const Mesh>& mesh : scene.meshes) {
    Mesh faceted = *mesh;
    faceted.normals.clear();
    faceted.tangents.clear();
    mesh = std::make_shared<const Mesh>(std::move(faceted));
  }
  for (Material& material : scene.materials) material.shading = shading;
  RenderSettings settings;
  settings.threads = 2;
  settings.msaa = 4;
  Renderer renderer(settings);
  if (!clip_vertices) pipeline::set_max_clip_vertex_bytes(renderer, 0);
  Rendered out;
  Camera camera = scene.camera;
  if (cut) camera.near_plane = glm::length(camera.target - camera.eye);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(out.framebuffer);
  out.stats = renderer.stats();
  return out;
}

TEST(BigFrames, CornersComputedInAssemblyDrawTheSameImage) {
  // Models with a batch vertex form and without (Gouraud lights the faces of a mesh without
  // normals in a per-face hook), seen whole and clipped by the near plane.
  for (ShadingModel shading :
       {ShadingModel::blinn_phong, ShadingModel::flat, ShadingModel::gouraud, ShadingModel::pbr}) {
    for (bool cut : {false, true}) {
      SCOPED_TRACE(static_cast<int>(shading));
      SCOPED_TRACE(cut);
      const Rendered kept = render_teapot_faceted(shading, cut, true);
      const Rendered computed = render_teapot_faceted(shading, cut, false);
      EXPECT_GT(kept.stats.drawn, 1000u);
      EXPECT_EQ(computed.stats.drawn, kept.stats.drawn);
      EXPECT_EQ(computed.stats.culled, kept.stats.culled);
      EXPECT_EQ(computed.stats.clipped, kept.stats.clipped);
      EXPECT_EQ(computed.framebuffer.rgba8(), kept.framebuffer.rgba8());
      EXPECT_EQ(computed.framebuffer.depth(), kept.framebuffer.depth());
    }
  }
}

}  // namespace
}  // namespace facet::test
