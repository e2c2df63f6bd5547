// The procedural sky's radiance (shading/sky_gradient-inl.h) for an array of directions at once,
// with SIMD (sky_batch.cpp, compiled for every target Highway supports): what
// project_environment (environment_light.cpp) integrates for a sky without an image.
#pragma once

#include <glm/vec3.hpp>

#include "core/simd_target.hpp"
#include "facet/light.hpp"

namespace facet::shading {

// radiance[i] = the sky's radiance along the unit direction whose upward (y) component is up[i],
// for i in [0, count), of an environment without an image.
using SkyBatchKernel = void (*)(const Environment& environment, const float* up, int count,
                                glm::vec3* radiance);
SkyBatchKernel sky_batch_kernel(SimdTarget target);

}  // namespace facet::shading
