// The shadow passes' casters write depth alone (DepthOnlyShading, pipeline/raster/depth_only.hpp):
// no varyings, no shading, no color, by their own raster path in one-sample tiles. The depths
// they leave must be those the shaded path leaves, bit for bit, whatever the triangles' sizes
// (the small-triangle search, partly and wholly covered blocks) and the order they overlap in.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "pipeline/record/custom_draw.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kWidth = 240, kHeight = 180;

// Spheres of tiny, middling and large triangles, drawn far to near and near to far, crossing
// each other, with `pipe` (none: nothing drawn).
Framebuffer render(const pipeline::DrawPipeline* pipe, int samples, int tile_size) {
  RenderSettings settings;
  settings.msaa = samples;
  settings.tile_size = tile_size;
  Renderer renderer(settings);
  renderer.begin_frame(test_camera(kWidth, kHeight));
  Material material;
  material.shading = ShadingModel::unlit;
  material.cull = CullMode::none;
  const Mesh fine = uv_sphere(1.0f, 160, 80), middling = uv_sphere(1.0f, 24, 12),
             coarse = uv_sphere(1.0f, 6, 3);
  const auto at = [](float x, float y, float z, float scale) {
    return glm::scale(glm::translate(glm::mat4(1.0f), {x, y, z}), glm::vec3(scale));
  };
  if (pipe != nullptr) {
    const std::pair<const Mesh*, glm::mat4> draws[] = {{&coarse, at(0.0f, 0.0f, -9.0f, 3.0f)},
                                                       {&fine, at(-1.0f, 0.3f, -4.0f, 1.0f)},
                                                       {&middling, at(-0.2f, 0.0f, -4.5f, 1.2f)},
                                                       {&coarse, at(1.5f, -0.5f, -3.5f, 0.8f)},
                                                       {&fine, at(1.0f, 0.8f, -12.0f, 2.5f)}};
    for (const auto& [mesh, transform] : draws) {
      pipeline::draw_with_pipeline(renderer, *mesh, material, transform, *pipe);
    }
  }
  Framebuffer target(kWidth, kHeight);
  renderer.finish(target);
  return target;
}

TEST(DepthOnly, WritesTheDepthsTheShadedPathWrites) {
  const auto depth_only = pipeline::make_pipeline<shading::DepthOnlyShading>();
  const auto shaded = pipeline::make_pipeline<shading::ConstantColorUnlitShading>();
  for (const int tile_size : {16, 64}) {
    const std::vector<float> expected = render(&shaded, 1, tile_size).depth();
    int drawn = 0;
    for (const float z : expected) drawn += z < 1.0f;
    ASSERT_GT(drawn, kWidth * kHeight / 4);  // the spheres are there
    const Framebuffer depth_alone = render(&depth_only, 1, tile_size);
    EXPECT_EQ(depth_alone.depth(), expected) << "tiles of " << tile_size;
    // And it took its own path: no color was written, where the shaded path writes white.
    EXPECT_EQ(depth_alone.rgba8(), render(nullptr, 1, tile_size).rgba8());
  }
}

TEST(DepthOnly, MultisampledTilesShadeItAndKeepTheSameDepths) {
  const auto depth_only = pipeline::make_pipeline<shading::DepthOnlyShading>();
  const auto shaded = pipeline::make_pipeline<shading::ConstantColorUnlitShading>();
  EXPECT_EQ(render(&depth_only, 4, 64).depth(), render(&shaded, 4, 64).depth());
}

}  // namespace
}  // namespace facet::test
