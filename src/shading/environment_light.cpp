// Image-based lighting (see environment_light.hpp).
#include "shading/environment_light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "facet/texture.hpp"
#include "shading/environment.hpp"
#include "shading/pbr_surface.hpp"  // kPi
#include "shading/sky_batch.hpp"

namespace facet::shading {
namespace {

constexpr int kColumns = 64, kRows = 32;

// The nine basis functions at unit direction d.
std::array<float, 9> basis(glm::vec3 d) {
  return {0.282095f,
          0.488603f * d.y,
          0.488603f * d.z,
          0.488603f * d.x,
          1.092548f * d.x * d.y,
          1.092548f * d.y * d.z,
          0.315392f * (3.0f * d.z * d.z - 1.0f),
          1.092548f * d.x * d.z,
          0.546274f * (d.x * d.x - d.y * d.y)};
}

// The mip level whose texels are about as large as a grid cell, so each lookup averages its
// cell rather than sampling one texel of it.
float grid_lod(const Environment& environment) {
  if (!environment.image) return 0.0f;
  const float texels_per_cell = static_cast<float>(environment.image->width()) / kColumns;
  return std::max(0.0f, std::log2(std::max(texels_per_cell, 1.0f)));
}

}  // namespace

IrradianceHarmonics project_environment(const Environment& environment) {
  IrradianceHarmonics sums{};
  const float lod = grid_lod(environment);
  const float cell = (2.0f * kPi / kColumns) * (kPi / kRows);
  const SimdTarget target = chosen_simd_target();
  const SkyBatchKernel sky = environment.image ? nullptr : sky_batch_kernel(target);
  const SampleAtKernel sample_at = sample_at_kernel(target);
  std::array<float, kColumns> lods;
  lods.fill(lod);
  for (int row = 0; row < kRows; ++row) {
    const float polar = (static_cast<float>(row) + 0.5f) * kPi / kRows;  // from straight up
    const float solid_angle = cell * std::sin(polar);
    std::array<glm::vec3, kColumns> directions, radiance;
    std::array<float, kColumns> up;
    for (int column = 0; column < kColumns; ++column) {
      const float azimuth = (static_cast<float>(column) + 0.5f) * 2.0f * kPi / kColumns;
      directions[column] = {std::sin(polar) * std::cos(azimuth), std::cos(polar),
                            std::sin(polar) * std::sin(azimuth)};
      up[column] = directions[column].y;
    }
    if (sky != nullptr) {
      sky(environment, up.data(), kColumns, radiance.data());
    } else {
      image_radiance(sample_at, environment, directions.data(), lods.data(), kColumns,
                     radiance.data());
    }
    for (int column = 0; column < kColumns; ++column) {
      const glm::vec3 weighted = radiance[column] * solid_angle;
      const std::array<float, 9> y = basis(directions[column]);
      for (int k = 0; k < 9; ++k) sums[k] += weighted * y[k];
    }
  }
  return sums;
}

glm::vec3 irradiance(const IrradianceHarmonics& l, glm::vec3 n) {
  // Ramamoorthi and Hanrahan's equation 13: the harmonics convolved with the clamped cosine.
  constexpr float c1 = 0.429043f, c2 = 0.511664f, c3 = 0.743125f, c4 = 0.886227f, c5 = 0.247708f;
  const glm::vec3 e = c1 * l[8] * (n.x * n.x - n.y * n.y) + c3 * l[6] * n.z * n.z + c4 * l[0] -
                      c5 * l[6] +
                      2.0f * c1 * (l[4] * n.x * n.y + l[7] * n.x * n.z + l[5] * n.y * n.z) +
                      2.0f * c2 * (l[3] * n.x + l[1] * n.y + l[2] * n.z);
  return glm::max(e, glm::vec3(0.0f));
}

SpecularIntegral specular_integral(float n_dot_v, float roughness) {
  const glm::vec4 c0{-1.0f, -0.0275f, -0.572f, 0.022f};
  const glm::vec4 c1{1.0f, 0.0425f, 1.04f, -0.04f};
  const glm::vec4 r = roughness * c0 + c1;
  const float a004 = std::min(r.x * r.x, std::exp2(-9.28f * std::max(n_dot_v, 0.0f))) * r.x + r.y;
  return {-1.04f * a004 + r.z, 1.04f * a004 + r.w};
}

glm::vec3 environment_light(const IrradianceHarmonics& light, const PbrSurface& surface,
                            glm::vec3 f0, glm::vec3 n, glm::vec3 v, glm::vec3 mirror,
                            glm::vec3 seen) {
  const glm::vec3 diffuse =
      surface.albedo * (1.0f - surface.metallic) * irradiance(light, n) * (1.0f / kPi);
  const float spread = surface.roughness * surface.roughness;
  const glm::vec3 blurred = glm::mix(seen, irradiance(light, mirror) * (1.0f / kPi), spread);
  const SpecularIntegral brdf = specular_integral(glm::dot(n, v), surface.roughness);
  return diffuse + blurred * (f0 * brdf.scale + brdf.bias);
}

}  // namespace facet::shading
