// Gouraud draws of one constant surface color interpolate only their light
// (ConstantColorGouraudShading, 6 varyings): chosen exactly when nothing in the draw varies the
// color, and drawing what the 12-varying Gouraud model draws, but for the last bit of rounding
// of the interpolated constant color that it no longer has. Under gray light, one channel of it
// (GrayLightGouraudShading, 2 varyings), drawing what the 6-varying model draws but for the
// rounding of the ambient light, which it adds after interpolation.
#include <gtest/gtest.h>

#include <memory>

#include "facet/procedural.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "shading/lit_models.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

Material gouraud_material() {
  Material m;
  m.shading = ShadingModel::gouraud;
  m.base_color = {0.8f, 0.45f, 0.2f, 1.0f};
  m.specular_color = glm::vec3(0.6f);
  m.shininess = 24.0f;
  m.emissive = {0.05f, 0.0f, 0.02f};
  return m;
}

TEST(ConstantColorGouraud, IsChosenOnlyWhenNothingVariesTheColor) {
  const Mesh plain = uv_sphere(1.0f, 8, 4);
  Mesh colored = plain;
  colored.colors.assign(colored.positions.size(), glm::vec4(0.5f));
  const std::shared_ptr<const Texture> texture =
      Texture::from_rgba8(1, 1, {255, 255, 255, 255}, true, "white");
  constexpr int kConstant = shading::ConstantColorGouraudShading::kVaryings;
  constexpr int kFull = shading::GouraudShading::kVaryings;
  static_assert(kConstant < kFull);
  Lighting lights;
  lights.lights[0].color = {1.0f, 0.9f, 0.8f};  // not gray (GrayLightGouraud below)

  Material m = gouraud_material();
  EXPECT_EQ(pipeline::pipeline_for(m, plain, lights).varyings, kConstant);
  EXPECT_EQ(pipeline::pipeline_for(m, colored, lights).varyings, kFull);
  m.use_vertex_colors = false;  // the colors are ignored
  EXPECT_EQ(pipeline::pipeline_for(m, colored, lights).varyings, kConstant);
  Material textured = gouraud_material();
  textured.base_color_map.texture = texture;
  EXPECT_EQ(pipeline::pipeline_for(textured, plain, lights).varyings, kFull);
  Material glowing = gouraud_material();
  glowing.emissive_map.texture = texture;
  EXPECT_EQ(pipeline::pipeline_for(glowing, plain, lights).varyings, kFull);
}

// Two spheres of gouraud_material() drawn with `pipe`: the left with normals (lit per vertex), the
// right without (lit per face: face_without_normals). First, the pipeline the draw would get.
struct LitSpheres {
  Mesh sphere = uv_sphere(1.0f, 40, 20);
  Mesh faceted = without_normals(sphere);
  Material material = gouraud_material();
  Lighting lighting;

  static Mesh without_normals(Mesh mesh) {
    mesh.normals.clear();
    return mesh;
  }
  pipeline::DrawPipeline chosen() const {
    return pipeline::pipeline_for(material, sphere, lighting);
  }
  Framebuffer render(const pipeline::DrawPipeline& pipe) const {
    return render_side_by_side(sphere, faceted, material, pipe, 160, 120, &lighting);
  }
};

TEST(ConstantColorGouraud, DrawsWhatTheFullGouraudModelDraws) {
  LitSpheres spheres;
  spheres.lighting.lights[0].color = {1.0f, 0.9f, 0.8f};  // not gray
  const pipeline::DrawPipeline constant = spheres.chosen();
  ASSERT_EQ(constant.varyings, shading::ConstantColorGouraudShading::kVaryings);
  expect_same_but_rounding(spheres.render(pipeline::make_pipeline<shading::GouraudShading>()),
                           spheres.render(constant));
}

// What makes the light gray: every light's color and the material's specular color (the ambient
// light need not be).
TEST(GrayLightGouraud, IsChosenOnlyUnderGrayLight) {
  const Mesh sphere = uv_sphere(1.0f, 8, 4);
  constexpr int kGray = shading::GrayLightGouraudShading::kVaryings;
  constexpr int kConstant = shading::ConstantColorGouraudShading::kVaryings;
  static_assert(kGray < kConstant);
  const Material m = gouraud_material();
  Lighting lighting;  // one white sun; a bluish ambient light
  ASSERT_NE(lighting.ambient.r, lighting.ambient.b);
  lighting.lights.push_back(
      Light::spot({0, 3, 0}, {0, -1, 0}, 20.0f, 30.0f, glm::vec3(0.5f), 3.0f));
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, lighting).varyings, kGray);
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, lighting, true).varyings, kGray);  // shadowed

  Lighting tinted = lighting;
  tinted.lights[1].color = {1.0f, 0.9f, 0.8f};
  EXPECT_EQ(pipeline::pipeline_for(m, sphere, tinted).varyings, kConstant);
  Material tinted_highlight = m;
  tinted_highlight.specular_color = {0.6f, 0.6f, 0.5f};
  EXPECT_EQ(pipeline::pipeline_for(tinted_highlight, sphere, lighting).varyings, kConstant);
  Material blended = m;
  blended.alpha_mode = AlphaMode::blend;
  EXPECT_EQ(pipeline::pipeline_for(blended, sphere, lighting).varyings, kConstant);
}

TEST(GrayLightGouraud, DrawsWhatTheConstantColorModelDraws) {
  LitSpheres spheres;
  spheres.lighting.ambient = {0.1f, 0.2f, 0.35f};
  spheres.lighting.lights = {Light::directional({-0.4f, -0.5f, -1.0f}, glm::vec3(0.9f), 1.5f),
                             Light::point({2.0f, 1.0f, -2.0f}, glm::vec3(2.0f), 4.0f)};
  const pipeline::DrawPipeline gray = spheres.chosen();
  ASSERT_EQ(gray.varyings, shading::GrayLightGouraudShading::kVaryings);
  expect_same_but_rounding(
      spheres.render(pipeline::make_pipeline<shading::ConstantColorGouraudShading>()),
      spheres.render(gray));
}

}  // namespace
}  // namespace facet::test
