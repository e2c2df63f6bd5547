// glmark2's per-vertex light (build, gouraud) is shaded in batches: whole blocks straight into
// the tile, partly covered ones packed, small triangles' pixels waiting to be shaded together.
// It draws exactly what the same light draws one pixel at a time with a fragment() (the
// interpolated colour shown as an 8-bit code, the formula of the batch kernel).
#include <gtest/gtest.h>

#include "facet/procedural.hpp"
#include "pipeline/record/pipeline_table.hpp"
#include "scenes/glmark2_shading.hpp"
#include "support/display_reference.hpp"
#include "support/render_helpers.hpp"

namespace facet::test {
namespace {

using bench::glmark2::BasicLightShading;

// The same model without a batch form: fragment() per pixel, the interpolated colour shown as
// glmark2 stores it (glmark2_shading.hpp).
struct PerPixelBasicLight : shading::DisplayReferred {
  static constexpr int kVaryings = BasicLightShading::kVaryings;
  static constexpr int kNormalSlot = BasicLightShading::kNormalSlot;
  static void vertex(const shading::VertexInput& in, const shading::DrawUniforms& u, float* out) {
    BasicLightShading::vertex(in, u, out);
  }
  static glm::vec4 fragment(const shading::Fragment& f, const shading::DrawUniforms& u) {
    return reference_display_value(shading::load3(f.v), u);
  }
};

TEST(BasicLightBatch, DrawsWhatPerPixelShadingDraws) {
  // Big triangles (whole blocks, and blocks partly covered along their edges) and small ones.
  constexpr int kWidth = 320, kHeight = 240;
  const Mesh coarse = uv_sphere(1.0f, 10, 6);
  const Mesh fine = uv_sphere(0.8f, 48, 24);
  Material material;
  material.base_color = {0.9f, 0.6f, 0.3f, 1.0f};
  auto render = [&](const pipeline::DrawPipeline& pipe) {
    return render_side_by_side(coarse, fine, material, pipe, kWidth, kHeight);
  };
  const Framebuffer batched = render(pipeline::make_pipeline<BasicLightShading>());
  const Framebuffer per_pixel = render(pipeline::make_pipeline<PerPixelBasicLight>());
  int lit = 0;
  for (std::size_t i = 0; i < batched.rgba8().size(); ++i) {
    ASSERT_EQ(batched.rgba8()[i], per_pixel.rgba8()[i]) << "byte " << i;
    lit += i % 4 == 0 && batched.rgba8()[i] > 0;
  }
  EXPECT_GT(lit, kWidth * kHeight / 8);
}

}  // namespace
}  // namespace facet::test
