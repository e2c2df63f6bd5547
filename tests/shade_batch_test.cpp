// The SIMD batch kernel of the built-in models (shade_batch.cpp), their only implementation:
// every target gives the portable target's bits, for one- and two-sided draws with and without
// each material map, emission, fog (at a perspective or an orthographic camera's view depth),
// reflections and the environment's light, under zero to three lights of every kind; the colors
// are the models' on cases worked out by hand; and the sky reflected by Phong and PBR surfaces
// (and lighting them) is its scalar definition's (support/sky_reference.hpp) on every target.
// So too for glmark2's shaders (bench/scenes/glmark2_batch.cpp), whose batch kernel is likewise
// their only implementation.
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
#include "shading/kernels.hpp"
#include "shading/lit_models.hpp"
#include "shading/models.hpp"
#include "support/display_reference.hpp"
#include "support/forced_target.hpp"
#include "support/sky_reference.hpp"

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
  shading::LightData lights[6];
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
  // None, a whole number (powers by repeated squaring) or any other (through log2 and exp2).
  const unsigned shininess_kind = rng() % 5;
  const float shininess = 1.0f + unit(rng) * 127.0f;
  d.material.shininess = shininess_kind == 0   ? 0.0f
                         : shininess_kind <= 2 ? std::floor(shininess)
                                               : shininess;
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
  // Display values decoded to linear, or kept as code / 255 (models.hpp).
  d.frame.display_referred = rng() % 2 == 0;
  // An orthographic camera's fog depth, from z (uniforms.hpp's ViewDepth), every third draw.
  if (rng() % 3 == 0) d.frame.view_depth = {0.0f, unit(rng) * 60.0f, unit(rng)};
}

// The raster loop's input for `count` pixels of `in`: the base color texel where the draw has
// the map, and each other map's where the raster loop samples it (maps_to_sample: the draw has
// it, the model reads it and, for the emissive map, the material emits).
template <class Shading>
shading::ShadeInput shade_input(const Inputs& in, int count, const Draw& draw) {
  const float(*texel)[4] = draw.material.base_color_map ? in.texel : nullptr;
  shading::ShadeInput input{count, in.w, in.z, in.v, texel, &draw.lighting.fog};
  constexpr unsigned kMapsRead = [] {
    if constexpr (requires { Shading::kMapsRead; }) return Shading::kMapsRead;
    return 0u;  // glmark2's shaders: the base color map alone
  }();
  const TextureMap* sampled[shading::kMaterialMaps];
  shading::maps_to_sample(kMapsRead, draw.material, sampled);
  for (int k = 0; k < shading::kMaterialMaps; ++k) {
    if (sampled[k] != nullptr) input.map_texel[k] = in.map_texel[k];
  }
  return input;
}

// Shades random batches with Shading::fragment_batch on every SIMD target and expects the
// portable target's bits from each; draws `takes` declines are skipped (for models chosen only
// for some draws: pipeline/record/pipeline_table.cpp), and `adapt` makes each random draw one
// the model is drawn with (for models whose draws are all of a kind).
template <class Shading>
void expect_every_target_alike(bool (*takes)(const Draw&) = nullptr,
                               void (*adapt)(Draw&) = nullptr) {
  const std::vector<std::int64_t> targets = simd_targets();
  ASSERT_GE(targets.size(), 2u);
  const std::int64_t portable = portable_simd_target();
  ASSERT_NE(portable, 0);
  std::mt19937 rng(20261122);
  int compared = 0;
  for (int round = 0; round < 60; ++round) {
    Inputs in;
    fill(rng, in);
    Draw draw;
    randomize(rng, draw);
    if (adapt) adapt(draw);
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
      std::fill_n(&rgba[0][0], 8 * 13 * 4, std::numeric_limits<float>::quiet_NaN());
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

// The depth and texture-coordinate views show, on every target, the values their definitions
// give (models.hpp), written out per pixel: 1 - (depth - near) / (far - near) clamped, and the
// coordinates' fractional parts, as display values (support/display_reference.hpp) in every
// kind of frame, for coordinates far outside [0, 1] and NaN too.
TEST(ShadeBatch, DebugViewsShowTheirDefinitionsOnEveryTarget) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), wide(-3e7f, 3e7f);
  int compared = 0;
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    for (int round = 0; round < 40; ++round) {
      Inputs in;
      fill(rng, in);
      for (int n = 0; n < kShadeBatch; ++n) {
        if (n % 3 == 0) in.v[0][n] = wide(rng), in.v[1][n] = wide(rng);
      }
      in.v[0][1] = std::numeric_limits<float>::quiet_NaN();
      in.v[1][2] = std::numeric_limits<float>::infinity();
      Draw draw;
      randomize(rng, draw);
      draw.lighting.fog.mode = FogMode::none;
      draw.frame.display_exact = round % 3 == 0;
      draw.frame.depth_view_near = unit(rng) * 10.0f;
      draw.frame.depth_view_far = draw.frame.depth_view_near + unit(rng) * 40.0f;
      const int count = 1 + static_cast<int>(rng() % kShadeBatch);
      alignas(64) float depth_view[kShadeBatch][4], texcoords_view[kShadeBatch][4];
      shading::DepthShading::fragment_batch(
          draw.uniforms, shade_input<shading::DepthShading>(in, count, draw), depth_view);
      shading::TexcoordShading::fragment_batch(
          draw.uniforms, shade_input<shading::TexcoordShading>(in, count, draw), texcoords_view);
      const shading::FrameUniforms& f = draw.frame;
      for (int n = 0; n < count; ++n) {
        const float t = (f.view_depth(in.w[n], in.z[n]) - f.depth_view_near) /
                        std::max(f.depth_view_far - f.depth_view_near, 1e-30f);
        const glm::vec4 depth =
            reference_display_value(glm::vec3(std::clamp(1.0f - t, 0.0f, 1.0f)), draw.uniforms);
        const float u = in.v[0][n], v = in.v[1][n];
        const glm::vec4 texcoords =
            reference_display_value({u - std::floor(u), v - std::floor(v), 0.0f}, draw.uniforms);
        ASSERT_EQ(std::memcmp(&depth, depth_view[n], sizeof depth), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n;
        ASSERT_EQ(std::memcmp(&texcoords, texcoords_view[n], sizeof texcoords), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << " at (" << u
            << ", " << v << ")";
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
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
  expect_every_target_alike<shading::GrayLightGouraudShading>(
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

// Each light adds its own highlight, whatever its kind and its place among the lights (the first
// directional lights' highlights are found ahead of the shading loop, the others in it): a batch
// of pixels of different normals and places under six lights of different strengths, a point
// light among them, against the sum written out.
TEST(ShadeBatch, PhongAndBlinnPhongAddEachLightsHighlight) {
  const glm::vec3 eye(0, 0, 10), lamp_at(1, -1, 3);
  const std::vector<shading::LightData> lights = {sun(glm::normalize(glm::vec3(1, 0, 2)), 1.0f),
                                                  lamp(lamp_at, 4.0f),
                                                  sun(glm::normalize(glm::vec3(0, 1, 1)), 2.0f),
                                                  sun(glm::normalize(glm::vec3(-1, 1, 3)), 0.25f),
                                                  sun(glm::normalize(glm::vec3(1, 1, 1)), 3.0f),
                                                  sun(glm::normalize(glm::vec3(-2, -1, 2)), 0.75f)};
  for (bool blinn : {false, true}) {
    Inputs in;
    Draw draw;
    plain_draw(draw, {});
    std::copy(lights.begin(), lights.end(), draw.lights);
    draw.frame.light_count = static_cast<int>(lights.size());
    draw.material.specular_color = glm::vec3(1.0f);
    draw.frame.eye = eye;
    glm::vec3 normal[kShadeBatch], position[kShadeBatch];
    for (int n = 0; n < kShadeBatch; ++n) {
      normal[n] = glm::normalize(glm::vec3((n % 8 - 3.5f) * 0.2f, (n / 8 - 3.5f) * 0.2f, 1.0f));
      position[n] = glm::vec3(n % 8 - 3.5f, n / 8 - 3.5f, 0.0f) * 0.25f;
      for (int c = 0; c < 3; ++c) {
        in.v[shading::kNormalSlot + c][n] = normal[n][c];
        in.v[shading::kPositionSlot + c][n] = position[n][c];
      }
      for (int c = 0; c < 4; ++c) in.v[shading::kColorSlot + c][n] = draw.material.base_color[c];
    }
    alignas(64) float rgba[kShadeBatch][4];
    const shading::ShadeInput input =
        blinn ? shade_input<shading::BlinnPhongShading>(in, kShadeBatch, draw)
              : shade_input<shading::PhongShading>(in, kShadeBatch, draw);
    if (blinn) {
      shading::BlinnPhongShading::fragment_batch(draw.uniforms, input, rgba);
    } else {
      shading::PhongShading::fragment_batch(draw.uniforms, input, rgba);
    }
    for (int n = 0; n < kShadeBatch; ++n) {
      const glm::vec3 view = glm::normalize(eye - position[n]);
      float expected = 0.5f * 0.25f;  // albedo x ambient
      for (const shading::LightData& l : lights) {
        glm::vec3 to_light = l.to_light;
        float radiance = l.radiance.x;
        if (l.type == LightType::point) {
          const glm::vec3 d = l.position - position[n];
          to_light = glm::normalize(d);
          radiance /= glm::dot(d, d);
        }
        const float n_dot_l = glm::dot(normal[n], to_light);
        if (n_dot_l <= 0.0f) continue;
        const float along = blinn ? glm::dot(normal[n], glm::normalize(to_light + view))
                                  : glm::dot(glm::reflect(-to_light, normal[n]), view);
        expected += radiance * (0.5f * n_dot_l + std::pow(std::max(along, 0.0f), 32.0f));
      }
      EXPECT_NEAR(rgba[n][0], expected, 1e-4f * expected) << (blinn ? "Blinn" : "Phong") << n;
    }
  }
}

TEST(ShadeBatch, NormalMapTurnsTheNormalWithinTheTangentFrame) {
  // A surface facing +Z lit from +X: dark unless its normal map turns it to +X.
  const auto phong = [](glm::vec3 texel, glm::vec3 tangent, glm::vec3 to_light = {1, 0, 0}) {
    Inputs in;
    Draw draw;
    plain_draw(draw, {sun(to_light)});
    draw.material.normal_map.texture = missing_texture();
    draw.material.normal_scale = 1.0f;
    place(in, draw, {0, 0, 1}, tangent);
    for (int c = 0; c < 3; ++c) in.map_texel[shading::kNormalMap][0][c] = texel[c];
    return shade_pixel<shading::PhongShading>(in, draw).r;
  };
  EXPECT_EQ(phong({0.5f, 0.5f, 1.0f}, {1, 0, 0}), 0.125f);  // the normal itself: ambient only
  EXPECT_EQ(phong({1.0f, 0.5f, 0.5f}, {1, 0, 0}), 0.625f);  // along the tangent, at the light
  // Without a tangent the map is not used: lit from +Z, a map turning the normal to -Z (which
  // the frame of a zero tangent would keep) leaves it lit.
  EXPECT_EQ(phong({0.5f, 0.5f, 0.0f}, {0, 0, 0}, {0, 0, 1}), 0.625f);
  EXPECT_EQ(phong({0.5f, 0.5f, 0.0f}, {1, 0, 0}, {0, 0, 1}), 0.125f);  // with one, turned away
}

TEST(ShadeBatch, SpecularMapScalesTheHighlight) {
  Inputs in;
  Draw draw;
  const glm::vec3 l = glm::normalize(glm::vec3(1, 0, 1));
  plain_draw(draw, {sun(l)});
  draw.material.base_color = {0, 0, 0, 1};  // specular light alone
  draw.material.specular_color = glm::vec3(1.0f);
  draw.material.specular_map.texture = missing_texture();
  draw.frame.ambient = glm::vec3(0.0f);
  place(in, draw, {0, 0, 1}, glm::vec3(0.0f), glm::vec3(-10, 0, 10));  // the view mirrors l
  const float texel[3] = {0.5f, 0.25f, 0.0f};
  for (int c = 0; c < 3; ++c) in.map_texel[shading::kSpecularMap][0][c] = texel[c];
  const glm::vec4 color = shade_pixel<shading::PhongShading>(in, draw);
  EXPECT_NEAR(color.r, 0.5f, 1e-5f);
  EXPECT_NEAR(color.g, 0.25f, 1e-5f);
  EXPECT_EQ(color.b, 0.0f);
}

TEST(ShadeBatch, PbrOcclusionAndMetallicRoughnessMapsScaleTheirFactors) {
  // No light: the ambient light alone, ambient x (albedo (1 - metallic) + f0 / 2) x occlusion.
  const auto pbr = [](float occlusion_texel, float metallic_texel) {
    Inputs in;
    Draw draw;
    plain_draw(draw, {});
    draw.material.base_color = glm::vec4(1.0f);
    draw.material.metallic = 1.0f;
    draw.material.occlusion_strength = 1.0f;
    draw.material.occlusion_map.texture = missing_texture();
    draw.material.metallic_roughness_map.texture = missing_texture();
    draw.frame.ambient = glm::vec3(1.0f);
    place(in, draw, {0, 0, 1});
    in.map_texel[shading::kOcclusionMap][0][0] = occlusion_texel;
    in.map_texel[shading::kMetallicRoughnessMap][0][1] = 1.0f;  // roughness
    in.map_texel[shading::kMetallicRoughnessMap][0][2] = metallic_texel;
    return shade_pixel<shading::PbrShading>(in, draw).r;
  };
  EXPECT_EQ(pbr(1.0f, 1.0f), 0.5f);            // a metal: f0 = albedo, halved
  EXPECT_NEAR(pbr(1.0f, 0.0f), 1.02f, 1e-6f);  // a dielectric: 1 + 0.04 / 2
  EXPECT_EQ(pbr(0.5f, 1.0f), 0.25f);           // half occluded
  EXPECT_EQ(pbr(0.0f, 0.0f), 0.0f);            // wholly occluded
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

// The fog, on every target: linear fog keeps all of the color before its start, half halfway,
// none past its end; exponential fog keeps e^(-density depth) (a polynomial: to within 1e-6),
// at the view depth of a perspective camera (w) and of an orthographic one (near + z (far -
// near)). Alpha is never fogged.
TEST(ShadeBatch, FogMixesTheColorTowardTheFogColorWithDepth) {
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    Draw draw;
    plain_draw(draw, {});
    Inputs in;
    const glm::vec3 fog_color{0.2f, 0.4f, 0.6f};
    const glm::vec4 color{1.0f, 0.0f, 0.5f, 0.25f};
    const float depths[] = {1.0f, 2.0f, 6.0f, 10.0f, 30.0f};
    auto fogged = [&](FogMode mode, shading::ViewDepth view_depth) {
      draw.lighting.fog = {mode, fog_color, 2.0f, 10.0f, 0.1f};
      draw.frame.view_depth = view_depth;
      alignas(64) float rgba[kShadeBatch][4];
      for (int n = 0; n < 5; ++n) {
        in.w[n] = view_depth.from_w != 0.0f ? depths[n] : 1.0f;
        in.z[n] = view_depth.from_z != 0.0f ? (depths[n] - 1.0f) / 49.0f : 0.5f;
        for (int c = 0; c < 4; ++c) rgba[n][c] = color[c];
      }
      const shading::ShadeInput input{5, in.w, in.z, in.v, nullptr, &draw.lighting.fog};
      draw.kernels.fog_batch(draw.uniforms, input, rgba);
      std::vector<glm::vec4> out;
      for (int n = 0; n < 5; ++n) out.emplace_back(rgba[n][0], rgba[n][1], rgba[n][2], rgba[n][3]);
      return out;
    };
    const shading::ViewDepth perspective{}, orthographic{0.0f, 49.0f, 1.0f};
    for (const shading::ViewDepth& view_depth : {perspective, orthographic}) {
      const std::vector<glm::vec4> linear = fogged(FogMode::linear, view_depth);
      const float linear_keep[] = {1.0f, 1.0f, 0.5f, 0.0f, 0.0f};
      const std::vector<glm::vec4> exponential = fogged(FogMode::exponential, view_depth);
      for (int n = 0; n < 5; ++n) {
        const float exp_keep = std::exp(-0.1f * depths[n]);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(linear[n][c], glm::mix(fog_color[c], color[c], linear_keep[n]), 1e-6f)
              << hwy::TargetName(target) << ", depth " << depths[n];
          EXPECT_NEAR(exponential[n][c], glm::mix(fog_color[c], color[c], exp_keep), 1e-6f)
              << hwy::TargetName(target) << ", depth " << depths[n];
        }
        EXPECT_EQ(linear[n].a, color.a);
        EXPECT_EQ(exponential[n].a, color.a);
      }
      const std::vector<glm::vec4> none = fogged(FogMode::none, view_depth);
      for (int n = 0; n < 5; ++n) EXPECT_EQ(none[n], color);
    }
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

// glmark2's shaders (bench/scenes/glmark2_batch.cpp) are drawn without fog, and the textured ones
// with their map (the scenes check both): random draws made so.
void glmark2_draw(Draw& d) {
  d.lighting.fog.mode = FogMode::none;
  d.material.base_color_map.texture = missing_texture();
}

TEST(ShadeBatch, Glmark2ShadersAreAlikeOnEveryTarget) {
  using namespace bench::glmark2;
  expect_every_target_alike<BasicLightShading>(nullptr, glmark2_draw);
  expect_every_target_alike<BasicLightTextureShading>(nullptr, glmark2_draw);
  expect_every_target_alike<BlinnPhongInfShading>(nullptr, glmark2_draw);
  expect_every_target_alike<PhongShading>(nullptr, glmark2_draw);
  expect_every_target_alike<CelShading>(nullptr, glmark2_draw);
  expect_every_target_alike<BumpPolyShading>(nullptr, glmark2_draw);
  expect_every_target_alike<BumpNormalsShading>(nullptr, glmark2_draw);
}

// A glmark2 draw of material colour `diffuse` in a display-referred frame (its colors are the
// 8-bit code / 255), no fog, the identity normal matrix.
void glmark2_plain_draw(Draw& d, glm::vec4 diffuse) {
  plain_draw(d, {});
  d.material.base_color = diffuse;
  d.frame.display_referred = true;
  d.uniforms.normal_matrix = glm::mat3(1.0f);
}

// Pixel 0 shaded by Shading with `varyings` (and base colour texel `texel`, when the draw has
// the map): the 8-bit codes it shows.
template <class Shading>
glm::vec3 glmark2_codes(const Draw& draw, std::initializer_list<float> varyings,
                        glm::vec4 texel = glm::vec4(0.0f)) {
  Inputs in;
  int k = 0;
  for (float v : varyings) in.v[k++][0] = v;
  for (int c = 0; c < 4; ++c) in.texel[0][c] = texel[c];
  alignas(64) float rgba[kShadeBatch][4];
  Shading::fragment_batch(draw.uniforms, shade_input<Shading>(in, 1, draw), rgba);
  EXPECT_EQ(rgba[0][3], 1.0f);
  return glm::vec3(rgba[0][0], rgba[0][1], rgba[0][2]) * 255.0f;
}

// The codes are those of `rgb` clamped to [0, 1], rounded to the nearest (within half a code:
// the hand-worked values are not rounded as the kernel's floats are, and some lie on a half).
void expect_codes(glm::vec3 codes, glm::vec3 rgb, const char* what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(codes[c], 255.0f * std::clamp(rgb[c], 0.0f, 1.0f), 0.501f)
        << what << ", channel " << c;
  }
}

template <class Shading>
glm::vec3 glmark2_vertex_light(const Draw& draw, glm::vec3 normal) {
  shading::VertexInput vertex{};
  vertex.normal = normal;
  float out[Shading::kVaryings] = {};
  Shading::vertex(vertex, draw.uniforms, out);
  return {out[0], out[1], out[2]};
}

TEST(ShadeBatch, Glmark2BasicLightShowsDiffuseTimesNDotL) {
  using namespace bench::glmark2;
  const glm::vec3 l(2.0f / 3.0f, 2.0f / 3.0f, 1.0f / 3.0f), z(0, 0, 1);
  Draw white;
  glmark2_plain_draw(white, glm::vec4(1.0f));
  const auto basic = [&](const Draw& draw, glm::vec3 n) {
    const glm::vec3 light = glmark2_vertex_light<BasicLightShading>(draw, n);
    return glmark2_codes<BasicLightShading>(draw, {light.x, light.y, light.z});
  };
  expect_codes(basic(white, z), glm::vec3(1.0f / 3.0f), "white, head-on");  // 85
  expect_codes(basic(white, l), glm::vec3(1.0f), "white, at the light");
  expect_codes(basic(white, -l), glm::vec3(0.0f), "white, turned away: black");
  Draw blue;
  glmark2_plain_draw(blue, {0, 0, 1, 1});
  expect_codes(basic(blue, z), {0.0f, 0.0f, 1.0f / 3.0f}, "blue, head-on");
  // The texture's: the same light times the texel.
  Draw crate;
  glmark2_plain_draw(crate, glm::vec4(1.0f));
  crate.material.base_color_map.texture = missing_texture();
  const glm::vec3 light = glmark2_vertex_light<BasicLightTextureShading>(crate, z);
  expect_codes(glmark2_codes<BasicLightTextureShading>(crate, {light.x, light.y, light.z, 0, 0},
                                                       {0.6f, 0.45f, 0.15f, 1.0f}),
               {0.2f, 0.15f, 0.05f}, "texel x 1/3");
}

TEST(ShadeBatch, Glmark2BlinnPhongLightsAtTheHalfVector) {
  using namespace bench::glmark2;
  const glm::vec3 l(2.0f / 3.0f, 2.0f / 3.0f, 1.0f / 3.0f);
  const glm::vec3 h = glm::vec3(1, 1, 2) / std::sqrt(6.0f);  // normalize(L + (0, 0, 1))
  const float l_dot_h = 2.0f / std::sqrt(6.0f);              // 0.816: ^100 is 2e-9, no highlight
  Draw draw;
  glmark2_plain_draw(draw, glm::vec4(1.0f));  // blinn-phong-inf's colours are its own
  const auto blinn = [&](glm::vec3 n) {
    return glmark2_codes<BlinnPhongInfShading>(draw, {n.x, n.y, n.z});
  };
  // rgb = 0.1 + 0.8 max(N.L, 0) (0, 0, 1) + 0.8 max(N.H, 0)^100; N normalized first.
  expect_codes(blinn(2.0f * l), {0.1f, 0.1f, 0.9f}, "N = L");
  expect_codes(blinn(h), {0.9f, 0.9f, 0.9f + 0.8f * l_dot_h}, "N = H: the highlight");
  expect_codes(blinn({0, 0, 1}), {0.1f, 0.1f, 0.1f + 0.8f / 3.0f}, "head-on");
  expect_codes(blinn(-l), glm::vec3(0.1f), "turned away: the ambient alone");
  // bump: white, specular 0.16: rgb = 0.1 + 0.8 max(N.L, 0) + 0.16 max(N.H, 0)^100.
  const auto bump_poly = [&](glm::vec3 n) {
    return glmark2_codes<BumpPolyShading>(draw, {n.x, n.y, n.z});
  };
  expect_codes(bump_poly(l), glm::vec3(0.9f), "bump-poly, N = L");
  expect_codes(bump_poly(h), glm::vec3(0.1f + 0.8f * l_dot_h + 0.16f), "bump-poly, N = H");
  expect_codes(bump_poly({0, 0, 1}), glm::vec3(0.1f + 0.8f / 3.0f), "bump-poly, head-on");
  // bump-normals: N = normalize(NormalMatrix (texel * 2 - 1)), the map's object-space normal.
  Draw bump;
  glmark2_plain_draw(bump, glm::vec4(1.0f));
  bump.material.base_color_map.texture = missing_texture();
  const auto bump_normals = [&](glm::vec3 n) {
    return glmark2_codes<BumpNormalsShading>(bump, {0, 0}, glm::vec4(n * 0.5f + 0.5f, 1.0f));
  };
  expect_codes(bump_normals({0, 0, 1}), glm::vec3(0.1f + 0.8f / 3.0f), "bump-normals, head-on");
  expect_codes(bump_normals(h), glm::vec3(0.1f + 0.8f * l_dot_h + 0.16f), "bump-normals, N = H");
  // Turned by the normal matrix, x -> y -> z -> x: the map's +Z is +X in the eye.
  bump.uniforms.normal_matrix =
      glm::mat3(glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(1, 0, 0));
  expect_codes(bump_normals({0, 0, 1}), glm::vec3(0.1f + 0.8f * 2.0f / 3.0f),
               "bump-normals, turned");
}

TEST(ShadeBatch, Glmark2PhongPeaksWhereTheLampMirrorsIntoTheEye) {
  using namespace bench::glmark2;
  // A pixel at eye (0, 0, -2), the lamp at (0, 1, 0): Ld = (0, 1, 2) / sqrt 5, E = (0, 0, 1).
  const glm::vec3 ld = glm::vec3(0, 1, 2) / std::sqrt(5.0f), e(0, 0, 1);
  const float n_dot_ld = 2.0f / std::sqrt(5.0f);  // head-on; R.E too, whose ^100 is 1e-5
  Draw draw;
  glmark2_plain_draw(draw, {0, 0, 1, 1});
  const auto phong = [&](glm::vec3 n) {
    return glmark2_codes<PhongShading>(draw, {n.x, n.y, n.z, 0.0f, 0.0f, -2.0f});
  };
  // rgb = 0.8 max(R.E, 0)^100 + 0.02 + 0.8 max(N.Ld, 0) x MaterialDiffuse.
  expect_codes(phong(e), {0.02f, 0.02f, 0.02f + 0.8f * n_dot_ld}, "head-on");
  const float half = std::sqrt((1.0f + n_dot_ld) / 2.0f);  // N.Ld for N halfway to the lamp
  expect_codes(phong(e + ld), {0.82f, 0.82f, 0.82f + 0.8f * half}, "the mirror: R = E");
  expect_codes(phong({0, -1, 0}), glm::vec3(0.02f), "turned from the lamp: the ambient");
  draw.material.base_color = {1.0f, 0.5f, 0.0f, 1.0f};
  expect_codes(phong(e), {0.02f + 0.8f * n_dot_ld, 0.02f + 0.4f * n_dot_ld, 0.02f},
               "orange, head-on");
}

TEST(ShadeBatch, Glmark2CelHasTwoGreensAnOutlineAndAHighlight) {
  using namespace bench::glmark2;
  // A pixel at eye P = (0, 0, -2): v = (4, 3, 1) - P = (4, 3, 3), |v| = sqrt 34,
  // att = sqrt 27 / sqrt 34 = 0.89, L = v / sqrt 34, V = (0, 0, 1).
  const glm::vec3 l = glm::vec3(4, 3, 3) / std::sqrt(34.0f), v(0, 0, 1);
  Draw draw;
  glmark2_plain_draw(draw, {0, 0, 1, 1});  // cel ignores the material
  const auto cel = [&](glm::vec3 n, float z = -2.0f) {
    return glmark2_codes<CelShading>(draw, {n.x, n.y, n.z, 0.0f, 0.0f, z});
  };
  // Head-on: d = 3 / sqrt 34 = 0.51, att d = 0.46 >= 0.1: the lit green; V.N = 1 is past
  // mix(0.1, 0.4, d); R.V = d, att d^10 = 0.001: no highlight.
  expect_codes(cel(v), {0.0f, 0.6f, 0.0f}, "lit");
  // Turned from the light (d = -0.12): the dark green, still facing the viewer.
  expect_codes(cel({-1, 0, 1}), {0.0f, 0.3f, 0.0f}, "unlit");
  // 60 deep the light is too weak: att = sqrt 27 / |(4, 3, 61)| = 0.085, att d < 0.1.
  expect_codes(cel(v, -60.0f), {0.0f, 0.3f, 0.0f}, "far: too weak a light");
  // Edge-on to the viewer (V.N = 0 < mix(0.1, 0.4, d)): the outline.
  expect_codes(cel({1, 0, 0}), glm::vec3(0.0f), "outline");
  // Halfway between L and V: R = V, att x 1 > 0.5: 0.7 + 0.3 x the lit green.
  expect_codes(cel(l + v), {0.7f, 0.7f + 0.3f * 0.6f, 0.7f}, "highlight");
}

// The sky seen in reflections, in SIMD lanes (shading/sky_gradient-inl.h), against its definition
// (support/sky_reference.hpp): random surfaces lit by nothing but the ambient light and a random
// sky environment, shaded by Shading on every target, each pixel's color compared bit for bit with
// expected(draw, its albedo, unit normal and unit view direction, computed with glm).
using SkyExpectation = glm::vec3 (*)(const Draw&, glm::vec3 albedo, glm::vec3 n, glm::vec3 view);

template <class Shading>
void expect_sky_reference_on_every_target(bool image_based_lighting, SkyExpectation expected) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), any(-1.0f, 1.0f);
  int compared = 0;
  for (int round = 0; round < 12; ++round) {
    Inputs in;
    fill(rng, in);
    for (int n = 0; n < kShadeBatch; ++n) {
      for (int c = 0; c < 4; ++c) in.v[shading::kColorSlot + c][n] = unit(rng);
    }
    in.v[shading::kNormalSlot][0] = 0.5f;  // fill() zeroes one normal; reflections need one
    Draw draw;
    plain_draw(draw, {});
    draw.frame.eye = {any(rng) * 5.0f, any(rng) * 5.0f, any(rng) * 5.0f};
    draw.frame.ambient = {unit(rng) * 0.2f, unit(rng) * 0.2f, unit(rng) * 0.2f};
    draw.material.reflectivity = 0.05f + unit(rng) * 0.95f;
    draw.material.metallic = unit(rng);
    draw.material.roughness = unit(rng);
    Environment& sky = draw.lighting.environment;
    sky.reflections = true;
    sky.intensity = 0.5f + unit(rng) * 2.0f;
    sky.sky_zenith = {unit(rng), unit(rng), unit(rng)};
    sky.sky_horizon = {unit(rng), unit(rng), unit(rng)};
    sky.ground = {unit(rng), unit(rng), unit(rng)};
    if (image_based_lighting) {
      draw.environment_light = shading::project_environment(sky);
      draw.frame.environment_light = &draw.environment_light;
    }
    const shading::ShadeInput input = shade_input<Shading>(in, kShadeBatch, draw);
    for (std::int64_t target : simd_targets()) {
      ForcedTarget forced(target);
      draw.kernels = shading::shading_kernels(chosen_simd_target());
      alignas(64) float rgba[kShadeBatch][4];
      Shading::fragment_batch(draw.uniforms, input, rgba);
      for (int n = 0; n < kShadeBatch; ++n) {
        glm::vec3 albedo, normal, position;
        for (int c = 0; c < 3; ++c) {
          albedo[c] = in.v[shading::kColorSlot + c][n];
          normal[c] = in.v[shading::kNormalSlot + c][n];
          position[c] = in.v[shading::kPositionSlot + c][n];
        }
        const glm::vec3 want = expected(draw, albedo, glm::normalize(normal),
                                        glm::normalize(draw.frame.eye - position));
        ASSERT_EQ(std::memcmp(&want, rgba[n], sizeof want), 0)
            << hwy::TargetName(target) << ", round " << round << ", pixel " << n << ": ("
            << rgba[n][0] << ", " << rgba[n][1] << ", " << rgba[n][2] << "), the reference ("
            << want.r << ", " << want.g << ", " << want.b << ")";
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 12 * kShadeBatch * 2);
}

// The PBR model's reflectance at normal incidence: mix(0.04, albedo, metallic).
glm::vec3 pbr_f0(const Material& m, glm::vec3 albedo) {
  return glm::vec3(0.04f * (1.0f - m.metallic)) + albedo * m.metallic;
}

TEST(ShadeBatch, PhongReflectsTheSkysDefinitionOnEveryTarget) {
  expect_sky_reference_on_every_target<shading::PhongShading>(
      false, [](const Draw& d, glm::vec3 albedo, glm::vec3 n, glm::vec3 v) {
        const glm::vec3 sky = sky_radiance(d.lighting.environment, glm::reflect(-v, n));
        return glm::mix(albedo * d.frame.ambient, sky, d.material.reflectivity);
      });
}

TEST(ShadeBatch, PbrReflectsTheSkysDefinitionOnEveryTarget) {
  // Reflections: the ambient light plus the mirror direction's sky through Fresnel, dimmed by
  // roughness.
  expect_sky_reference_on_every_target<shading::PbrShading>(
      false, [](const Draw& d, glm::vec3 albedo, glm::vec3 n, glm::vec3 v) {
        const Material& m = d.material;
        const glm::vec3 f0 = pbr_f0(m, albedo);
        const glm::vec3 ambient = d.frame.ambient * (albedo * (1.0f - m.metallic) + f0 * 0.5f);
        const float k = 1.0f - std::clamp(glm::dot(n, v), 0.0f, 1.0f);
        const glm::vec3 fresnel = f0 + (1.0f - f0) * (k * k * (k * k) * k);
        const glm::vec3 sky = sky_radiance(d.lighting.environment, glm::reflect(-v, n));
        return ambient + sky * fresnel * (1.0f - m.roughness * 0.7f);
      });
  // Image-based light: the split sum from the mirror direction's sky.
  expect_sky_reference_on_every_target<shading::PbrShading>(
      true, [](const Draw& d, glm::vec3 albedo, glm::vec3 n, glm::vec3 v) {
        const Material& m = d.material;
        const glm::vec3 mirror = glm::reflect(-v, n);
        return shading::environment_light(*d.frame.environment_light,
                                          {albedo, m.metallic, m.roughness}, pbr_f0(m, albedo), n,
                                          v, mirror, sky_radiance(d.lighting.environment, mirror));
      });
}

}  // namespace
}  // namespace facet::test
