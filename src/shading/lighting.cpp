// Light preparation (see lighting.hpp).
#include "shading/lighting.hpp"

#include <algorithm>
#include <cmath>

namespace facet::shading {

LightData prepare_light(const Light& light) {
  LightData d;
  d.type = light.type;
  d.position = light.position;
  float length = glm::length(light.direction);
  glm::vec3 travel = length > 0.0f ? light.direction / length : glm::vec3(0.0f, -1.0f, 0.0f);
  d.to_light = -travel;
  d.spot_direction = travel;
  d.radiance = light.color * light.intensity;
  d.inv_range_squared = light.range > 0.0f ? 1.0f / (light.range * light.range) : 0.0f;
  float outer = std::clamp(light.outer_cone_degrees, 0.0f, 90.0f);
  float inner = std::clamp(light.inner_cone_degrees, 0.0f, outer);
  d.cos_inner = std::cos(glm::radians(inner));
  d.cos_outer = std::cos(glm::radians(outer));
  return d;
}

}  // namespace facet::shading
