// A planar reflection as the surfaces on its plane read it: the scene mirrored through the
// plane, rendered by the frame's reflection pass (pipeline/reflection/reflection_passes.cpp)
// before the color pass, and read through DrawUniforms::reflection by the Phong and PBR batch
// kernels (planar_reflection-inl.h) in place of the environment's radiance from the mirror
// direction.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

#include "facet/texture.hpp"

namespace facet::shading {

struct PlanarReflection {
  // The pass's image: linear float RGBA with its mip chain, read trilinear, clamped to the edges.
  const Texture* image = nullptr;
  Sampler sampler{Filter::trilinear, Wrap::clamp_to_edge, Wrap::clamp_to_edge};
  // World position -> (u w, v w, 0, w): divided by w, the texture coordinates where the
  // reflection of what lies behind that point of the plane is seen.
  glm::mat4 world_to_image{1.0f};
  // The blur of a surface of roughness alpha: the level of detail log2(1 + alpha * blur_texels).
  float blur_texels = 0.0f;
};

// The roughness (alpha) whose blur a Phong or Blinn-Phong highlight of this exponent matches:
// Walter et al.'s Beckmann equivalent, sqrt(2 / (n + 2)).
inline float phong_roughness(float shininess) {
  return std::sqrt(2.0f / (std::max(shininess, 0.0f) + 2.0f));
}

}  // namespace facet::shading
