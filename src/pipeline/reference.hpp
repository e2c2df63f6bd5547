// The reference rasterizer: short, scalar and obviously correct, used only by tests to check
// the tiled fast path. Same rules (pixel centres, 8-bit sub-pixel snapping, top-left fill
// rule, clipping), none of the machinery: no tiles, no bins, no incremental stepping.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "facet/material.hpp"

namespace facet::pipeline {

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<int> coverage;  // how many triangles covered each pixel centre
  std::vector<float> depth;   // nearest window depth (1 = far, the clear value)
};

// Rasterizes a triangle soup (every 3 positions, object space) transformed by
// model_view_projection.
ReferenceImage reference_rasterize(const std::vector<glm::vec3>& positions,
                                   const glm::mat4& model_view_projection, CullMode cull, int width,
                                   int height);

}  // namespace facet::pipeline
