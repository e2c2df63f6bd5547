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

// `scene` from its own camera, its near plane through the target when `cut`, at 4 samples a
// pixel, by a renderer whose limits `limit` may lower.
Rendered render(const Scene& scene, bool cut, void (*limit)(Renderer&)) {
  RenderSettings settings;
  settings.threads = 2;
  settings.msaa = 4;
  Renderer renderer(settings);
  if (limit != nullptr) limit(renderer);
  Rendered out;
  Camera camera = scene.camera;
  if (cut) camera.near_plane = glm::length(camera.target - camera.eye);
  renderer.begin_frame(camera, scene.lighting);
  draw_scene(renderer, scene);
  renderer.finish(out.framebuffer);
  out.stats = renderer.stats();
  return out;
}

// Both frames drew the same triangles into the same image and depth.
void expect_same_frame(const Rendered& got, const Rendered& want) {
  EXPECT_GT(want.stats.drawn, 1000u);
  EXPECT_EQ(got.stats.drawn, want.stats.drawn);
  EXPECT_EQ(got.stats.culled, want.stats.culled);
  EXPECT_EQ(got.stats.clipped, want.stats.clipped);
  EXPECT_EQ(got.framebuffer.rgba8(), want.framebuffer.rgba8());
  EXPECT_EQ(got.framebuffer.depth(), want.framebuffer.depth());
}

void without_regions(Renderer& renderer) { pipeline::set_max_triangle_region_bytes(renderer, 0); }
void without_clip_vertices(Renderer& renderer) { pipeline::set_max_clip_vertex_bytes(renderer, 0); }

TEST(BigFrames, TrianglesSetUpWithoutRegionsDrawTheSameImage) {
  const Scene teapot = make_builtin_scene("teapot");
  // Seen whole, and cut in two by the near plane (clipping's extra triangles overflow in both
  // paths).
  for (bool cut : {false, true}) {
    SCOPED_TRACE(cut);
    expect_same_frame(render(teapot, cut, without_regions), render(teapot, cut, nullptr));
  }
  EXPECT_GT(render(teapot, true, nullptr).stats.clipped, 0u);
}

// The teapot world without vertex normals (face normals filled in: a hook), every material
// shaded `shading`.
Scene faceted_teapot(ShadingModel shading) {
  Scene scene = make_builtin_scene("teapot");
  for (std::shared_ptr<const Mesh>& mesh : scene.meshes) {
    Mesh faceted = *mesh;
    faceted.normals.clear();
    faceted.tangents.clear();
    mesh = std::make_shared<const Mesh>(std::move(faceted));
  }
  for (Material& material : scene.materials) material.shading = shading;
  return scene;
}

TEST(BigFrames, CornersComputedInAssemblyDrawTheSameImage) {
  // Models with a batch vertex form and without (Gouraud lights the faces of a mesh without
  // normals in a per-face hook), seen whole and clipped by the near plane.
  for (ShadingModel shading :
       {ShadingModel::blinn_phong, ShadingModel::flat, ShadingModel::gouraud, ShadingModel::pbr}) {
    const Scene scene = faceted_teapot(shading);
    for (bool cut : {false, true}) {
      SCOPED_TRACE(static_cast<int>(shading));
      SCOPED_TRACE(cut);
      expect_same_frame(render(scene, cut, without_clip_vertices), render(scene, cut, nullptr));
    }
  }
}

}  // namespace
}  // namespace facet::test
