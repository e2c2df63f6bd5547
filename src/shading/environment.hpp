// The environment: what a reflection or the background sees in a world direction — an
// equirectangular or sphere-map image, or a procedural sky gradient when there is none.
#pragma once

#include <glm/glm.hpp>

#include "facet/light.hpp"

namespace facet::shading {

// Texture coordinates of a unit world direction in an equirectangular image: longitude along
// u (u = 0.5 looks down -Z), latitude along v (v = 1 is straight up).
glm::vec2 equirectangular_uv(glm::vec3 direction);
// ... and in a sphere map (a mirrored ball photographed from +Z).
glm::vec2 sphere_map_uv(glm::vec3 direction);

// Linear radiance arriving from `direction` (unit, world space). lod blurs image
// environments (rough reflections); the gradient is smooth already.
glm::vec3 environment_radiance(const Environment& environment, glm::vec3 direction,
                               float lod = 0.0f);

// A surface of the given reflectivity (0..1) mirroring the environment: its color mixed with the
// radiance from the mirror direction of `view` (unit, toward the eye) about unit `normal`.
glm::vec3 mix_reflection(const Environment& environment, float reflectivity, glm::vec3 color,
                         glm::vec3 view, glm::vec3 normal);

}  // namespace facet::shading
