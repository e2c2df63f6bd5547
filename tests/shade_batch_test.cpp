// The SIMD batch forms of the unlit, Lambert, Phong and Blinn-Phong models and the normals view
// (shade_batch.cpp) and of
// glmark2's shaders (scene/glmark2_batch.cpp) give their fragment()'s bits (then apply_fog's)
// on every SIMD target: one- and two-sided, with and without a base color texel, emission and
// fog (at a perspective or an orthographic camera's view depth), under zero to three directional
// lights; and they decline what they do not cover.
#include "shading/shade_batch.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "core/simd_target.hpp"
#include "scenes/glmark2_shading.hpp"
#include "shading/fog.hpp"
#include "shading/kernels.hpp"
#include "shading/lit_models.hpp"
#include "shading/models.hpp"
#include "support/forced_target.hpp"

namespace facet::test {
namespace {

using shading::kShadeBatch;

struct Inputs {
  alignas(64) float w[kShadeBatch] = {};
  alignas(64) float z[kShadeBatch] = {};
  alignas(64) float v[shading::kMaxVaryings][kShadeBatch] = {};
  alignas(64) float texel[kShadeBatch][4] = {};
};

void fill(std::mt19937& rng, Inputs& in) {
  std::uniform_real_distribution<float> any(-2.0f, 2.0f), unit(0.0f, 1.0f), depth(0.2f, 50.0f);
  for (int n = 0; n < kShadeBatch; ++n) {
    in.w[n] = depth(rng);
    in.z[n] = unit(rng);
    for (int k = 0; k < shading::kMaxVaryings; ++k) in.v[k][n] = any(rng);
    for (int c = 0; c < 4; ++c) in.texel[n][c] = unit(rng);
  }
  in.v[shading::kNormalSlot][0] = in.v[shading::kNormalSlot + 1][0] =
      in.v[shading::kNormalSlot + 2][0] = 0.0f;  // a zero normal: safe_normalize's other side
}

struct Draw {
  Material material;
  Lighting lighting;
  shading::LightData lights[3];
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;
};

void randomize(std::mt19937& rng, Draw& d) {
  std::uniform_real_distribution<float> any(-1.0f, 1.0f), unit(0.0f, 1.0f);
  d.material.cull = rng() % 2 ? CullMode::none : CullMode::back;
  d.material.emissive = rng() % 2 ? glm::vec3(0.0f) : glm::vec3(unit(rng), unit(rng), 0.0f);
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.kernels = shading::shading_kernels(chosen_simd_target());  // the forced target's
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.eye = {any(rng) * 5.0f, any(rng) * 5.0f, any(rng) * 5.0f};
  d.frame.ambient = {unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f};
  d.frame.light_count = static_cast<int>(rng() % 4);
  // Directional lights in half the draws (which some models' forms need: pipeline_table.cpp),
  // any kind in the others: point and spot lights near the surfaces, some with a range.
  const bool any_kind = rng() % 2 == 0;
  for (int i = 0; i < d.frame.light_count; ++i) {
    shading::LightData& l = d.lights[i];
    l = {};
    l.type = any_kind ? static_cast<LightType>(rng() % 3) : LightType::directional;
    l.to_light = glm::normalize(glm::vec3(any(rng), any(rng), any(rng)) + 0.01f);
    l.position = {any(rng) * 3.0f, any(rng) * 3.0f, any(rng) * 3.0f};
    l.spot_direction = glm::normalize(glm::vec3(any(rng), any(rng), any(rng)) + 0.01f);
    l.cos_outer = unit(rng) * 0.9f;
    l.cos_inner = rng() % 4 == 0 ? l.cos_outer : l.cos_outer + unit(rng) * (1.0f - l.cos_outer);
    l.inv_range_squared = rng() % 2 == 0 ? 0.0f : unit(rng) * 0.3f;
    l.radiance = {unit(rng) * 3.0f, unit(rng) * 3.0f, unit(rng) * 3.0f};
  }
  d.frame.lights = d.lights;
  d.material.base_color = {unit(rng), unit(rng), unit(rng), 1.0f};
  d.material.specular_color = {unit(rng), unit(rng), unit(rng)};
  d.material.shininess = rng() % 5 == 0 ? 0.0f : 1.0f + unit(rng) * 127.0f;
  d.uniforms.normal_matrix = glm::mat3(any(rng), any(rng), any(rng), any(rng), any(rng), any(rng),
                                       any(rng), any(rng), any(rng));
  switch (rng() % 3) {
    case 0:
      d.lighting.fog.mode = FogMode::none;
      break;
    case 1:
      d.lighting.fog.mode = FogMode::linear;
      d.lighting.fog.start = unit(rng) * 10.0f;
      d.lighting.fog.end = d.lighting.fog.start + unit(rng) * 40.0f;
      break;
    default:
      d.lighting.fog.mode = FogMode::exponential;
      d.lighting.fog.density = unit(rng) * 0.2f;
  }
  d.lighting.fog.color = {unit(rng), unit(rng), unit(rng)};
  // Display values decoded to linear, or kept as code / 255 (models.hpp's display_value).
  d.frame.display_referred = rng() % 2 == 0;
  // An orthographic camera's fog depth, from z (uniforms.hpp's ViewDepth), every third draw.
  if (rng() % 3 == 0) d.frame.view_depth = {0.0f, unit(rng) * 60.0f, unit(rng)};
}

template <class Shading>
glm::vec4 scalar_fragment(const Inputs& in, const float (*texel)[4], int n,
                          const shading::DrawUniforms& u) {
  shading::Fragment f;
  f.w = in.w[n];
  f.z = in.z[n];
  for (int k = 0; k < shading::kMaxVaryings; ++k) f.v[k] = in.v[k][n];
  if (texel != nullptr) {
    f.base_texel = {texel[n][0], texel[n][1], texel[n][2], texel[n][3]};
    f.base_texel_ready = true;
  }
  glm::vec4 color = Shading::fragment(f, u);
  shading::apply_fog(color, u.frame->view_depth(f.w, f.z), u.frame->lighting->fog);
  return color;
}

// Compares Shading::fragment_batch with fragment() (then apply_fog) over random batches, on
// every SIMD target; draws its batch_shades declines are skipped (enough must remain), and so
// are those `takes` declines (for models chosen only for some draws:
// pipeline/record/pipeline_table.cpp).
template <class Shading>
void expect_same_bits(bool (*takes)(const Draw&) = nullptr) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  std::mt19937 rng(20261122);
  int compared = 0;
  for (std::int64_t target : targets) {
    ForcedTarget forced(target);
    for (int round = 0; round < 40; ++round) {
      Inputs in;
      fill(rng, in);
      Draw draw;
      randomize(rng, draw);
      // A texture present: the models multiply by the texel only when the material has a map.
      const bool textured = round % 2 == 0;
      if (textured) draw.material.base_color_map.texture = missing_texture();
      const float(*texel)[4] = textured ? in.texel : nullptr;
      if (!Shading::batch_shades(draw.uniforms) || (takes && !takes(draw))) continue;
      // Every fourth round a whole block into rows 13 colors apart, as into a tile.
      const bool rows = round % 4 == 1;
      const int count = rows ? kShadeBatch : 1 + static_cast<int>(rng() % kShadeBatch);
      const int stride = rows ? 13 : 8;
      alignas(64) float rgba[8 * 13][4];
      shading::ShadeInput input{count, in.w, in.z, in.v, texel, &draw.lighting.fog};
      input.rgba_row_stride = stride;
      Shading::fragment_batch(draw.uniforms, input, rgba);
      for (int n = 0; n < count; ++n) {
        const glm::vec4 expected = scalar_fragment<Shading>(in, texel, n, draw.uniforms);
        const float* color = rgba[(n / 8) * stride + n % 8];
        ASSERT_EQ(std::memcmp(&expected, color, sizeof expected), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << ": ("
            << color[0] << ", " << color[1] << ", " << color[2] << ", " << color[3]
            << "), fragment() gives (" << expected.r << ", " << expected.g << ", " << expected.b
            << ", " << expected.a << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100 * static_cast<int>(simd_targets().size()));
}

TEST(ShadeBatch, LambertGivesFragmentsBitsOnEveryTarget) {
  expect_same_bits<shading::LambertShading>();
}

TEST(ShadeBatch, UnpositionedLambertGivesFragmentsBitsOnEveryTarget) {
  // Chosen only for draws lit from one side by directional lights.
  expect_same_bits<shading::UnpositionedLambertShading>([](const Draw& d) {
    return d.material.cull != CullMode::none && shading::only_directional_lights(d.uniforms);
  });
}

TEST(ShadeBatch, GouraudModelsGiveFragmentsBitsOnEveryTarget) {
  expect_same_bits<shading::GouraudShading>();
  // Chosen only for draws without a texture (nor vertex colors, which randomize() has none of).
  expect_same_bits<shading::ConstantColorGouraudShading>(
      [](const Draw& d) { return !d.material.base_color_map; });
}

TEST(ShadeBatch, PhongAndBlinnPhongGiveFragmentsBitsOnEveryTarget) {
  expect_same_bits<shading::PhongShading>();
  expect_same_bits<shading::BlinnPhongShading>();
}

TEST(ShadeBatch, UnlitGivesFragmentsBitsOnEveryTarget) {
  expect_same_bits<shading::UnlitShading>();
  expect_same_bits<shading::ConstantColorUnlitShading>();
}

TEST(ShadeBatch, NormalsViewGivesFragmentsBitsOnEveryTarget) {
  expect_same_bits<shading::NormalsShading>();
}

// glmark2's shaders (scene/glmark2_batch.cpp): they decline fog, and the textured ones need
// their map.
TEST(ShadeBatch, Glmark2ShadersGiveFragmentsBitsOnEveryTarget) {
  using namespace bench::glmark2;
  expect_same_bits<BasicLightShading>();
  expect_same_bits<BasicLightTextureShading>();
  expect_same_bits<BlinnPhongInfShading>();
  expect_same_bits<PhongShading>();
  expect_same_bits<CelShading>();
  expect_same_bits<BumpPolyShading>();
  expect_same_bits<BumpNormalsShading>();
}

}  // namespace
}  // namespace facet::test
