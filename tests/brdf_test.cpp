// Reflectance and light models against known numbers: GGX, Smith, Schlick, energy
// conservation (white furnace), Phong lobes, light attenuation and spot cones.
#include "shading/brdf.hpp"

#include <gtest/gtest.h>

#include <random>

#include "shading/lighting.hpp"

namespace facet::shading {
namespace {

TEST(Brdf, GgxDistributionKnownValues) {
  // At n.h = 1, D = 1 / (pi alpha^2) with alpha = roughness^2.
  EXPECT_NEAR(distribution_ggx(1.0f, 0.5f), 1.0f / (kPi * 0.0625f), 1e-3f);
  // Roughness 1: alpha = 1, D = 1/pi everywhere (uniform).
  EXPECT_NEAR(distribution_ggx(0.3f, 1.0f), 1.0f / kPi, 1e-6f);
}

TEST(Brdf, SchlickFresnelEndsAtF0AndOne) {
  EXPECT_NEAR(fresnel_schlick(glm::vec3(0.04f), 1.0f).x, 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_schlick(glm::vec3(0.04f), 0.0f).x, 1.0f, 1e-6f);
  EXPECT_NEAR(fresnel_schlick(glm::vec3(0.04f), 0.5f).x, 0.04f + 0.96f / 32.0f, 1e-6f);
}

TEST(Brdf, SmithGeometryIsOneHeadOnAndFallsAtGrazing) {
  EXPECT_NEAR(geometry_smith(1.0f, 1.0f, 0.5f), 1.0f, 1e-6f);
  EXPECT_LT(geometry_smith(0.05f, 1.0f, 0.5f), 0.5f);
}

// Directional albedo: the integral over the hemisphere of f(l, v) (n.l) dl, by Monte Carlo.
// The diffuse part uses cosine-weighted directions (pdf = n.l / pi); the specular part
// importance-samples the GGX lobe (pdf = D (n.h) / (4 v.h)), without which a sharp lobe is
// hit so rarely that the estimate is noise.
glm::vec3 directional_albedo(const PbrSurface& s, glm::vec3 v) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const glm::vec3 n(0, 0, 1);
  const float roughness = std::clamp(s.roughness, 0.04f, 1.0f);
  const float a2 = std::pow(roughness, 4.0f);
  glm::vec3 diffuse(0.0f), specular(0.0f);
  const int kSamples = 200000;
  for (int i = 0; i < kSamples; ++i) {
    float r = std::sqrt(unit(rng)), phi = 2.0f * kPi * unit(rng);
    glm::vec3 l(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - r * r)));
    diffuse += cook_torrance_parts(s, n, v, l).diffuse * kPi;
    // GGX half-vector sample: cos^2(theta_h) = (1 - u) / (1 + (a2 - 1) u).
    float u = unit(rng), phi_h = 2.0f * kPi * unit(rng);
    float cos_h = std::sqrt((1.0f - u) / (1.0f + (a2 - 1.0f) * u));
    float sin_h = std::sqrt(std::max(0.0f, 1.0f - cos_h * cos_h));
    glm::vec3 h(sin_h * std::cos(phi_h), sin_h * std::sin(phi_h), cos_h);
    glm::vec3 l_spec = glm::reflect(-v, h);
    float v_dot_h = glm::dot(v, h);
    if (l_spec.z <= 0.0f || v_dot_h <= 0.0f) continue;
    float pdf = distribution_ggx(cos_h, roughness) * cos_h / (4.0f * v_dot_h);
    specular += cook_torrance_parts(s, n, v, l_spec).specular * (l_spec.z / pdf);
  }
  return (diffuse + specular) / float(kSamples);
}

TEST(Brdf, WhiteFurnaceNeverReflectsMoreThanArrives) {
  for (float metallic : {0.0f, 1.0f}) {
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
      for (float angle : {0.0f, 1.0f, 1.4f}) {
        glm::vec3 v(std::sin(angle), 0.0f, std::cos(angle));
        glm::vec3 albedo = directional_albedo({glm::vec3(1.0f), metallic, roughness}, v);
        EXPECT_LE(albedo.x, 1.0f + 0.02f)
            << "metallic " << metallic << " roughness " << roughness << " angle " << angle;
        EXPECT_GT(albedo.x, 0.3f);  // and it reflects something
      }
    }
  }
}

TEST(Brdf, LambertianPartMatchesAlbedoOverPi) {
  // A rough dielectric seen head-on, light head-on: diffuse = (1 - F0)^2 albedo / pi (Fresnel
  // on the way in and out).
  PbrSurface s{glm::vec3(0.5f), 0.0f, 1.0f};
  glm::vec3 f = cook_torrance(s, {0, 0, 1}, {0, 0, 1}, {0, 0, 1});
  float diffuse = 0.96f * 0.96f * 0.5f / kPi;
  EXPECT_GT(f.x, diffuse);  // plus a specular part
  EXPECT_LT(f.x, diffuse + 0.1f);
}

TEST(Brdf, PhongAndBlinnPeaks) {
  glm::vec3 n(0, 0, 1), l = glm::normalize(glm::vec3(1, 0, 1)),
                        v = glm::normalize(glm::vec3(-1, 0, 1));
  EXPECT_NEAR(phong_specular(n, v, l, 32.0f), 1.0f, 1e-5f);        // mirror direction
  EXPECT_NEAR(blinn_phong_specular(n, v, l, 32.0f), 1.0f, 1e-5f);  // h == n
  EXPECT_LT(phong_specular(n, n, l, 32.0f), 0.01f);
}

TEST(Lights, PointLightFallsOffWithTheSquareOfDistance) {
  LightData light = prepare_light(Light::point({0, 0, 0}, glm::vec3(1.0f), 4.0f));
  EXPECT_NEAR(incident(light, {0, 2, 0}).radiance.x, 1.0f, 1e-6f);
  EXPECT_NEAR(incident(light, {0, 4, 0}).radiance.x, 0.25f, 1e-6f);
  EXPECT_NEAR(incident(light, {0, 4, 0}).direction.y, -1.0f, 1e-6f);
  LightData ranged = prepare_light(Light::point({0, 0, 0}, glm::vec3(1.0f), 1.0f, 3.0f));
  EXPECT_EQ(incident(ranged, {0, 3.5f, 0}).radiance.x, 0.0f);
}

TEST(Lights, SpotConeIsFullInsideZeroOutside) {
  LightData spot = prepare_light(Light::spot({0, 0, 0}, {0, -1, 0}, 20.0f, 30.0f));
  EXPECT_NEAR(incident(spot, {0, -1, 0}).radiance.x, 1.0f, 1e-6f);
  glm::vec3 at40(std::sin(glm::radians(40.0f)), -std::cos(glm::radians(40.0f)), 0.0f);
  EXPECT_EQ(incident(spot, at40).radiance.x, 0.0f);
  glm::vec3 at25(std::sin(glm::radians(25.0f)), -std::cos(glm::radians(25.0f)), 0.0f);
  float partial = incident(spot, at25).radiance.x;
  EXPECT_GT(partial, 0.0f);
  EXPECT_LT(partial, 1.0f);
}

TEST(Lights, DirectionalLightPointsBackAlongItsTravel) {
  LightData sun = prepare_light(Light::directional({0, -2, 0}, glm::vec3(1.0f), 0.5f));
  EXPECT_EQ(sun.to_light, glm::vec3(0, 1, 0));
  EXPECT_EQ(incident(sun, {5, 5, 5}).radiance, glm::vec3(0.5f));
}

}  // namespace
}  // namespace facet::shading
