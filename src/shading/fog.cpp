// Distance fog (see fog.hpp).
#include "shading/fog.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace facet::shading {

glm::vec4 fogged(glm::vec4 color, float view_depth, const Fog& fog) {
  float keep = fog.mode == FogMode::linear
                   ? (fog.end - view_depth) / std::max(fog.end - fog.start, 1e-6f)
                   : std::exp(-fog.density * view_depth);
  keep = std::clamp(keep, 0.0f, 1.0f);
  return {glm::mix(fog.color, glm::vec3(color), keep), color.a};
}

}  // namespace facet::shading
