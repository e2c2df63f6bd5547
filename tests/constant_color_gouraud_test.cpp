// Gouraud draws of one constant surface color interpolate only their light
// (ConstantColorGouraudShading, 6 varyings): chosen exactly when nothing in the draw varies the
// color, and drawing what the 12-varying Gouraud model draws, but for the last bit of rounding
// of the interpolated constant color that it no longer has.
#include <gtest/gtest.h>

#include <cstdlib>
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
  const Lighting lights;

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

TEST(ConstantColorGouraud, DrawsWhatTheFullGouraudModelDraws) {
  constexpr int kWidth = 160, kHeight = 120;
  const Mesh sphere = uv_sphere(1.0f, 40, 20);  // normals: lit per vertex
  Mesh faceted = sphere;
  faceted.normals.clear();  // lit per face (face_without_normals)
  const Material material = gouraud_material();
  auto render = [&](const pipeline::DrawPipeline& pipe) {
    return render_side_by_side(sphere, faceted, material, pipe, kWidth, kHeight);
  };
  const Framebuffer full = render(pipeline::make_pipeline<shading::GouraudShading>());
  const Framebuffer constant = render(pipeline::pipeline_for(material, sphere, Lighting{}));
  int lit = 0, differing = 0;
  for (std::size_t i = 0; i < full.rgba8().size(); ++i) {
    const int difference = std::abs(full.rgba8()[i] - constant.rgba8()[i]);
    ASSERT_LE(difference, 1) << "byte " << i;
    differing += difference != 0;
    lit += i % 4 == 0 && full.rgba8()[i] != 0;
  }
  EXPECT_GT(lit, kWidth * kHeight / 8);  // the spheres are there
  EXPECT_LT(differing, lit / 20);        // and almost every byte is the same
  EXPECT_EQ(full.depth(), constant.depth());
}

}  // namespace
}  // namespace facet::test
