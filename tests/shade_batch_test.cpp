// The SIMD batch kernel of the built-in models (shade_batch.cpp), their only implementation:
// every target gives the portable target's bits, for one- and two-sided draws with and without
// each material map, emission, fog (at a perspective or an orthographic camera's view depth),
// reflections and the environment's light, under zero to three lights of every kind; and the
// colors are the models' on cases worked out by hand. glmark2's shaders (bench/scenes/
// glmark2_batch.cpp), which keep a fragment(), give its bits.
#include "shading/shade_batch.hpp"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/simd_target.hpp"
#include "scenes/glmark2_shading.hpp"
#include "shading/environment_light.hpp"
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
  alignas(64) float map_texel[shading::kMaterialMaps][kShadeBatch][4] = {};
};

void fill(std::mt19937& rng, Inputs& in) {
  std::uniform_real_distribution<float> any(-2.0f, 2.0f), unit(0.0f, 1.0f), depth(0.2f, 50.0f);
  for (int n = 0; n < kShadeBatch; ++n) {
    in.w[n] = depth(rng);
    in.z[n] = unit(rng);
    for (int k = 0; k < shading::kMaxVaryings; ++k) in.v[k][n] = any(rng);
    for (int c = 0; c < 4; ++c) in.texel[n][c] = unit(rng);
    for (auto& map : in.map_texel) {
      for (int c = 0; c < 4; ++c) map[n][c] = unit(rng);
    }
  }
  in.v[shading::kNormalSlot][0] = in.v[shading::kNormalSlot + 1][0] =
      in.v[shading::kNormalSlot + 2][0] = 0.0f;  // a zero normal: safe_normalize's other side
}

struct Draw {
  Material material;
  Lighting lighting;
  shading::LightData lights[3];
  shading::IrradianceHarmonics environment_light{};
  shading::ShadingKernels kernels;
  shading::FrameUniforms frame;
  shading::DrawUniforms uniforms;
};

TextureMap& map_of(Material& m, shading::MaterialMap map) {
  return const_cast<TextureMap&>(shading::material_map(m, map));
}

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
  // Maps (their texels are the batch's input), PBR factors, reflections of the sky gradient and
  // its light.
  for (int k = 0; k < shading::kMaterialMaps; ++k) {
    const auto map = static_cast<shading::MaterialMap>(k);
    if (rng() % 2 == 0) map_of(d.material, map).texture = missing_texture();
  }
  d.material.normal_scale = 0.5f + unit(rng);
  d.material.occlusion_strength = unit(rng);
  d.material.metallic = unit(rng);
  d.material.roughness = unit(rng);
  d.material.reflectivity = rng() % 2 == 0 ? 0.0f : unit(rng);
  d.lighting.environment.reflections = rng() % 2 == 0;
  if (rng() % 3 == 0) {
    d.environment_light = shading::project_environment(d.lighting.environment);
    d.frame.environment_light = &d.environment_light;
  }
  // Display values decoded to linear, or kept as code / 255 (models.hpp's display_value).
  d.frame.display_referred = rng() % 2 == 0;
  // An orthographic camera's fog depth, from z (uniforms.hpp's ViewDepth), every third draw.
  if (rng() % 3 == 0) d.frame.view_depth = {0.0f, unit(rng) * 60.0f, unit(rng)};
}

// The raster loop's input for `count` pixels of `in`: the base color texel where the draw has
// the map, and each other map's where the draw has it, the model reads it (batch_maps) and, for
// the emissive map, the material emits.
template <class Shading>
shading::ShadeInput shade_input(const Inputs& in, int count, const Draw& draw) {
  const float(*texel)[4] = draw.material.base_color_map ? in.texel : nullptr;
  shading::ShadeInput input{count, in.w, in.z, in.v, texel, &draw.lighting.fog};
  for (int k = 0; k < shading::kMaterialMaps; ++k) {
    const auto map = static_cast<shading::MaterialMap>(k);
    const bool read = (Shading::kMapsRead & shading::map_bit(map)) != 0 &&
                      material_map(draw.material, map) &&
                      (map != shading::kEmissiveMap || draw.material.emissive != glm::vec3(0.0f));
    if (read) input.map_texel[k] = in.map_texel[k];
  }
  return input;
}

// The portable target (EMU128 or SCALAR), which the others must match.
std::int64_t portable_target(const std::vector<std::int64_t>& targets) {
  for (std::int64_t target : targets) {
    if (target == HWY_EMU128 || target == HWY_SCALAR) return target;
  }
  return targets.back();
}

// Shades random batches with Shading::fragment_batch on every SIMD target and expects the
// portable target's bits from each; draws `takes` declines are skipped (for models chosen only
// for some draws: pipeline/record/pipeline_table.cpp).
template <class Shading>
void expect_every_target_alike(bool (*takes)(const Draw&) = nullptr) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::int64_t portable = portable_target(targets);
  std::mt19937 rng(20261122);
  int compared = 0;
  for (int round = 0; round < 60; ++round) {
    Inputs in;
    fill(rng, in);
    Draw draw;
    randomize(rng, draw);
    if (takes && !takes(draw)) continue;
    // Every fourth round a whole block into rows 13 colors apart, as into a tile.
    const bool rows = round % 4 == 1;
    const int count = rows ? kShadeBatch : 1 + static_cast<int>(rng() % kShadeBatch);
    const int stride = rows ? 13 : 8;
    shading::ShadeInput input = shade_input<Shading>(in, count, draw);
    input.rgba_row_stride = stride;
    alignas(64) float expected[8 * 13][4];
    {
      ForcedTarget forced(portable);
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      Shading::fragment_batch(draw.uniforms, input, expected);
    }
    for (std::int64_t target : targets) {
      if (target == portable) continue;
      ForcedTarget forced(target);
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      alignas(64) float rgba[8 * 13][4];
      Shading::fragment_batch(draw.uniforms, input, rgba);
      for (int n = 0; n < count; ++n) {
        const float* want = expected[(n / 8) * stride + n % 8];
        const float* color = rgba[(n / 8) * stride + n % 8];
        ASSERT_EQ(std::memcmp(want, color, sizeof(float) * 4), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << ": ("
            << color[0] << ", " << color[1] << ", " << color[2] << ", " << color[3] << "), "
            << hwy::TargetName(portable) << " gives (" << want[0] << ", " << want[1] << ", "
            << want[2] << ", " << want[3] << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 20 * kShadeBatch / 2 * static_cast<int>(targets.size() - 1));
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

// For the models that keep a fragment() (glmark2's shaders): compares Shading::fragment_batch
// with fragment() (then apply_fog) over random batches, on every SIMD target; draws its
// batch_shades declines are skipped (enough must remain), and so are those `takes` declines.
template <class Shading>
void expect_fragments_bits(bool (*takes)(const Draw&) = nullptr) {
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
      for (int k = 0; k < shading::kMaterialMaps; ++k) {
        map_of(draw.material, static_cast<shading::MaterialMap>(k)) = {};  // theirs are their own
      }
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

TEST(ShadeBatch, LambertIsAlikeOnEveryTarget) {
  expect_every_target_alike<shading::LambertShading>();
}

TEST(ShadeBatch, UnpositionedLambertIsAlikeOnEveryTarget) {
  // Chosen only for draws lit from one side by directional lights.
  expect_every_target_alike<shading::UnpositionedLambertShading>([](const Draw& d) {
    return d.material.cull != CullMode::none && shading::only_directional_lights(d.uniforms);
  });
}

TEST(ShadeBatch, GouraudModelsAreAlikeOnEveryTarget) {
  expect_every_target_alike<shading::GouraudShading>();
  // Chosen only for draws without a texture (nor vertex colors, which randomize() has none of).
  expect_every_target_alike<shading::ConstantColorGouraudShading>(
      [](const Draw& d) { return !d.material.base_color_map; });
}

TEST(ShadeBatch, PhongBlinnPhongAndPbrAreAlikeOnEveryTarget) {
  expect_every_target_alike<shading::PhongShading>();
  expect_every_target_alike<shading::BlinnPhongShading>();
  expect_every_target_alike<shading::PbrShading>();
}

TEST(ShadeBatch, UnlitIsAlikeOnEveryTarget) {
  expect_every_target_alike<shading::UnlitShading>();
  expect_every_target_alike<shading::ConstantColorUnlitShading>();
}

TEST(ShadeBatch, NormalsViewIsAlikeOnEveryTarget) {
  expect_every_target_alike<shading::NormalsShading>();
}

// A draw of one gray material (base color 0.5) under ambient light 0.25 and `lights`, no fog.
void plain_draw(Draw& d, std::initializer_list<shading::LightData> lights) {
  d.material.base_color = {0.5f, 0.5f, 0.5f, 1.0f};
  d.material.specular_color = glm::vec3(0.0f);
  d.material.shininess = 32.0f;
  d.uniforms.material = &d.material;
  d.uniforms.frame = &d.frame;
  d.kernels = shading::shading_kernels(chosen_simd_target());
  d.frame.kernels = &d.kernels;
  d.frame.lighting = &d.lighting;
  d.frame.ambient = glm::vec3(0.25f);
  std::copy(lights.begin(), lights.end(), d.lights);
  d.frame.lights = d.lights;
  d.frame.light_count = static_cast<int>(lights.size());
}

shading::LightData sun(glm::vec3 to_light, float radiance = 1.0f) {
  shading::LightData l;
  l.to_light = to_light;
  l.radiance = glm::vec3(radiance);
  return l;
}

shading::LightData lamp(glm::vec3 position, float radiance) {
  shading::LightData l;
  l.type = LightType::point;
  l.position = position;
  l.radiance = glm::vec3(radiance);
  return l;
}

// Pixel 0 of `in` shaded by Shading, its color the material's (as the vertex stage writes it).
template <class Shading>
glm::vec4 shade_pixel(Inputs& in, const Draw& draw) {
  for (int c = 0; c < 4; ++c) in.v[shading::kColorSlot + c][0] = draw.material.base_color[c];
  alignas(64) float rgba[kShadeBatch][4];
  const shading::ShadeInput input = shade_input<Shading>(in, 1, draw);
  Shading::fragment_batch(draw.uniforms, input, rgba);
  return {rgba[0][0], rgba[0][1], rgba[0][2], rgba[0][3]};
}

// Pixel 0 at the origin with normal n, tangent t (handedness +1), seen from eye.
void place(Inputs& in, Draw& draw, glm::vec3 n, glm::vec3 t = glm::vec3(0.0f),
           glm::vec3 eye = {0, 0, 10}) {
  for (int c = 0; c < 3; ++c) {
    in.v[shading::kNormalSlot + c][0] = n[c];
    in.v[shading::kPositionSlot + c][0] = 0.0f;
    in.v[shading::kTangentSlot + c][0] = t[c];
  }
  in.v[shading::kTangentSlot + 3][0] = 1.0f;
  draw.frame.eye = eye;
}

TEST(ShadeBatch, LambertAddsEachLightFacingTheSurfaceToTheAmbient) {
  const glm::vec3 up(0, 1, 0);
  const auto lambert = [&](std::initializer_list<shading::LightData> lights) {
    Inputs in;
    Draw draw;
    plain_draw(draw, lights);
    place(in, draw, up);
    return shade_pixel<shading::LambertShading>(in, draw).r;
  };
  EXPECT_EQ(lambert({}), 0.125f);  // 0.5 x 0.25
  EXPECT_EQ(lambert({sun(up)}), 0.625f);
  EXPECT_EQ(lambert({sun(-up)}), 0.125f);                // from below: ambient alone
  EXPECT_EQ(lambert({sun(up), sun(up, 2.0f)}), 1.625f);  // 0.5 x (0.25 + 1 + 2)
  EXPECT_EQ(lambert({lamp({0, 2, 0}, 4.0f)}), 0.625f);   // 4 / 2^2
  shading::LightData ranged = lamp({0, 2, 0}, 4.0f);
  ranged.inv_range_squared = 1.0f / (1.5f * 1.5f);
  EXPECT_EQ(lambert({ranged}), 0.125f);  // beyond its range
  shading::LightData spot = lamp({0, 2, 0}, 4.0f);
  spot.type = LightType::spot;
  spot.spot_direction = -up;
  spot.cos_outer = 0.5f, spot.cos_inner = 0.9f;
  EXPECT_EQ(lambert({spot}), 0.625f);  // inside the cone
  spot.spot_direction = {1, 0, 0};
  EXPECT_EQ(lambert({spot}), 0.125f);  // outside it
}

TEST(ShadeBatch, PhongAndBlinnPhongPeakAtTheMirrorDirection) {
  const glm::vec3 n(0, 0, 1), l = glm::normalize(glm::vec3(1, 0, 1));
  for (bool blinn : {false, true}) {
    Inputs in;
    Draw draw;
    plain_draw(draw, {sun(l)});
    draw.material.base_color = {0, 0, 0, 1};  // specular light alone
    draw.material.specular_color = glm::vec3(1.0f);
    draw.frame.ambient = glm::vec3(0.0f);
    place(in, draw, n, glm::vec3(0.0f), glm::vec3(-10, 0, 10));  // the view mirrors l
    const float peak = blinn ? shade_pixel<shading::BlinnPhongShading>(in, draw).r
                             : shade_pixel<shading::PhongShading>(in, draw).r;
    EXPECT_NEAR(peak, 1.0f, 1e-5f) << blinn;
    draw.frame.eye = {0, 0, 10};  // 45 degrees off: far down the lobe
    const float off = blinn ? shade_pixel<shading::BlinnPhongShading>(in, draw).r
                            : shade_pixel<shading::PhongShading>(in, draw).r;
    EXPECT_LT(off, 0.1f) << blinn;
  }
}

TEST(ShadeBatch, NormalMapTurnsTheNormalWithinTheTangentFrame) {
  // A surface facing +Z lit from +X: dark unless its normal map turns it to +X.
  const auto phong = [](glm::vec3 texel, glm::vec3 tangent) {
    Inputs in;
    Draw draw;
    plain_draw(draw, {sun({1, 0, 0})});
    draw.material.normal_map.texture = missing_texture();
    draw.material.normal_scale = 1.0f;
    place(in, draw, {0, 0, 1}, tangent);
    for (int c = 0; c < 3; ++c) in.map_texel[shading::kNormalMap][0][c] = texel[c];
    return shade_pixel<shading::PhongShading>(in, draw).r;
  };
  EXPECT_EQ(phong({0.5f, 0.5f, 1.0f}, {1, 0, 0}), 0.125f);  // the normal itself: ambient only
  EXPECT_EQ(phong({1.0f, 0.5f, 0.5f}, {1, 0, 0}), 0.625f);  // along the tangent, at the light
  EXPECT_EQ(phong({1.0f, 0.5f, 0.5f}, {0, 0, 0}), 0.125f);  // no tangent: the map is not used
}

TEST(ShadeBatch, EmissiveMapScalesTheEmission) {
  Inputs in;
  Draw draw;
  plain_draw(draw, {});
  draw.material.emissive = glm::vec3(2.0f);
  draw.material.emissive_map.texture = missing_texture();
  const float texel[3] = {0.25f, 0.5f, 0.125f};
  for (int c = 0; c < 3; ++c) in.map_texel[shading::kEmissiveMap][0][c] = texel[c];
  EXPECT_EQ(shade_pixel<shading::UnlitShading>(in, draw), glm::vec4(1.0f, 1.5f, 0.75f, 1.0f));
  draw.material.emissive_map = {};
  EXPECT_EQ(shade_pixel<shading::UnlitShading>(in, draw), glm::vec4(2.5f, 2.5f, 2.5f, 1.0f));
}

// The PBR model's BRDF f(l, v) times pi n.l, for a white (albedo 1) surface of normal +Z lit by
// a unit sun along l and seen along each view[n] (pixel n at -view[n], the eye at the origin).
void pbr_lit(float metallic, float roughness, glm::vec3 l, const std::vector<glm::vec3>& views,
             std::vector<float>& red) {
  Inputs in;
  Draw draw;
  plain_draw(draw, {sun(l)});
  draw.material.base_color = glm::vec4(1.0f);
  draw.material.metallic = metallic, draw.material.roughness = roughness;
  draw.frame.ambient = glm::vec3(0.0f);
  draw.frame.eye = glm::vec3(0.0f);
  red.resize(views.size());
  for (std::size_t first = 0; first < views.size(); first += kShadeBatch) {
    const int count = static_cast<int>(std::min<std::size_t>(kShadeBatch, views.size() - first));
    for (int n = 0; n < count; ++n) {
      for (int c = 0; c < 4; ++c) in.v[shading::kColorSlot + c][n] = 1.0f;
      for (int c = 0; c < 3; ++c) {
        in.v[shading::kNormalSlot + c][n] = c == 2 ? 1.0f : 0.0f;
        in.v[shading::kPositionSlot + c][n] = -views[first + n][c];
      }
    }
    alignas(64) float rgba[kShadeBatch][4];
    shading::PbrShading::fragment_batch(draw.uniforms,
                                        shade_input<shading::PbrShading>(in, count, draw), rgba);
    for (int n = 0; n < count; ++n) red[first + n] = rgba[n][0];
  }
}

TEST(ShadeBatch, PbrSeenHeadOnIsMostlyLambertian) {
  // A rough dielectric seen and lit head-on: diffuse = (1 - F0)^2 albedo / pi (Fresnel on the
  // way in and out), plus a small specular part.
  std::vector<float> red;
  pbr_lit(0.0f, 1.0f, {0, 0, 1}, {{0, 0, 1}}, red);
  const float brdf = red[0] / shading::kPi;
  const float diffuse = 0.96f * 0.96f / shading::kPi;
  EXPECT_GT(brdf, diffuse);
  EXPECT_LT(brdf, diffuse + 0.1f);
}

// The white furnace: a white surface lit along l reflects at most what arrives, over all views:
// the integral of f(l, v) n.v over the hemisphere of views (the directional albedo, by the
// BRDF's reciprocity), by Monte Carlo with half the views cosine-weighted and half from the GGX
// lobe about l's mirror (weighted by the mixture's density), without which a sharp lobe is hit
// so rarely that the estimate is noise.
float directional_albedo(float metallic, float roughness, glm::vec3 l) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float r = std::clamp(roughness, 0.04f, 1.0f);
  const float a2 = std::pow(r, 4.0f);
  const auto ggx = [a2](float cos_h) {  // D(n.h)
    const float d = cos_h * cos_h * (a2 - 1.0f) + 1.0f;
    return a2 / (shading::kPi * d * d);
  };
  constexpr int kSamples = 64000;
  std::vector<glm::vec3> views;
  for (int i = 0; i < kSamples; ++i) {
    glm::vec3 v;
    if (i % 2 == 0) {
      const float s = std::sqrt(unit(rng)), phi = 2.0f * shading::kPi * unit(rng);
      v = {s * std::cos(phi), s * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - s * s))};
    } else {
      const float u = unit(rng), phi = 2.0f * shading::kPi * unit(rng);
      const float cos_h = std::sqrt((1.0f - u) / (1.0f + (a2 - 1.0f) * u));
      const float sin_h = std::sqrt(std::max(0.0f, 1.0f - cos_h * cos_h));
      v = glm::reflect(-l, glm::vec3(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h));
    }
    views.push_back(v);
  }
  std::vector<float> red;
  pbr_lit(metallic, roughness, l, views, red);
  double sum = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const glm::vec3 v = views[i];
    if (v.z <= 1e-4f) continue;
    const glm::vec3 h = glm::normalize(v + l);
    const float pdf_cosine = v.z / shading::kPi;
    const float pdf_lobe = ggx(h.z) * h.z / (4.0f * glm::dot(v, h));
    const float f = red[i] / (shading::kPi * l.z);
    sum += f * v.z / (0.5f * pdf_cosine + 0.5f * pdf_lobe);
  }
  return static_cast<float>(sum / kSamples);
}

TEST(ShadeBatch, PbrWhiteFurnaceNeverReflectsMoreThanArrives) {
  for (float metallic : {0.0f, 1.0f}) {
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
      for (float angle : {0.0f, 1.0f, 1.4f}) {
        const glm::vec3 l(std::sin(angle), 0.0f, std::cos(angle));
        const float albedo = directional_albedo(metallic, roughness, l);
        EXPECT_LE(albedo, 1.0f + 0.02f)
            << "metallic " << metallic << " roughness " << roughness << " angle " << angle;
        EXPECT_GT(albedo, 0.3f);  // and it reflects something
      }
    }
  }
}

// glmark2's shaders (scene/glmark2_batch.cpp): they decline fog, and the textured ones need
// their map.
TEST(ShadeBatch, Glmark2ShadersGiveFragmentsBitsOnEveryTarget) {
  using namespace bench::glmark2;
  expect_fragments_bits<BasicLightShading>();
  expect_fragments_bits<BasicLightTextureShading>();
  expect_fragments_bits<BlinnPhongInfShading>();
  expect_fragments_bits<PhongShading>();
  expect_fragments_bits<CelShading>();
  expect_fragments_bits<BumpPolyShading>();
  expect_fragments_bits<BumpNormalsShading>();
}

}  // namespace
}  // namespace facet::test
