// Lambert draws lit by directional lights only, from one side, leave out the interpolated
// position they never read (UnpositionedLambertShading, 9 varyings instead of 12): chosen exactly
// then, and drawing the very bytes the full Lambert model draws, whether shaded a batch at a
// time or one pixel at a time.
#include <gtest/gtest.h>

#include <memory>

#include "facet/procedural.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kUnpositioned = shading::UnpositionedLambertShading::kVaryings;
constexpr int kFull = shading::LambertShading::kVaryings;
static_assert(kUnpositioned < kFull);

TEST(UnpositionedLambert, IsChosenOnlyForOneSidedDrawsUnderDirectionalLights) {
  const Mesh sphere = uv_sphere(1.0f, 8, 4);
  Material m;
  m.shading = ShadingModel::lambert;
  Lighting suns;
  suns.lights = {Light::directional({0, -1, 0}), Light::directional({1, 0, 0})};
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, suns).varyings, kUnpositioned);
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, Lighting{}).varyings, kUnpositioned);
  m.cull = CullMode::front;
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, suns).varyings, kUnpositioned);
  m.cull = CullMode::none;  // back faces turn to the viewer: that needs the position
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, suns).varyings, kFull);
  m.cull = CullMode::back;
  Lighting lamp = suns;
  lamp.lights.push_back(Light::point({0, 2, 0}));
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, lamp).varyings, kFull);
  Lighting spot = suns;
  spot.lights.push_back(Light::spot({0, 2, 0}, {0, -1, 0}, 20.0f, 30.0f));
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, spot).varyings, kFull);
  m.shading = ShadingModel::phong;  // specular light needs the view
  EXPECT_NE(pipeline::pipeline_for(m, sphere, suns).varyings, kUnpositioned);
}

TEST(UnpositionedLambert, DrawsWhatTheFullLambertModelDraws) {
  constexpr int kWidth = 160, kHeight = 120;
  Mesh sphere = uv_sphere(1.0f, 40, 20);
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    sphere.colors.push_back({0.5f + 0.5f * sphere.normals[i].x, 0.8f, 0.4f, 1.0f});
  }
  Mesh faceted = sphere;
  faceted.normals.clear();  // the face normal fills the normal slot
  const std::shared_ptr<const Texture> checker = checker_texture();
  Material batched;
  batched.shading = ShadingModel::lambert;
  batched.base_color_map.texture = checker;
  batched.use_vertex_colors = true;
  batched.emissive = {0.02f, 0.0f, 0.05f};
  // An emissive map keeps the batch shader out: one pixel at a time (fragment()).
  Material per_pixel = batched;
  per_pixel.emissive_map.texture = checker;
  Lighting lighting;
  lighting.lights = {Light::directional({-0.4f, -1.0f, -0.6f}),
                     Light::directional({1.0f, 0.2f, -0.3f}, {0.3f, 0.4f, 0.9f}, 0.7f)};
  lighting.fog.mode = FogMode::linear;
  lighting.fog.start = 3.0f;
  lighting.fog.end = 9.0f;
  for (const Material* material : {&batched, &per_pixel}) {
    auto render = [&](const pipeline::DrawPipeline& pipe) {
      return render_side_by_side(sphere, faceted, *material, pipe, kWidth, kHeight, &lighting);
    };
    const pipeline::DrawPipeline chosen = pipeline::pipeline_for(*material, sphere, lighting);
    ASSERT_EQ(chosen.varyings, kUnpositioned);
    const Framebuffer full = render(pipeline::make_pipeline<shading::LambertShading>());
    const Framebuffer unpositioned = render(chosen);
    EXPECT_EQ(full.rgba8(), unpositioned.rgba8());
    EXPECT_EQ(full.depth(), unpositioned.depth());
    int lit = 0;  // the spheres are there, lit in more than one shade
    for (std::size_t i = 0; i < full.rgba8().size(); i += 4) lit += full.rgba8()[i] > 60;
    EXPECT_GT(lit, kWidth * kHeight / 10);
  }
}

}  // namespace
}  // namespace facet::test
