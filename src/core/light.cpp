// Light constructors and the default three-point setup.
#include "facet/light.hpp"

#include <glm/glm.hpp>

namespace facet {

Light Light::directional(glm::vec3 direction, glm::vec3 color, float intensity) {
  Light l;
  l.type = LightType::directional;
  l.direction = direction;
  l.color = color;
  l.intensity = intensity;
  return l;
}

Light Light::point(glm::vec3 position, glm::vec3 color, float intensity, float range) {
  Light l;
  l.type = LightType::point;
  l.position = position;
  l.color = color;
  l.intensity = intensity;
  l.range = range;
  return l;
}

Light Light::spot(glm::vec3 position, glm::vec3 direction, float inner_degrees, float outer_degrees,
                  glm::vec3 color, float intensity, float range) {
  Light l = point(position, color, intensity, range);
  l.type = LightType::spot;
  l.direction = direction;
  l.inner_cone_degrees = inner_degrees;
  l.outer_cone_degrees = outer_degrees;
  return l;
}

std::vector<Light> three_point_lights(glm::vec3 forward, glm::vec3 right) {
  forward = glm::normalize(forward);
  right = glm::normalize(right);
  glm::vec3 up = glm::normalize(glm::cross(right, forward));
  // Directions the light travels: the key comes from above-left-front of the viewer, the fill
  // from the right at eye height, the rim from behind the model toward the viewer.
  Light key = Light::directional(forward + right * 0.6f - up * 0.9f, {1.0f, 0.95f, 0.88f}, 1.0f);
  Light fill = Light::directional(forward * 0.6f - right - up * 0.2f, {0.75f, 0.82f, 1.0f}, 0.35f);
  Light rim = Light::directional(-forward - up * 0.5f, {1.0f, 1.0f, 1.0f}, 0.45f);
  // Only the key light casts shadows: shadows from the fill and the rim would cross the key's.
  fill.casts_shadows = rim.casts_shadows = false;
  return {key, fill, rim};
}

}  // namespace facet
