// Unlit draws whose color is the material's alone interpolate only their texture coordinate
// (ConstantColorUnlitShading, 2 varyings instead of 6): chosen exactly when no vertex colors
// vary the color, and drawing what the full unlit model draws, but for the last bit of rounding
// of the interpolated constant color that it no longer has.
#include <gtest/gtest.h>

#include "facet/procedural.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

constexpr int kConstant = shading::ConstantColorUnlitShading::kVaryings;
constexpr int kFull = shading::UnlitShading::kVaryings;
static_assert(kConstant < kFull);

TEST(ConstantColorUnlit, IsChosenOnlyWhenNoVertexColorVariesTheColor) {
  const Mesh plain = uv_sphere(1.0f, 8, 4);
  Mesh colored = plain;
  colored.colors.assign(colored.positions.size(), glm::vec4(0.5f));
  const Lighting lights;
  Material m;
  m.shading = ShadingModel::unlit;
  EXPECT_EQ(pipeline::pipeline_for(m, plain, lights).varyings, kConstant);
  EXPECT_EQ(pipeline::pipeline_for(m, colored, lights).varyings, kFull);
  m.use_vertex_colors = false;  // the colors are ignored
  EXPECT_EQ(pipeline::pipeline_for(m, colored, lights).varyings, kConstant);
  m.base_color_map.texture = checker_texture();  // a texture reads the texture coordinate only
  EXPECT_EQ(pipeline::pipeline_for(m, colored, lights).varyings, kConstant);
  m.alpha_mode = AlphaMode::blend;
  EXPECT_EQ(pipeline::pipeline_for(m, plain, lights).varyings, kConstant);
}

TEST(ConstantColorUnlit, DrawsWhatTheFullUnlitModelDraws) {
  constexpr int kWidth = 160, kHeight = 120;
  const Mesh sphere = uv_sphere(1.0f, 40, 20);
  Material batched;
  batched.shading = ShadingModel::unlit;
  batched.base_color = {0.8f, 0.45f, 0.2f, 1.0f};
  batched.base_color_map.texture = checker_texture();
  batched.emissive = {0.05f, 0.0f, 0.02f};
  // An emissive map keeps the batch shader out: one pixel at a time (fragment()).
  Material per_pixel = batched;
  per_pixel.emissive_map.texture = checker_texture();
  for (const Material* material : {&batched, &per_pixel}) {
    auto render = [&](const pipeline::DrawPipeline& pipe) {
      return render_side_by_side(sphere, sphere, *material, pipe, kWidth, kHeight);
    };
    const pipeline::DrawPipeline chosen = pipeline::pipeline_for(*material, sphere, Lighting{});
    ASSERT_EQ(chosen.varyings, kConstant);
    expect_same_but_rounding(render(pipeline::make_pipeline<shading::UnlitShading>()),
                             render(chosen));
  }
}

}  // namespace
}  // namespace facet::test
