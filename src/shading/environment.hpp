// The environment: what a reflection or the background sees in a world direction — here, an
// equirectangular or sphere-map image (the procedural sky gradient is sky_gradient-inl.h).
#pragma once

#include <glm/glm.hpp>

#include "core/texture_sampler.hpp"
#include "facet/light.hpp"

namespace facet::shading {

// Texture coordinates of a unit world direction in an equirectangular image: longitude along
// u (u = 0.5 looks down -Z), latitude along v (v = 1 is straight up).
glm::vec2 equirectangular_uv(glm::vec3 direction);
// ... and in a sphere map (a mirrored ball photographed from +Z).
glm::vec2 sphere_map_uv(glm::vec3 direction);

// Linear radiance arriving out of an image environment (environment.image set) along `count`
// unit world directions: radiance[i] along directions[i], blurred to mip level lod[i] (rough
// reflections), sampled with `sample_at` (the frame's texture lookups). The procedural sky (no
// image) is computed on vectors of directions: sky_gradient-inl.h.
void image_radiance(SampleAtKernel sample_at, const Environment& environment,
                    const glm::vec3* directions, const float* lod, int count, glm::vec3* radiance);

}  // namespace facet::shading
