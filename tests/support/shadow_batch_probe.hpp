// The SIMD shadow lookup of the batch kernels (shading/shadow_batch-inl.h's ShadowVisibility),
// compiled here for every SIMD target, so that shadow_batch_test compares its bits with the
// scalar shadow_visibility directly, point by point.
#pragma once

#include <glm/glm.hpp>

#include "core/simd_target.hpp"
#include "shading/shadow_map.hpp"

namespace facet::test {

// visibility[n]: ShadowVisibility(maps, points[n], normals[n]) on `target`, for n < count, a
// vector of points at a time.
void shadow_visibility_batch(SimdTarget target, const shading::ShadowMaps& maps,
                             const glm::vec3* points, const glm::vec3* normals, int count,
                             float* visibility);

}  // namespace facet::test
