// The environment: what a reflection or the background sees in a world direction — here, an
// equirectangular or sphere-map image (the procedural sky gradient is sky_gradient-inl.h).
#pragma once

#include <glm/glm.hpp>

#include "facet/light.hpp"

namespace facet::shading {

// Texture coordinates of a unit world direction in an equirectangular image: longitude along
// u (u = 0.5 looks down -Z), latitude along v (v = 1 is straight up).
glm::vec2 equirectangular_uv(glm::vec3 direction);
// ... and in a sphere map (a mirrored ball photographed from +Z).
glm::vec2 sphere_map_uv(glm::vec3 direction);

// Linear radiance arriving from `direction` (unit, world space) out of an image environment
// (environment.image set); lod blurs it (rough reflections). The procedural sky (no image) is
// computed on vectors of directions: sky_gradient-inl.h.
glm::vec3 image_radiance(const Environment& environment, glm::vec3 direction, float lod = 0.0f);

}  // namespace facet::shading
