// Stage: setup, for draws whose model lights the back faces of two-sided materials
// (DrawPipeline::lights_back_faces): which triangles get their normal reversed.
#pragma once

#include <glm/glm.hpp>

namespace facet::pipeline {

// Whether a triangle's normal is reversed: when its vertex normals point to the side of it not
// seen. That is its back, as the winding says, for the triangles whose normals agree with their
// winding; a triangle whose normals point against its winding (a mesh wound inconsistently) is
// trusted to its normals. One decision for the whole triangle: a pixel's own normal, at a smooth
// silhouette, may turn away from the viewer on a face that is seen.
//
// over_w[i] points at vertex i's varyings times its 1 / w, inv_w[i] (what setup reads); the
// world position and the normal are the three varyings from `position` and `normal`. The
// reference rasterizer decides with the same function, so the same bits.
inline bool reverses_normal(const float* const over_w[3], const float inv_w[3], int position,
                            int normal, bool front_facing) {
  glm::vec3 p[3], normals(0.0f);
  for (int i = 0; i < 3; ++i) {
    const float w = 1.0f / inv_w[i];
    const float* at = over_w[i] + position;
    const float* n = over_w[i] + normal;
    p[i] = glm::vec3(at[0] * w, at[1] * w, at[2] * w);
    normals += glm::vec3(n[0] * w, n[1] * w, n[2] * w);
  }
  const bool normals_front = glm::dot(normals, glm::cross(p[1] - p[0], p[2] - p[0])) >= 0.0f;
  return normals_front != front_facing;
}

}  // namespace facet::pipeline
