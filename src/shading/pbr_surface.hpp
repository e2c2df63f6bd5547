// The physically based model's constant and surface, shared by its SIMD kernel (shade_batch.cpp,
// where the Cook-Torrance BRDF is) and the environment's light (environment_light.cpp).
#pragma once

#include <glm/glm.hpp>

namespace facet::shading {

inline constexpr float kPi = 3.14159265358979f;

struct PbrSurface {
  glm::vec3 albedo;  // base color, linear
  float metallic;
  float roughness;  // perceptual
};

}  // namespace facet::shading
