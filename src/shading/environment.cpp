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

glm::vec3 image_radiance(const Environment& env, glm::vec3 d, float lod) {
  Sampler sampler;
  sampler.wrap_v = Wrap::clamp_to_edge;
  glm::vec2 uv = env.projection == EnvironmentProjection::equirectangular ? equirectangular_uv(d)
                                                                          : sphere_map_uv(d);
  if (env.projection == EnvironmentProjection::sphere_map) sampler.wrap_u = Wrap::clamp_to_edge;
  return glm::vec3(env.image->sample(sampler, uv, lod)) * env.intensity;
}

}  // namespace facet::shading
