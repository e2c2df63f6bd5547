// Image-based lighting (Environment::image_based_lighting, shading/environment_light.hpp): the
// irradiance of environments whose exact irradiance is known, the split sum's BRDF integral at
// its ends, a PBR sphere lit by nothing but a uniform environment, whose diffuse light must be
// the albedo times the environment's radiance, and the harmonics of the procedural sky (its
// radiance in SIMD lanes) against the sky's scalar definition.
#include "shading/environment_light.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "core/simd_target.hpp"
#include "facet/procedural.hpp"
#include "facet/renderer.hpp"
#include "facet/texture.hpp"
#include "shading/pbr_surface.hpp"
#include "support/forced_target.hpp"
#include "support/render_helpers.hpp"
#include "support/sky_reference.hpp"

namespace facet::test {
namespace {

using shading::irradiance;
using shading::kPi;
using shading::project_environment;

// An equirectangular image, radiance `above` in its upper half and `below` in its lower.
std::shared_ptr<const Texture> two_halves(glm::vec3 above, glm::vec3 below) {
  constexpr int kWidth = 32, kHeight = 128;
  std::vector<float> rgba(kWidth * kHeight * 4);
  for (int y = 0; y < kHeight; ++y) {
    const glm::vec3 c = y < kHeight / 2 ? above : below;  // row 0 is the top
    for (int x = 0; x < kWidth; ++x) {
      float* p = &rgba[(y * kWidth + x) * 4];
      p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
    }
  }
  return Texture::from_rgba32f(kWidth, kHeight, std::move(rgba), "halves");
}

TEST(EnvironmentLight, AUniformEnvironmentGivesPiTimesItsRadianceEverywhere) {
  Environment environment;
  environment.image = two_halves(glm::vec3(0.7f, 0.5f, 0.2f), glm::vec3(0.7f, 0.5f, 0.2f));
  const shading::IrradianceHarmonics sh = project_environment(environment);
  for (glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0),
                      glm::normalize(glm::vec3(1, 2, -3))}) {
    const glm::vec3 e = irradiance(sh, n);
    EXPECT_NEAR(e.r, kPi * 0.7f, 0.003f);
    EXPECT_NEAR(e.g, kPi * 0.5f, 0.003f);
    EXPECT_NEAR(e.b, kPi * 0.2f, 0.003f);
  }
}

TEST(EnvironmentLight, AnOvercastSkyOverBlackGroundGivesTheHemisphereIrradiance) {
  // Radiance 1 above the horizon, 0 below: E = pi (1 + cos theta) / 2 from straight up, which
  // the first two bands hold exactly (the third band of a step is zero).
  Environment environment;
  environment.image = two_halves(glm::vec3(1.0f), glm::vec3(0.0f));
  environment.intensity = 2.0f;
  const shading::IrradianceHarmonics sh = project_environment(environment);
  for (float angle : {0.0f, 45.0f, 90.0f, 135.0f, 180.0f}) {
    const float theta = glm::radians(angle);
    const glm::vec3 n{std::sin(theta), std::cos(theta), 0.0f};
    const float want = 2.0f * kPi * (1.0f + std::cos(theta)) / 2.0f;
    EXPECT_NEAR(irradiance(sh, n).g, want, 0.05f) << angle << " degrees from up";
  }
}

TEST(EnvironmentLight, TheSpecularIntegralAtItsEnds) {
  // A mirror seen head on reflects all of f0 (scale + bias near 1 for f0 = 1, bias near 0).
  const shading::SpecularIntegral mirror = shading::specular_integral(1.0f, 0.0f);
  EXPECT_NEAR(mirror.scale + mirror.bias, 1.0f, 0.05f);
  EXPECT_NEAR(mirror.bias, 0.0f, 0.02f);
  // At grazing angles Fresnel takes over: the bias (white) grows.
  EXPECT_GT(shading::specular_integral(0.05f, 0.0f).bias, 0.3f);
  // Rough surfaces reflect less of f0 than smooth ones, head on.
  EXPECT_LT(shading::specular_integral(1.0f, 1.0f).scale, mirror.scale);
}

// A PBR sphere (roughness 0.6, dielectric) with base color `albedo`, lit by nothing but a
// uniform environment of radiance 0.8 (no lights, no constant ambient), into a float target.
Framebuffer sphere_in_uniform_light(float albedo, bool image_based) {
  constexpr int kSize = 48;
  RenderSettings settings;
  settings.clear_color = glm::vec4(0.0f);
  Renderer renderer(settings);
  Lighting lighting;
  lighting.lights.clear();
  lighting.ambient = glm::vec3(0.1f);
  lighting.environment.image = two_halves(glm::vec3(0.8f), glm::vec3(0.8f));
  lighting.environment.image_based_lighting = image_based;
  Material material;
  material.shading = ShadingModel::pbr;
  material.base_color = glm::vec4(glm::vec3(albedo), 1.0f);
  material.metallic = 0.0f;
  material.roughness = 0.6f;
  auto sphere = std::make_shared<const Mesh>(uv_sphere(1.0f, 48, 24));
  renderer.begin_frame(test_camera(kSize, kSize), lighting);
  renderer.draw(sphere, material, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -3.5f}));
  Framebuffer fb(kSize, kSize, ColorFormat::rgba32f);
  renderer.finish(fb);
  return fb;
}

TEST(EnvironmentLight, APbrSphereInUniformLightHasItsAlbedoTimesTheRadiance) {
  const Framebuffer bright = sphere_in_uniform_light(0.8f, true);
  const Framebuffer dark = sphere_in_uniform_light(0.2f, true);
  const Framebuffer constant_ambient = sphere_in_uniform_light(0.8f, false);
  int covered = 0;
  for (std::size_t p = 0; p < bright.rgba32f().size(); p += 4) {
    if (bright.rgba32f()[p + 3] == 0.0f) continue;  // the background
    ++covered;
    // The specular light does not depend on a dielectric's albedo: the difference is all
    // diffuse, (0.8 - 0.2) x 0.8 on every pixel, whatever way the surface faces.
    EXPECT_NEAR(bright.rgba32f()[p] - dark.rgba32f()[p], 0.6f * 0.8f, 0.01f) << p / 4;
    EXPECT_GT(bright.rgba32f()[p], 0.64f) << "diffuse and some specular";
    EXPECT_LT(constant_ambient.rgba32f()[p], 0.2f) << "lit by Lighting::ambient alone";
  }
  EXPECT_GT(covered, 300);
}

// The harmonics of the sky, as project_environment defines them, one direction at a time with
// the sky's scalar definition: the same grid of 64 x 32 directions, solid angles and sums.
shading::IrradianceHarmonics reference_sky_harmonics(const Environment& sky) {
  constexpr int kColumns = 64, kRows = 32;
  shading::IrradianceHarmonics sums{};
  const float cell = (2.0f * kPi / kColumns) * (kPi / kRows);
  for (int row = 0; row < kRows; ++row) {
    const float polar = (static_cast<float>(row) + 0.5f) * kPi / kRows;
    const float solid_angle = cell * std::sin(polar);
    for (int column = 0; column < kColumns; ++column) {
      const float azimuth = (static_cast<float>(column) + 0.5f) * 2.0f * kPi / kColumns;
      const glm::vec3 d{std::sin(polar) * std::cos(azimuth), std::cos(polar),
                        std::sin(polar) * std::sin(azimuth)};
      const glm::vec3 radiance = sky_radiance(sky, d) * solid_angle;
      const float y[9] = {0.282095f,
                          0.488603f * d.y,
                          0.488603f * d.z,
                          0.488603f * d.x,
                          1.092548f * d.x * d.y,
                          1.092548f * d.y * d.z,
                          0.315392f * (3.0f * d.z * d.z - 1.0f),
                          1.092548f * d.x * d.z,
                          0.546274f * (d.x * d.x - d.y * d.y)};
      for (int k = 0; k < 9; ++k) sums[k] += radiance * y[k];
    }
  }
  return sums;
}

TEST(EnvironmentLight, TheSkysHarmonicsAreThoseOfItsDefinitionOnEveryTarget) {
  Environment sky;
  sky.intensity = 1.3f;
  sky.ground = {0.1f, 0.4f, 0.2f};
  const shading::IrradianceHarmonics want = reference_sky_harmonics(sky);
  for (std::int64_t target : simd_targets()) {
    ForcedTarget forced(target);
    const shading::IrradianceHarmonics sh = project_environment(sky);
    EXPECT_EQ(std::memcmp(sh.data(), want.data(), sizeof want), 0) << hwy::TargetName(target);
  }
}

}  // namespace
}  // namespace facet::test
