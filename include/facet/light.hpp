// Lighting: one directional light (the sun) plus an ambient term, the classic teaching setup.
#pragma once

#include <glm/vec3.hpp>

namespace facet {

struct DirectionalLight {
  glm::vec3 direction{-0.4f, -1.0f, -0.6f};  // direction the light travels (world space)
  glm::vec3 color{1.0f, 1.0f, 1.0f};         // linear RGB
  float intensity = 1.0f;
};

struct Lighting {
  DirectionalLight sun;
  glm::vec3 ambient{0.15f, 0.15f, 0.18f};  // linear RGB added to every lit surface
};

}  // namespace facet
