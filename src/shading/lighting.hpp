// Light evaluation shared by the lit shading models: how much light of each kind reaches a
// surface point, with distance attenuation and spot cones.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "shading/shadow_map.hpp"
#include "shading/uniforms.hpp"

namespace facet::shading {

LightData prepare_light(const Light& light);

// Direction toward the light (unit) and the radiance arriving at world position p.
struct IncidentLight {
  glm::vec3 direction;
  glm::vec3 radiance;
};

inline IncidentLight incident(const LightData& light, glm::vec3 p) {
  if (light.type == LightType::directional) return {light.to_light, light.radiance};
  glm::vec3 to_light = light.position - p;
  float distance_squared = std::max(glm::dot(to_light, to_light), 1e-8f);
  glm::vec3 direction = to_light * (1.0f / std::sqrt(distance_squared));
  // Inverse-square falloff, windowed to reach zero at the range (glTF KHR_lights_punctual).
  float attenuation = 1.0f / distance_squared;
  if (light.inv_range_squared > 0.0f) {
    float ratio = distance_squared * light.inv_range_squared;
    float window = std::clamp(1.0f - ratio * ratio, 0.0f, 1.0f);
    attenuation *= window * window;
  }
  if (light.type == LightType::spot) {
    float cos_angle = glm::dot(-direction, light.spot_direction);
    float t = (cos_angle - light.cos_outer) / std::max(light.cos_inner - light.cos_outer, 1e-4f);
    t = std::clamp(t, 0.0f, 1.0f);
    attenuation *= t * t;
  }
  return {direction, light.radiance * attenuation};
}

// The radiance of `in` at world position p of unit normal n (facing the light), after the
// light's shadow (none: unchanged, the same bits).
inline glm::vec3 received_radiance(const LightData& light, const IncidentLight& in, glm::vec3 p,
                                   glm::vec3 n) {
  if (!light.shadow) return in.radiance;
  return in.radiance * shadow_visibility(*light.shadow, p, n);
}

}  // namespace facet::shading
