// Environment lookups (see environment.hpp).
#include "shading/environment.hpp"

#include <algorithm>
#include <cmath>

#include "facet/texture.hpp"
#include "shading/pbr_surface.hpp"  // kPi

namespace facet::shading {

glm::vec2 equirectangular_uv(glm::vec3 d) {
  float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
  float v = 0.5f + std::asin(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
  return {u, v};
}

glm::vec2 sphere_map_uv(glm::vec3 d) {
  float m = 2.0f * std::sqrt(d.x * d.x + d.y * d.y + (d.z + 1.0f) * (d.z + 1.0f));
  if (m < 1e-6f) return {0.5f, 0.5f};
  return {d.x / m + 0.5f, d.y / m + 0.5f};
}

void image_radiance(SampleAtKernel sample_at, const Environment& env, const glm::vec3* directions,
                    const float* lod, int count, glm::vec3* radiance) {
  Sampler sampler;
  sampler.wrap_v = Wrap::clamp_to_edge;
  const bool sphere_map = env.projection == EnvironmentProjection::sphere_map;
  if (sphere_map) sampler.wrap_u = Wrap::clamp_to_edge;
  constexpr int kChunk = 64;
  float u[kChunk], v[kChunk], rgba[kChunk][4];
  for (int first = 0; first < count; first += kChunk) {
    const int n = std::min(kChunk, count - first);
    for (int i = 0; i < n; ++i) {
      const glm::vec3 d = directions[first + i];
      const glm::vec2 uv = sphere_map ? sphere_map_uv(d) : equirectangular_uv(d);
      u[i] = uv.x, v[i] = uv.y;
    }
    sample_at(*env.image, sampler, u, v, lod + first, n, rgba);
    for (int i = 0; i < n; ++i) {
      radiance[first + i] = glm::vec3(rgba[i][0], rgba[i][1], rgba[i][2]) * env.intensity;
    }
  }
}

}  // namespace facet::shading
